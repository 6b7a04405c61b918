// The properties every shape function must have, checked for every entry of the one list
// (ShapeFunctions, mpm/shape/shape_functions.hpp) by one typed test suite, so that a function added to the
// list is tested without a line here:
// - partition of unity, gradients summing to zero and linear reproduction (sum phi_I x_I = x,
//   sum x_I (x) grad phi_I = I; review §3.1), quadratic reproduction where the function declares it
//   (Lagrange), and weights >= the function's declared minimum (0, or the -1/8 lobe of Lagrange), at
//   random points of an anisotropic grid, a share of them in the cells next to the faces (where the
//   B-splines use their boundary-modified functions, review eqs 3.18-3.21), on nodes and half-cells, on
//   both corners of the box, on every grid size from the function's minimum up, in every dimension it
//   exists in. GIMP domains stay inside the box (no ghost nodes); CPDI domains are random distorted
//   elements within the stencil's reach, whose centroid the weights reproduce (eq. 3.39);
// - the slab thickness of the race-free scatter: two slabs of the same colour never reach a common node;
// - the factored stencil TLMPM caches equals the full stencil (tensor-product functions);
// - derivatives against central differences of the weights (tensor-product functions).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <set>
#include <type_traits>
#include <vector>

#include "cpdi_random_domain.hpp"
#include "mpm/shape/factored_stencil.hpp"
#include "mpm/shape/shape_functions.hpp"
#include "mpm/shape/stencil.hpp"

