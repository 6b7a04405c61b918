// CPDI (review §3.6): the closed-form corner weights of every element against Gauss integration of
// M_c and grad M_c over the current (distorted) element (eqs 3.30-3.31); sum w^f = 1 and sum w^g = 0
// (eq. 3.33); the assembled stencil against the defining integral (1/V) int sum_c M_c N_I(x_c) dV,
// evaluated node by node with its own hat function; partition of unity, zero gradient sum and exact
// gradients of linear fields for distorted domains anywhere in the grid; equality with uGIMP for an
// axis-aligned box inside one cell; the Kuhn split of sub-cells into tetrahedra.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "cpdi_random_domain.hpp"
#include "mpm/geometry/cpdi_domains.hpp"
#include "mpm/shape/cpdi.hpp"
#include "mpm/shape/gimp.hpp"

namespace mpm {
namespace {

using Vec2 = Vec<2>;

// Reference shape functions of the particle elements and a Gauss rule exact for M_c det J (degree 2).
struct QuadRule {
  static constexpr int corners = 4;
  static std::vector<std::pair<std::array<Real, 3>, Real>> points() {  // (xi, eta), weight
    const Real g = 1 / std::sqrt(Real(3));
    return {{{-g, -g, 0}, 1}, {{g, -g, 0}, 1}, {{g, g, 0}, 1}, {{-g, g, 0}, 1}};
  }
  static void shape(const std::array<Real, 3>& s, Real* M, Real (*dM)[3]) {
    const Real xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};  // counter-clockwise
    for (int c = 0; c < 4; ++c) {
      M[c] = (1 + xi[c] * s[0]) * (1 + eta[c] * s[1]) / 4;
      dM[c][0] = xi[c] * (1 + eta[c] * s[1]) / 4;
      dM[c][1] = eta[c] * (1 + xi[c] * s[0]) / 4;
    }
  }
};
struct TriangleRule {
  static constexpr int corners = 3;
  static std::vector<std::pair<std::array<Real, 3>, Real>> points() {  // degree 2, reference area 1/2
    return {{{1. / 6, 1. / 6, 0}, 1. / 6}, {{2. / 3, 1. / 6, 0}, 1. / 6}, {{1. / 6, 2. / 3, 0}, 1. / 6}};
  }
  static void shape(const std::array<Real, 3>& s, Real* M, Real (*dM)[3]) {
    M[0] = 1 - s[0] - s[1], M[1] = s[0], M[2] = s[1];
    dM[0][0] = -1, dM[0][1] = -1, dM[1][0] = 1, dM[1][1] = 0, dM[2][0] = 0, dM[2][1] = 1;
  }
};
struct TetRule {
  static constexpr int corners = 4;
  static std::vector<std::pair<std::array<Real, 3>, Real>> points() {  // degree 2, reference volume 1/6
    const Real a = 0.5854101966249685, b = 0.1381966011250105;
    return {{{b, b, b}, 1. / 24}, {{a, b, b}, 1. / 24}, {{b, a, b}, 1. / 24}, {{b, b, a}, 1. / 24}};
  }
  static void shape(const std::array<Real, 3>& s, Real* M, Real (*dM)[3]) {
    M[0] = 1 - s[0] - s[1] - s[2], M[1] = s[0], M[2] = s[1], M[3] = s[2];
    for (int c = 0; c < 4; ++c)
      for (int d = 0; d < 3; ++d) dM[c][d] = c == 0 ? -1 : (c - 1 == d ? 1 : 0);
  }
};

/// w^f_c = (1/V) int M_c dV and w^g_c = (1/V) int grad M_c dV by Gauss integration on the element.
template <int Dim, class Rule>
void gauss_weights(const CornerSet<Dim>& x, Real* wf, Real (*wg)[Dim]) {
  Real V = 0;
  for (int c = 0; c < Rule::corners; ++c) {
    wf[c] = 0;
    for (int d = 0; d < Dim; ++d) wg[c][d] = 0;
  }
  for (const auto& [s, weight] : Rule::points()) {
    Real M[4], dM[4][3];
    Rule::shape(s, M, dM);
    Mat<Dim> J = Mat<Dim>::Zero();  // J(d, e) = dx_d / ds_e
    for (int c = 0; c < Rule::corners; ++c)
      for (int d = 0; d < Dim; ++d)
        for (int e = 0; e < Dim; ++e) J(d, e) += x[c][d] * dM[c][e];
    const Real dV = J.determinant() * weight;
    const Mat<Dim> inv = J.inverse();
    V += dV;
    for (int c = 0; c < Rule::corners; ++c) {
      wf[c] += M[c] * dV;
      for (int d = 0; d < Dim; ++d)
        for (int e = 0; e < Dim; ++e) wg[c][d] += inv(e, d) * dM[c][e] * dV;  // grad M = J^-T dM/ds
    }
  }
  for (int c = 0; c < Rule::corners; ++c) {
    wf[c] /= V;
    for (int d = 0; d < Dim; ++d) wg[c][d] /= V;
  }
}

template <int Dim, class Element, class Rule>
void expect_weights_match_gauss(const CornerSet<Dim>& x) {
  Real wf[4], wg[4][Dim], gf[4], gg[4][Dim];
  Element::weights(x, wf, wg);
  gauss_weights<Dim, Rule>(x, gf, gg);
  Real sum_f = 0;
  Vec<Dim> sum_g = Vec<Dim>::Zero();
  for (int c = 0; c < Element::corners; ++c) {
    EXPECT_NEAR(wf[c], gf[c], 1e-13) << "corner " << c;
    for (int d = 0; d < Dim; ++d) EXPECT_NEAR(wg[c][d], gg[c][d], 1e-11) << "corner " << c << " axis " << d;
    sum_f += wf[c];
    for (int d = 0; d < Dim; ++d) sum_g[d] += wg[c][d];
  }
  EXPECT_NEAR(sum_f, 1, 1e-14);  // eq. 3.33
  EXPECT_LT(sum_g.norm(), 1e-11);
}

TEST(Cpdi, QuadWeightsMatchGaussOnDistortedQuads) {
  // A strongly non-parallelogram quad (a, b != 0 in eq. 3.36), a parallelogram (R4) and a rectangle.
  expect_weights_match_gauss<2, CpdiQuad, QuadRule>({Vec2(0.1, 0.05), Vec2(0.9, 0.2), Vec2(1.2, 1.1), Vec2(-0.1, 0.7)});
  expect_weights_match_gauss<2, CpdiQuad, QuadRule>({Vec2(0, 0), Vec2(1, 0.3), Vec2(1.4, 1.3), Vec2(0.4, 1)});
  expect_weights_match_gauss<2, CpdiQuad, QuadRule>({Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)});
  Real wf[4], wg[4][2];
  CpdiQuad::weights({Vec2(0, 0), Vec2(1, 0.3), Vec2(1.4, 1.3), Vec2(0.4, 1)}, wf, wg);
  for (Real w : wf) EXPECT_NEAR(w, 0.25, 1e-15);  // parallelogram: the R4 weights of eq. 3.32
}

