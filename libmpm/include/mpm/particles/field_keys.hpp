#pragma once
/// \file field_keys.hpp
/// Keys of the on-demand particle fields that the core reads or writes, and of the one field that two
/// modules share without depending on each other (temperature: heated by plasticity, conducted by
/// thermal). A field only one module uses has its key in that module (`mpm/<module>/field_keys.hpp`).

#include <array>

#include "mpm/core/types.hpp"
#include "mpm/particles/field_key.hpp"
#include "mpm/shape/cpdi_elements.hpp"

namespace mpm::keys {

/// X_p, m: the position at the start (TLMPM's reference configuration; `displacement` output).
template <int Dim>
inline constexpr FieldKey<VecU<Dim>> reference_position{"reference_position"};
/// L_p of the last step, 1/s: stored only when the output asks for `velocity_gradient` (particle_set.hpp).
template <int Dim>
inline constexpr FieldKey<MatU<Dim>> velocity_gradient{"velocity_gradient"};
/// C_p of APIC (review §5.5.1), 1/s.
template <int Dim>
inline constexpr FieldKey<MatU<Dim>> affine_velocity{"affine_velocity"};
/// PolyPIC's velocity modes of degree two and more (Fu et al. 2017; docs/theory.md §2, velocity transfers), which
/// a particle keeps with v_p and C_p: 2^Dim - 1 - Dim of them, the coefficients of (x - x_p)(y - y_p) in 2D, and
/// of xy, xz, yz, xyz in 3D (kernels::polypic_masks), 1/s^2 and 1/s^3; none in 1D (PolyPIC is APIC there).
template <int Dim>
inline constexpr int polypic_extra_modes = (1 << Dim) - 1 - Dim;
template <int Dim>
using PolyModes = std::array<VecU<Dim>, (polypic_extra_modes<Dim> > 0 ? polypic_extra_modes<Dim> : 1)>;
template <int Dim>
inline constexpr FieldKey<PolyModes<Dim>> polypic_modes{"polypic_modes"};
/// Every mode zero (Eigen leaves a default-constructed vector uninitialised).
template <int Dim>
PolyModes<Dim> zero_poly_modes() {
  PolyModes<Dim> modes;
  for (auto& c : modes) c.setZero();
  return modes;
}
/// Prescribed body force per unit mass b_p, m/s^2 (manufactured solutions), added to gravity in P2G.
template <int Dim>
inline constexpr FieldKey<VecU<Dim>> body_force{"body_force"};
/// GIMP: half the initial particle domain length per axis, m (review §3.3).
template <int Dim>
inline constexpr FieldKey<VecU<Dim>> domain_half_length0{"domain_half_length0"};
/// CPDI2: the tracked corners of the particle domain, m (eq. 3.38).
template <int Dim>
inline constexpr FieldKey<CornerSet<Dim>> cpdi_corners{"cpdi_corners"};
/// Original CPDI: the initial corner offsets from the particle, m, convected with F (eq. 3.27).
template <int Dim>
inline constexpr FieldKey<CornerSet<Dim>> cpdi_corner_offsets0{"cpdi_corner_offsets0"};
/// Axisymmetric bodies only (axisymmetric.hpp): the hoop stretch F_tt (-) and the hoop velocity gradient
/// L_tt = v_r / r of the last step (1/s), which the schemes write and the materials read.
inline constexpr FieldKey<Real> hoop_stretch{"hoop_stretch"};
inline constexpr FieldKey<Real> hoop_velocity_gradient{"hoop_velocity_gradient"};
/// Temperature, K: added by a plastic material with specific_heat and by the thermal module's bodies.
inline constexpr FieldKey<Real> temperature{"temperature"};
/// Bodies whose material has a `failure:` block (failure/failing_material.hpp): 1 for a failed particle that carries
/// only compressive pressure (action fail), else 0; and the work its stress has done per reference volume,
/// integral of J sigma : D dt (J/m^3), from which its strain energy is booked (eq. 16.4).
inline constexpr FieldKey<Real> failed{"failed"};
inline constexpr FieldKey<Real> stress_work{"stress_work"};

}  // namespace mpm::keys
