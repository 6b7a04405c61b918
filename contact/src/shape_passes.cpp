#include "shape_passes.hpp"

#include <cmath>
#include <stdexcept>

#include "mpm/grid/tile_binning.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/shape/shape_functions.hpp"
#include "mpm/shape/stencil.hpp"

namespace mpm::contact {
namespace {

/// The shape functions contact runs with: every listed one the updated schemes run (not tlmpm_only). Lagrange
/// quadratic is offered with the TLMPM only (its negative lobes would give a particle a negative share of a nodal
/// mass once it moves), and the TLMPM maps on the reference configuration, where two bodies never meet: there is
/// no contact to detect (contact_section.cpp refuses the TLMPM before this list is read).
template <class Shape>
constexpr bool contact_supports = !shape_tlmpm_only<Shape>;

template <int Dim, class Shape, class Coords>
class Passes final : public ShapePasses<Dim> {
 public:
  void mass_gradient(const Body<Dim>& body, const GridGeometry<Dim>& g, std::vector<VecU<Dim>>& out) const override {
    const auto& p = body.particles;
    VecU<Dim>* n = out.data();
    // Same slab colouring as the P2G scatter: race-free and deterministic (ghost nodes exchanged when distributed).
    for_each_tile_coloured(body.bins, {HaloArray::of(out)}, [&](const Index* index, Index count) {
      axisym::StencilFor<Dim, Shape, Coords> st;
      const ParticleDomain<Dim, Shape> domain(p);
      for (Index k = 0; k < count; ++k) {
        const Index i = index[k];
        st.compute(p.x[i], g, domain(i));
        const Real m = Coords::axisymmetric ? p.mass[i] / p.x[i][0] : p.mass[i];
        for (int a = 0; a < st.count; ++a)
          for (int d = 0; d < Dim; ++d) n[st.node[a]][d] += m * st.grad[a][d];
      }
    });
  }

  void extents(const Body<Dim>& body, const GridGeometry<Dim>& g, const std::uint8_t* flag, const VecU<Dim>* normal,
               Real sign, std::vector<Real>& out) const override {
    const auto& p = body.particles;
    Real* e = out.data();
    const Real* hoop = axisym::hoop_stretch_of(p);
    // a maximum, not a sum: the copy-not-add exchange keeps it the serial one all the same
    for_each_tile_coloured(body.bins, {HaloArray::of(out)}, [&](const Index* index, Index count) {
      axisym::StencilFor<Dim, Shape, Coords> st;
      const ParticleDomain<Dim, Shape> domain(p);
      for (Index k = 0; k < count; ++k) {
        const Index i = index[k];
        st.compute(p.x[i], g, domain(i));
        bool any = false;
        for (int a = 0; a < st.count; ++a) any |= (flag[st.node[a]] & 1) != 0 && st.w[a] > 0;
        if (!any) continue;
        if constexpr (shape_corner_domain<Shape>) {
          // CPDI: the particle's domain is known, the farthest of its corners along sign n_I
          const CornerSet<Dim> corners = domain(i);
          for (int a = 0; a < st.count; ++a) {
            const Index I = st.node[a];
            if (!(flag[I] & 1) || !(st.w[a] > 0)) continue;
            for (int c = 0; c < Shape::element::corners; ++c) {
              const Real s = sign * Vec<Dim>(corners[c]).dot(Vec<Dim>(normal[I]));
              if (s > e[I]) e[I] = s;
            }
          }
        } else {
          const Real volume = p.volume0[i] * axisym::volume_ratio(p, i, hoop);
          const Real size = Coords::axisymmetric ? axisym::meridian_area(volume, p.x[i][0]) : volume;
          const Real half = 0.5 * std::pow(size, 1.0 / Dim);
          for (int a = 0; a < st.count; ++a) {
            const Index I = st.node[a];
            if (!(flag[I] & 1) || !(st.w[a] > 0)) continue;
            const Real s = sign * Vec<Dim>(p.x[i]).dot(Vec<Dim>(normal[I])) + half;
            if (s > e[I]) e[I] = s;
          }
        }
      }
    });
  }
};

}  // namespace

template <int Dim>
std::unique_ptr<ShapePasses<Dim>> make_shape_passes(const std::string& shape, Coordinates coordinates) {
  std::unique_ptr<ShapePasses<Dim>> passes;
  dispatch_shape(shape, [&]<class Shape>() {
    // (a CPDI element of another dimension: the scene loader refuses it before contact is built)
    if constexpr (contact_supports<Shape> && shape_exists_in<Shape, Dim>) {
      if constexpr (Dim == 2 && shape_axisymmetric<Shape>)
        if (coordinates == Coordinates::axisymmetric) {
          passes = std::make_unique<Passes<Dim, Shape, AxisymmetricCoordinates>>();
          return;
        }
      passes = std::make_unique<Passes<Dim, Shape, CartesianCoordinates>>();
    }
  });
  if (!passes)
    throw std::invalid_argument(
        "contact is not available with the shape function '" + shape +
        "': it is offered with the TLMPM only (negative weights), and the TLMPM has no contact between bodies "
        "(valid: " +
        shape_function_names_where([]<class Shape>() { return contact_supports<Shape>; }) + ")");
  return passes;
}

template std::unique_ptr<ShapePasses<1>> make_shape_passes<1>(const std::string&, Coordinates);
template std::unique_ptr<ShapePasses<2>> make_shape_passes<2>(const std::string&, Coordinates);
template std::unique_ptr<ShapePasses<3>> make_shape_passes<3>(const std::string&, Coordinates);

}  // namespace mpm::contact