TEST(Cpdi, TriangleAndTetrahedronWeightsMatchGauss) {
  expect_weights_match_gauss<2, CpdiTriangle, TriangleRule>({Vec2(0.1, 0.2), Vec2(1.3, -0.1), Vec2(0.4, 0.9)});
  expect_weights_match_gauss<3, CpdiTetrahedron, TetRule>(
      {Vec3(0.1, 0.2, 0.0), Vec3(1.2, 0.1, 0.3), Vec3(0.3, 1.1, -0.2), Vec3(0.2, 0.4, 0.9)});
  EXPECT_NEAR(CpdiTetrahedron::volume({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}), 1. / 6, 1e-15);
}

TEST(Cpdi, SegmentWeights) {  // eq. 3.26
  Real wf[4], wg[4][1];
  CpdiSegment::weights({Vec<1>(0.2), Vec<1>(0.7)}, wf, wg);
  EXPECT_DOUBLE_EQ(wf[0], 0.5);
  EXPECT_DOUBLE_EQ(wf[1], 0.5);
  EXPECT_DOUBLE_EQ(wg[0][0], -2);
  EXPECT_DOUBLE_EQ(wg[1][0], 2);
}

// ---- the assembled stencil ----

template <int Dim>
GridGeometry<Dim> test_grid(int cells) {
  Vec<Dim> origin, h;
  std::array<int, Dim> n{};
  for (int d = 0; d < Dim; ++d) origin[d] = -0.3 * (d + 1), h[d] = 0.1 + 0.05 * d, n[d] = cells + d;
  return GridGeometry<Dim>(origin, h, n);
}

/// N_I(x) of the grid's hat functions, written independently of the stencil code.
template <int Dim>
Real hat(const GridGeometry<Dim>& g, Index node, const Vec<Dim>& x) {
  const Vec<Dim> xI = g.node_position(g.node_indices(node));
  Real N = 1;
  for (int d = 0; d < Dim; ++d) N *= std::max<Real>(0, 1 - std::abs(x[d] - xI[d]) * g.inv_h[d]);
  return N;
}