namespace mpm {
namespace {

template <class List>
struct GTestTypes;
template <class... Shapes>
struct GTestTypes<ShapeList<Shapes...>> {
  using type = ::testing::Types<Shapes...>;
};

/// The listed functions whose weights are products of 1D functions (all but CPDI): the factored-stencil
/// and derivative checks below apply to these only, so they run over this sub-list instead of skipping.
template <class Done, class Rest>
struct TensorProductOf;
template <class... Done>
struct TensorProductOf<ShapeList<Done...>, ShapeList<>> {
  using type = ShapeList<Done...>;
};
template <class... Done, class First, class... Rest>
struct TensorProductOf<ShapeList<Done...>, ShapeList<First, Rest...>> {
  using type = typename TensorProductOf<
      std::conditional_t<TensorProductShape<First>, ShapeList<Done..., First>, ShapeList<Done...>>,
      ShapeList<Rest...>>::type;
};
using TensorProductShapes = TensorProductOf<ShapeList<>, ShapeFunctions>::type;

template <class Shape>
class ShapeFunctionProperties : public ::testing::Test {};
TYPED_TEST_SUITE(ShapeFunctionProperties, GTestTypes<ShapeFunctions>::type);

template <class Shape>
class TensorProductShapeProperties : public ::testing::Test {};
TYPED_TEST_SUITE(TensorProductShapeProperties, GTestTypes<TensorProductShapes>::type);

/// `cells` raised to the function's minimum (and to 2) and to a multiple of its cell multiple.
template <class Shape>
int admissible_cells(int cells) {
  cells = std::max({cells, Shape::min_cells, 2});
  const int m = shape_cell_multiple<Shape>;
  return (cells + m - 1) / m * m;
}

/// The grid sizes a property is checked on in `Dim` dimensions: the smallest admissible grid and a few
/// larger ones (1D: minimum, 3, 7, 8 cells; 2D: 5, 6; 3D: minimum, 4, 5), raised to admissible counts.
template <int Dim, class Shape>
std::vector<int> grid_sizes() {
  const std::vector<int> wanted =
      Dim == 1 ? std::vector<int>{0, 3, 7, 8} : (Dim == 2 ? std::vector<int>{5, 6} : std::vector<int>{0, 4, 5});
  std::set<int> sizes;
  for (const int c : wanted) sizes.insert(admissible_cells<Shape>(c));
  return {sizes.begin(), sizes.end()};
}

/// Axis d gets cells + m d cells (m the cell multiple), spacings 0.1 + 0.05 d, origin -0.3 (d + 1).
template <int Dim, class Shape>
GridGeometry<Dim> property_grid(int cells) {
  Vec<Dim> origin, h;
  std::array<int, Dim> n{};
  for (int d = 0; d < Dim; ++d) {
    origin[d] = -0.3 * (d + 1);
    h[d] = 0.1 + 0.05 * d;
    n[d] = cells + shape_cell_multiple<Shape> * d;
  }
  return GridGeometry<Dim>(origin, h, n);
}

/// What Stencil<Dim, Shape>::compute takes besides the position: domain half-lengths (none, or GIMP's)
/// or the corners of the particle element (CPDI).
template <int Dim, class Shape>
using DomainOf = std::conditional_t<shape_corner_domain<Shape>, CornerSet<Dim>, Vec<Dim>>;

/// One particle of the property checks and the point its weights must reproduce.
template <int Dim, class Shape>
struct Sample {
  VecU<Dim> x;
  DomainOf<Dim, Shape> domain;
  Vec<Dim> reproduced;  ///< sum_I phi_I x_I: the position, or the domain centroid for CPDI (eq. 3.39)
};

/// Sample `trial` of the sequence: uniform in the box, every fifth in the first cell, the last cell, the
/// first two cells, on nodes and half-cells (faces included); trial 0 on the lower corner of the box and
/// trial 5 on the upper one. GIMP: a random half-length of 0.05 to 1 cell per axis, the position moved
/// so that the domain lies inside the box. CPDI: a random distorted element of half a cell around the
/// position; nullopt when a corner lies outside the box or beyond the stencil's reach (the clamped case,
/// test_cpdi.cpp).
template <int Dim, class Shape>
std::optional<Sample<Dim, Shape>> sample(const GridGeometry<Dim>& g, int trial, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(0, 1);
  Sample<Dim, Shape> s;
  for (int d = 0; d < Dim; ++d) {
    const int n = g.cells(d);
    Real xi = u(rng) * n;
    if (trial % 5 == 1) xi = u(rng);                  // first cell
    if (trial % 5 == 2) xi = n - u(rng);              // last cell
    if (trial % 5 == 3) xi = 2 * u(rng);              // first two cells
    if (trial % 5 == 4) xi = std::floor(xi * 2) / 2;  // nodes and half-cells, faces included
    if (trial == 0) xi = 0;
    if (trial == 5) xi = n;
    s.x[d] = g.origin[d] + xi * g.h[d];
  }
  if constexpr (shape_corner_domain<Shape>) {
    s.domain = test::random_domain<Dim, Shape>(g, Vec<Dim>(s.x), 0.5, rng);
    if (!test::within_reach<Dim, Shape>(g, Vec<Dim>(s.x), s.domain)) return std::nullopt;
    Real wf[Shape::element::corners], wg[Shape::element::corners][Dim];
    Shape::element::weights(s.domain, wf, wg);
    s.reproduced = Vec<Dim>::Zero();
    for (int c = 0; c < Shape::element::corners; ++c) s.reproduced += wf[c] * Vec<Dim>(s.domain[c]);
  } else {
    s.domain = Vec<Dim>::Zero();
    if constexpr (shape_uses_domain<Shape>)
      for (int d = 0; d < Dim; ++d) {
        const Real a = 0.05 + 0.95 * u(rng);  // cells
        s.domain[d] = a * g.h[d];
        s.x[d] = std::clamp<Real>(s.x[d], g.origin[d] + s.domain[d], g.origin[d] + (g.cells(d) - a) * g.h[d]);
      }
    s.reproduced = Vec<Dim>(s.x);
  }
  return s;
}

template <int Dim, class Shape>
void check_properties(int cells) {
  SCOPED_TRACE(testing::Message() << Shape::name << ", " << Dim << "D, " << cells << " cells");
  const GridGeometry<Dim> g = property_grid<Dim, Shape>(cells);
  std::mt19937 rng(7);
  Stencil<Dim, Shape> st;
  Real min_w = 1;
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto s = sample<Dim, Shape>(g, trial, rng);
    if (!s) continue;
    ++accepted;
    st.compute(s->x, g, s->domain);
    Real sum_w = 0;
    Vec<Dim> sum_grad = Vec<Dim>::Zero(), reproduced = Vec<Dim>::Zero(), reproduced2 = Vec<Dim>::Zero();
    Mat<Dim> grad_x = Mat<Dim>::Zero(), grad_x2 = Mat<Dim>::Zero();
    for (int a = 0; a < st.count; ++a) {
      ASSERT_GE(st.w[a], shape_min_weight<Shape> - 1e-15) << "weights must not go below the declared minimum";
      ASSERT_GE(st.node[a], 0);
      ASSERT_LT(st.node[a], g.node_count());
      const Vec<Dim> xI = g.node_position(g.node_indices(st.node[a]));
      Vec<Dim> grad;
      for (int d = 0; d < Dim; ++d) grad[d] = st.grad[a][d];
      min_w = std::min(min_w, st.w[a]);
      sum_w += st.w[a];
      sum_grad += grad;
      reproduced += st.w[a] * xI;
      grad_x += xI * grad.transpose();
      reproduced2 += st.w[a] * xI.cwiseProduct(xI);
      grad_x2 += xI.cwiseProduct(xI) * grad.transpose();
    }
    ASSERT_NEAR(sum_w, 1, 1e-13);
    ASSERT_LT(sum_grad.norm(), 1e-11);
    ASSERT_LT((reproduced - s->reproduced).norm(), 1e-12);
    ASSERT_LT((grad_x - Mat<Dim>::Identity()).norm(), 1e-11);
    if constexpr (shape_reproduced_degree<Shape> >= 2) {
      // Quadratic reproduction: sum phi_I x_I^2 = x^2 and sum x_I^2 grad phi_I = 2 x (per axis).
      const Vec<Dim> xp = s->reproduced;
      ASSERT_LT((reproduced2 - xp.cwiseProduct(xp)).norm(), 1e-12);
      ASSERT_LT((grad_x2 - Mat<Dim>((2 * xp).asDiagonal())).norm(), 1e-10);
    }
  }
  EXPECT_GE(accepted, 1000) << "too few samples within the stencil's reach";
  if constexpr (shape_min_weight<Shape> < 0) {
    EXPECT_LT(min_w, 0) << "the function declares negative lobes; the sample should have found one";
  }
}

template <int Dim, class Shape>
void check_properties_in() {
  if constexpr (shape_exists_in<Shape, Dim>)
    for (const int cells : grid_sizes<Dim, Shape>()) check_properties<Dim, Shape>(cells);
}

TYPED_TEST(ShapeFunctionProperties, PartitionOfUnityAndReproduction) {
  check_properties_in<1, TypeParam>();
  check_properties_in<2, TypeParam>();
  check_properties_in<3, TypeParam>();
}

/// The only dimension of a CPDI element, else 1: where the slabs are checked (slabs are cut along x).
template <class Shape>
constexpr int slab_dimension = shape_dimension<Shape> == 0 ? 1 : shape_dimension<Shape>;

/// The scatter writes every node of a particle's stencil (zero weights included). Slabs of
/// `Shape::slab_cells` cells along x, binned as bin_by_tile does; two slabs of the same colour (s and
/// s + 2) must not reach a common node. GIMP with the longest domain (one cell each side; the nodes
/// reached do not depend on it), CPDI with small random elements.
template <class Shape>
void check_slab_thickness(int cells) {
  constexpr int Dim = slab_dimension<Shape>;
  std::array<int, Dim> n;
  n.fill(admissible_cells<Shape>(Shape::min_cells + 2));
  n[0] = cells;
  const GridGeometry<Dim> g(Vec<Dim>::Zero(), Vec<Dim>::Ones(), n);
  const int slabs = (cells + Shape::slab_cells - 1) / Shape::slab_cells;
  std::vector<int> lo(slabs, cells + 1), hi(slabs, -1);
  std::mt19937 rng(9);
  Stencil<Dim, Shape> st;
  auto visit = [&](Real xi) {
    Vec<Dim> x = (g.upper() - g.origin) / 2;
    x[0] = xi;
    if constexpr (shape_corner_domain<Shape>)
      st.compute(VecU<Dim>(x), g, test::random_domain<Dim, Shape>(g, x, 2e-3, rng));
    else
      st.compute(VecU<Dim>(x), g, Vec<Dim>::Ones());
    const int slab = std::clamp(static_cast<int>(xi), 0, cells - 1) / Shape::slab_cells;
    for (int a = 0; a < st.count; ++a) {
      const int i = g.node_indices(st.node[a])[0];
      lo[slab] = std::min(lo[slab], i);
      hi[slab] = std::max(hi[slab], i);
    }
  };
  std::uniform_real_distribution<Real> u(0, cells);
  for (int i = 0; i < 4000; ++i) visit(u(rng));
  for (int i = 0; i <= 8 * cells; ++i) visit(i / Real(8));  // cell faces, centres, quarters and eighths exactly
  // The slab's declared reach (the halo of a distributed run, tile_halo.hpp) holds every node it reached.
  for (int s = 0; s < slabs; ++s) {
    if (hi[s] < 0) continue;
    EXPECT_GE(lo[s], s * Shape::slab_cells - Shape::slab_reach_below)
        << Shape::name << ", " << cells << " cells, slab " << s;
    EXPECT_LE(hi[s], (s + 1) * Shape::slab_cells - 1 + Shape::slab_reach_above)
        << Shape::name << ", " << cells << " cells, slab " << s;
  }
  static_assert(Shape::slab_reach_below + Shape::slab_reach_above <= Shape::slab_cells);
  for (int s = 0; s + 2 < slabs; ++s)
    EXPECT_LT(hi[s], lo[s + 2]) << Shape::name << ", " << cells << " cells: slabs " << s << " and " << s + 2
                                << " share a node";
}

TYPED_TEST(ShapeFunctionProperties, SlabThickness) {
  std::set<int> sizes;
  for (const int cells : {6, 8, 9, 10, 12, 13, 23, 25, 30, 31, 40}) sizes.insert(admissible_cells<TypeParam>(cells));
  for (const int cells : sizes) check_slab_thickness<TypeParam>(cells);
}

// The factored stencil TLMPM caches (factored_stencil.hpp) visits the same nodes, in the same order, with
// the same weights and gradients as the full stencil, at random points including the boundary cells.
template <int Dim, class Shape>
void check_factored_matches_full(int cells) {
  std::array<int, Dim> n;
  n.fill(cells);
  const GridGeometry<Dim> g(Vec<Dim>::Constant(-0.3), Vec<Dim>::Constant(0.25), n);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(0, 1);
  const Vec<Dim> half = Vec<Dim>::Constant(shape_uses_domain<Shape> ? 0.5 * 0.25 : 0);  // GIMP: half a cell
  for (int trial = 0; trial < 200; ++trial) {
    VecU<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = g.origin[d] + u(rng) * g.h[d] * cells;
    Stencil<Dim, Shape> full;
    FactoredStencil<Dim, Shape> factored;
    full.compute(x, g, half);
    factored.compute(x, g, half);
    int a = 0;
    factored.for_each(g, [&](Index node, Real w, const Vec<Dim>& grad) {
      ASSERT_LT(a, full.count);
      EXPECT_EQ(node, full.node[a]);
      EXPECT_NEAR(w, full.w[a], 1e-15);
      for (int d = 0; d < Dim; ++d) EXPECT_NEAR(grad[d], full.grad[a][d], 1e-13);
      ++a;
    });
    EXPECT_EQ(a, full.count);
  }
}

// CPDI weights are not products of 1D functions (TLMPM caches their full stencil): not in this list.
TYPED_TEST(TensorProductShapeProperties, FactoredStencilMatchesFull) {
  check_factored_matches_full<1, TypeParam>(admissible_cells<TypeParam>(6));
  check_factored_matches_full<2, TypeParam>(admissible_cells<TypeParam>(5));
  check_factored_matches_full<3, TypeParam>(admissible_cells<TypeParam>(4));
}

/// Weight and derivative of node `node` (0 outside the particle's stencil) on a 1D grid of unit cells,
/// with domain half-length `a` cells (GIMP; ignored by the others).
template <class Shape>
void weight_of(Real xi, int cells, Real a, int node, Real& w, Real& dw) {
  const GridGeometry<1> g(Vec<1>::Zero(), Vec<1>::Ones(), {cells});
  Stencil<1, Shape> st;
  st.compute(VecU<1>(xi), g, Vec<1>(a));
  w = dw = 0;
  for (int k = 0; k < st.count; ++k)
    if (st.node[k] == node) {
      w = st.w[k];
      dw = st.grad[k][0];
    }
}

/// Derivatives against central differences (step 1e-6) at 1000 random points at least 1e-4 from any
/// knot: the knots of every listed function lie on multiples of half a cell, shifted by the domain
/// half-length a for GIMP (r = +-a, 1 +- a).
template <class Shape>
void check_derivatives(int cells, Real a) {
  SCOPED_TRACE(testing::Message() << Shape::name << ", " << cells << " cells, half-length " << a);
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(a, cells - a);
  const Real step = 1e-6;
  auto near_knot = [](Real s) { return std::abs(s * 2 - std::round(s * 2)) < 2e-4; };
  int checked = 0;
  while (checked < 1000) {
    const Real xi = u(rng);
    if (near_knot(xi) || near_knot(xi + a) || near_knot(xi - a) || xi < 1e-4 || xi > cells - 1e-4) continue;
    ++checked;
    for (int node = 0; node <= cells; ++node) {
      Real w, dw, wp, dp, wm, dm;
      weight_of<Shape>(xi, cells, a, node, w, dw);
      weight_of<Shape>(xi + step, cells, a, node, wp, dp);
      weight_of<Shape>(xi - step, cells, a, node, wm, dm);
      ASSERT_NEAR(dw, (wp - wm) / (2 * step), 1e-8) << "xi = " << xi << ", node " << node;
    }
  }
}

// CPDI gradients are domain averages, not derivatives of the weights in x_p: not in this list.
TYPED_TEST(TensorProductShapeProperties, DerivativesMatchFiniteDifferences) {
  for (const int cells : {admissible_cells<TypeParam>(0), admissible_cells<TypeParam>(8)})
    for (const Real a : shape_uses_domain<TypeParam> ? std::vector<Real>{0.3, 0.5, 0.85} : std::vector<Real>{0})
      check_derivatives<TypeParam>(cells, a);
}

}  // namespace
}  // namespace mpm
