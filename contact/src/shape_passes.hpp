#pragma once
// The contact module's particle passes that need the scene's shape function (private to contact/):
// the mass gradient of eq. 5.12 and the particle extents of the gap criterion. One virtual call per body
// per step; the loops inside are templated on the shape like the schemes' transfers.
#include <memory>
#include <string>
#include <vector>

#include "mpm/particles/body.hpp"

namespace mpm::contact {

template <int Dim>
class ShapePasses {
 public:
  virtual ~ShapePasses() = default;
  /// out[I] += sum_p m_p grad phi_I(x_p) (eq. 5.12, not normalised; m_p / r_p when axisymmetric); `out` has one
  /// entry per node.
  virtual void mass_gradient(const Body<Dim>& body, const GridGeometry<Dim>& g, std::vector<VecU<Dim>>& out) const = 0;
  /// At the nodes flagged in `flag` (bit 1): out[I] = max(out[I], sign x_p.n_I + s_p) over the particles
  /// whose support contains I, with n_I = normal[I] and s_p half the particle's size (V_p^(1/Dim) / 2); with CPDI,
  /// max over the domain's corners of sign x_c.n_I (the domain is known, so its extent is exact).
  virtual void extents(const Body<Dim>& body, const GridGeometry<Dim>& g, const std::uint8_t* flag,
                       const VecU<Dim>* normal, Real sign, std::vector<Real>& out) const = 0;
};

/// The passes on the scene's shape function; throws std::invalid_argument, listing the valid ones, for a
/// function contact does not support (Lagrange quadratic, TLMPM-only; contact_supports in shape_passes.cpp).
/// CPDI: the mass gradient with the CPDI gradients (the ones its P2G force uses, eq. 3.30).
/// Axisymmetric: the stencils of the axisymmetric schemes, the mass gradient of the meridian density (m_p / r_p:
/// the ring mass grows with r, which would tilt the normals towards the axis) and sizes from meridian areas.
template <int Dim>
std::unique_ptr<ShapePasses<Dim>> make_shape_passes(const std::string& shape_function, Coordinates coordinates);

}  // namespace mpm::contact