/// phi_I and grad phi_I of the stencil against (1/V) sum_c w_c N_I(x_c) over every node, partition of
/// unity, gradient sum, and the exact gradient of a linear field (sum_I x_I (x) grad phi_I = I).
template <int Dim, class Shape>
void check_stencil(int cells, Real size) {
  using Element = typename Shape::element;
  const GridGeometry<Dim> g = test_grid<Dim>(cells);
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(0, 1);
  Stencil<Dim, Shape> st;
  SCOPED_TRACE(testing::Message() << "domain size " << size << " cells");
  int accepted = 0;
  for (int trial = 0; trial < 2000 && accepted < 300; ++trial) {
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = g.origin[d] + g.h[d] * u(rng) * g.cells(d);
    const CornerSet<Dim> c = test::random_domain<Dim, Shape>(g, x, size, rng);
    // The stencil's reach (cpdi.hpp): every corner inside the grid box and in the particle's cell or a
    // neighbouring one. Other samples are the clamped case, tested separately.
    if (!test::within_reach<Dim, Shape>(g, x, c)) continue;
    ++accepted;
    st.compute(VecU<Dim>(x), g, c);
    Real wf[4], wg[4][Dim];
    Element::weights(c, wf, wg);
    std::vector<Real> phi(g.node_count(), 0);
    std::vector<Vec<Dim>> grad(g.node_count(), Vec<Dim>::Zero());
    for (int a = 0; a < st.count; ++a) {
      phi[st.node[a]] += st.w[a];
      for (int d = 0; d < Dim; ++d) grad[st.node[a]][d] += st.grad[a][d];
    }
    Real sum = 0;
    Vec<Dim> sum_grad = Vec<Dim>::Zero(), centroid = Vec<Dim>::Zero(), reproduced = Vec<Dim>::Zero();
    Mat<Dim> grad_x = Mat<Dim>::Zero();
    for (int k = 0; k < Element::corners; ++k) centroid += wf[k] * Vec<Dim>(c[k]);
    for (Index I = 0; I < g.node_count(); ++I) {
      Real expected = 0;
      Vec<Dim> expected_grad = Vec<Dim>::Zero();
      for (int k = 0; k < Element::corners; ++k) {
        const Real N = hat<Dim>(g, I, c[k]);
        expected += wf[k] * N;
        for (int d = 0; d < Dim; ++d) expected_grad[d] += wg[k][d] * N;
      }
      ASSERT_NEAR(phi[I], expected, 1e-13) << "node " << I;
      ASSERT_LT((grad[I] - expected_grad).norm(), 1e-10 * (1 + expected_grad.norm())) << "node " << I;
      const Vec<Dim> xI = g.node_position(g.node_indices(I));
      sum += phi[I];
      sum_grad += grad[I];
      reproduced += phi[I] * xI;
      grad_x += xI * grad[I].transpose();
    }
    ASSERT_NEAR(sum, 1, 1e-13);
    ASSERT_LT(sum_grad.norm(), 1e-10);
    ASSERT_LT((reproduced - centroid).norm(), 1e-12);  // sum phi_I x_I = domain centroid (eq. 3.39)
    ASSERT_LT((grad_x - Mat<Dim>::Identity()).norm(), 1e-10);
  }
  EXPECT_GE(accepted, 100) << "too few domains within the stencil's reach";
}

// Domains of half a cell (2 PPC) and of 1.4 cells (grown by the deformation); samples whose corners
// leave the block are skipped here.
TEST(Cpdi, L2StencilMatchesDefinition) {
  check_stencil<1, CpdiL2>(7, 0.5);
  check_stencil<1, CpdiL2>(7, 1.4);
}
TEST(Cpdi, Q4StencilMatchesDefinition) {
  check_stencil<2, CpdiQ4>(6, 0.5);
  check_stencil<2, CpdiQ4>(8, 2.5);  // reach 2: domains up to about four cells
}
TEST(Cpdi, T3StencilMatchesDefinition) {
  check_stencil<2, CpdiT3>(6, 0.5);
  check_stencil<2, CpdiT3>(8, 2.5);
}
TEST(Cpdi, Tet4StencilMatchesDefinition) {
  check_stencil<3, CpdiTet4>(5, 0.5);
  check_stencil<3, CpdiTet4>(5, 1.2);
}

// For an axis-aligned box inside one cell, the corner interpolant of the bilinear N_I is exact, so
// CPDI-R4 equals uGIMP (the exact domain average of N_I, eq. 3.12).
TEST(Cpdi, R4EqualsGimpForABoxInsideOneCell) {
  const GridGeometry<2> g = test_grid<2>(6);
  const Vec2 x(g.origin[0] + 2.5 * g.h[0], g.origin[1] + 3.4 * g.h[1]), half(0.2 * g.h[0], 0.15 * g.h[1]);
  Stencil<2, CpdiR4> cpdi;
  cpdi.compute(
      VecU<2>(x), g,
      {Vec2(x - half), Vec2(x[0] + half[0], x[1] - half[1]), Vec2(x + half), Vec2(x[0] - half[0], x[1] + half[1])});
  Stencil<2, UGimp> gimp;
  gimp.compute(VecU<2>(x), g, half);
  // The CPDI block is wider (reach 2): compare node by node.
  std::map<Index, std::array<Real, 3>> by_node;
  for (int a = 0; a < cpdi.count; ++a) by_node[cpdi.node[a]] = {cpdi.w[a], cpdi.grad[a][0], cpdi.grad[a][1]};
  for (int a = 0; a < gimp.count; ++a) {
    ASSERT_TRUE(by_node.count(gimp.node[a])) << "node " << gimp.node[a];
    const auto& c = by_node[gimp.node[a]];
    EXPECT_NEAR(c[0], gimp.w[a], 1e-14);
    EXPECT_NEAR(c[1], gimp.grad[a][0], 1e-11);
    EXPECT_NEAR(c[2], gimp.grad[a][1], 1e-11);
    by_node.erase(gimp.node[a]);
  }
  for (const auto& [node, c] : by_node) EXPECT_EQ(c[0], 0) << "node " << node << " outside GIMP's support";
}

// Kuhn's split: six right-handed tetrahedra of a sixth of the sub-cell each, centroids averaging to the
// sub-cell centre; triangles counter-clockwise.
TEST(Cpdi, SubCellSplits) {
  geometry::ParticleSeeds<3> seeds;
  seeds.positions = {Vec3(1, 2, 3)};
  seeds.volume = 0.5 * 0.25 * 0.2;
  const Vec3 spacing(0.5, 0.25, 0.2);
  const auto tets = geometry::cpdi_particles<3>(seeds, spacing, 4);
  ASSERT_EQ(tets.positions.size(), 6u);
  Vec3 mean = Vec3::Zero();
  for (std::size_t k = 0; k < 6; ++k) {
    CornerSet<3> c;
    for (int j = 0; j < 4; ++j) c[j] = tets.positions[k] + Vec3(tets.offsets[k][j]);
    EXPECT_NEAR(CpdiTetrahedron::volume(c), seeds.volume / 6, 1e-15);
    EXPECT_NEAR(tets.volumes[k], seeds.volume / 6, 1e-15);
    mean += tets.positions[k] / 6;
  }
  EXPECT_LT((mean - seeds.positions[0]).norm(), 1e-14);

  geometry::ParticleSeeds<2> square;
  square.positions = {Vec2(0, 0)};
  square.volume = 1;
  const auto tris = geometry::cpdi_particles<2>(square, Vec2(1, 1), 3);
  ASSERT_EQ(tris.positions.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    CornerSet<2> c;
    for (int j = 0; j < 3; ++j) c[j] = tris.positions[k] + Vec2(tris.offsets[k][j]);
    EXPECT_NEAR(CpdiTriangle::volume(c), 0.5, 1e-15);
  }
  EXPECT_THROW(geometry::cpdi_particles<3>(seeds, spacing, 3), std::invalid_argument);
}

}  // namespace
}  // namespace mpm

namespace mpm {
namespace {

// Corners beyond the stencil's reach (a domain three cells long, review §3.7) or outside the grid box
// are clamped into the block: partition of unity and the zero gradient sum still hold.
TEST(Cpdi, ClampedCornersKeepPartitionOfUnity) {
  const GridGeometry<2> g = test_grid<2>(6);
  const Vec2 x = g.origin + Vec2(0.2 * g.h[0], 3.5 * g.h[1]);
  for (const Real l : {3.0, 0.6}) {
    const Vec2 r1(l * g.h[0], 0.3 * g.h[1]), r2(-0.2 * g.h[0], 0.8 * l * g.h[1]);
    Stencil<2, CpdiQ4> st;
    st.compute(VecU<2>(x), g, {Vec2(x - r1 - r2), Vec2(x + r1 - r2), Vec2(x + r1 + r2), Vec2(x - r1 + r2)});
    Real sum = 0;
    Vec2 sum_grad = Vec2::Zero();
    for (int a = 0; a < st.count; ++a) {
      EXPECT_GE(st.w[a], 0);
      sum += st.w[a];
      sum_grad += Vec2(st.grad[a][0], st.grad[a][1]);
    }
    EXPECT_NEAR(sum, 1, 1e-14) << "domain " << l << " cells";
    EXPECT_LT(sum_grad.norm(), 1e-10) << "domain " << l << " cells";
  }
}

}  // namespace
}  // namespace mpm
