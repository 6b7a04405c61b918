#pragma once
/// \file axisymmetric.hpp
/// Axisymmetric kinematics and forces (docs/theory.md §14; review App. G, eqs G.1-G.4, with volumes and masses
/// of a full revolution instead of per radian; Sulsky & Schreyer 1996; the GIMP weights of Nairn & Guilkey
/// 2015), written once as small functions that every scheme calls (USL, MUSL, USF, TLMPM here; the implicit
/// scheme later): x is the radius r, y the axial coordinate z, and a particle stands for the ring it sweeps.
///   volume and mass          V_p = 2 pi r_p A_p, m_p = rho V_p                       (G.1, G.3)
///   hoop stretch, rate       F_tt <- (1 + dt L_tt) F_tt,  L_tt = sum_I T_Ip v_rI      (G.4)
///   volume ratio             J = det(F_rz) F_tt
///   radial internal force    f_rI -= V_p sigma_tt T_Ip                                (G.2, third term)
/// T_Ip is the hoop weight, phi_I(x_p) / r_p for grid functions (hats, B-splines); for GIMP the r-weighted
/// domain averages replace phi and grad phi and T_Ip is the unweighted domain average of N_I over r_p
/// (Nairn & Guilkey 2015, eqs 19-21; review Remark 42). With the TLMPM the same functions take the reference
/// radius R_p: F_tt += dt sum_I phi_I(X_p) v_rI / R_p, and the force uses P_tt = det(F_rz) sigma_tt.
/// F_tt and L_tt are particle fields (keys::hoop_stretch, keys::hoop_velocity_gradient) that only the bodies of
/// an axisymmetric scene carry; the materials read them there (once per block, never per particle).

#include <array>
#include <numbers>

#include "mpm/grid/grid.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/shape/factored_stencil.hpp"

namespace mpm::axisym {

inline constexpr Real two_pi = 2 * std::numbers::pi_v<Real>;

/// V = 2 pi r A: the volume of the ring swept by the meridian area A (m^2) at radius r (m), m^3 (Pappus; exact for
/// a rectangular sub-cell with r its centroid).
inline Real revolved_volume(Real r, Real area) { return two_pi * r * area; }
/// A = V / (2 pi r): the meridian (r-z) area of a ring of volume V at radius r, m^2 (the particle's size in the
/// plane: artificial viscosity lengths, contact extents).
inline Real meridian_area(Real volume, Real r) { return volume / (two_pi * r); }

/// J = det(F_rz) F_tt.
inline Real volume_ratio(const Mat<2>& F, Real hoop_stretch) { return F.determinant() * hoop_stretch; }

/// F_tt^{t+dt} = (1 + dt L_tt) F_tt^t (eq. 2.55b, theta-theta component); false when it is not admissible
/// (F_tt <= 0 or not finite), which trips the stability guard like det F <= 0.
inline bool update_hoop_stretch(Real& hoop_stretch, Real hoop_rate, Real dt) {
  hoop_stretch *= 1 + dt * hoop_rate;
  return hoop_stretch > 0 && std::isfinite(hoop_stretch);
}

/// The hoop part of the radial internal force on node I (eq. G.2): -V sigma_tt T_I, N, from
/// `volume_hoop_stress` = V_p sigma_tt (N m) and the hoop weight T_I (1/m).
inline Real hoop_force(Real volume_hoop_stress, Real hoop_weight) { return -volume_hoop_stress * hoop_weight; }

/// P_tt of the first Piola-Kirchhoff stress, J sigma_tt / F_tt = det(F_rz) sigma_tt, Pa: the TLMPM's hoop force
/// is -V_0 P_tt phi_I(X_p) / R_p.
inline Real nominal_hoop_stress(const Mat<2>& F, Real hoop_stress) { return F.determinant() * hoop_stress; }

/// One axis of shape-function values for the radial axis: weights w, derivatives dw (per cell) and the
/// "planar" weights w_planar whose quotient by r is the hoop weight. Grid functions: all from `evaluate`
/// (w_planar = w). Domain functions (GIMP): Shape::evaluate_radial, the r-weighted domain averages.
template <class Shape>
inline void radial_axis(Real xi, int nodes, Real a, int& base, Real* w, Real* dw, Real* w_planar) {
  if constexpr (requires { Shape::uses_domain; }) {
    Shape::evaluate_radial(xi, nodes, a, base, w, dw, w_planar);
  } else {
    Shape::evaluate(xi, nodes, base, w, dw);
    for (int k = 0; k < Shape::support; ++k) w_planar[k] = w[k];
  }
}

/// The stencil of an axisymmetric particle: Stencil<2, Shape> (weights, gradients, nodes, offsets) with the
/// radial axis evaluated by radial_axis, plus the hoop weights T_I (1/m).
template <class Shape>
struct AxisymmetricStencil : Stencil<2, Shape> {
  using Base = Stencil<2, Shape>;
  static constexpr int per_axis = Base::per_axis;
  static constexpr int count = Base::count;

  Real hoop[count];  ///< T_I, 1/m

  inline void compute(const VecU<2>& x, const GridGeometry<2>& g, const Vec<2>& half = Vec<2>::Zero()) {
    int base[2];
    Real wa[2][per_axis], da[2][per_axis], planar[per_axis];
    const Real xi_r = (x[0] - g.origin[0]) * g.inv_h[0];
    radial_axis<Shape>(xi_r, g.nodes[0], half[0] * g.inv_h[0], base[0], wa[0], da[0], planar);
    evaluate_axis<Shape>((x[1] - g.origin[1]) * g.inv_h[1], g.nodes[1], half[1] * g.inv_h[1], base[1], wa[1], da[1]);
    this->scale_and_offset(0, xi_r, g, base[0], da[0]);
    this->scale_and_offset(1, (x[1] - g.origin[1]) * g.inv_h[1], g, base[1], da[1]);
    this->combine(base, wa, da, g);
    const Real inv_r = 1 / x[0];
    int n = 0;
    for (int j = 0; j < per_axis; ++j)
      for (int i = 0; i < per_axis; ++i, ++n) hoop[n] = planar[i] * wa[1][j] * inv_r;
  }
};

/// The stencil type of the kernels: AxisymmetricStencil in axisymmetric 2D, Stencil otherwise.
template <int Dim, class Shape, class Coords>
struct StencilSelect {
  using type = Stencil<Dim, Shape>;
};
template <class Shape>
struct StencilSelect<2, Shape, AxisymmetricCoordinates> {
  using type = AxisymmetricStencil<Shape>;
};
template <int Dim, class Shape, class Coords>
using StencilFor = typename StencilSelect<Dim, Shape, Coords>::type;

/// L_tt = sum_I T_I v_rI (eq. G.4; TLMPM: the rate of F_tt with T at the reference radius), 1/s, from the
/// nodal velocities `velocity_of(node)`.
template <class Shape, class VelocityOf>
inline Real hoop_rate(const AxisymmetricStencil<Shape>& st, VelocityOf&& velocity_of) {
  Real L = 0;
  for (int a = 0; a < st.count; ++a) L += st.hoop[a] * velocity_of(st.node[a])[0];
  return L;
}

/// f(node, phi, grad phi, T) for every node of a stencil: T is the hoop weight in axisymmetric 2D and 0 in
/// Cartesian coordinates (where f ignores it), so that one loop body serves both.
template <class Coords, int Dim, class St, class F>
inline void for_each_node_with_hoop(const St& st, const GridGeometry<Dim>& g, F&& f) {
  if constexpr (Coords::axisymmetric) {
    for (int a = 0; a < St::count; ++a) f(st.node[a], st.w[a], Vec<2>(st.grad[a][0], st.grad[a][1]), st.hoop[a]);
  } else {
    for_each_node(st, g, [&](Index n, Real w, const Vec<Dim>& grad) { f(n, w, grad, Real(0)); });
  }
}

/// The hoop fields of a particle set, or null pointers: only the bodies of an axisymmetric scene have them.
struct HoopFields {
  Real* stretch = nullptr;  ///< F_tt
  Real* rate = nullptr;     ///< L_tt of the last step, 1/s
  explicit operator bool() const { return stretch != nullptr; }
};
template <int Dim>
HoopFields hoop_fields(ParticleSet<Dim>& p) {
  if constexpr (Dim == 2)
    if (p.has_field(keys::hoop_stretch))
      return {p.field(keys::hoop_stretch).data(), p.field(keys::hoop_velocity_gradient).data()};
  return {};
}
/// F_tt of every particle, or nullptr (Cartesian bodies).
template <int Dim>
const Real* hoop_stretch_of(const ParticleSet<Dim>& p) {
  if constexpr (Dim == 2)
    if (p.has_field(keys::hoop_stretch)) return p.field(keys::hoop_stretch).data();
  return nullptr;
}
/// Adds F_tt = 1 and L_tt = 0 to the particles of an axisymmetric body.
inline void add_hoop_fields(ParticleSet<2>& p) {
  p.add_field(keys::hoop_stretch, Real(1));
  p.add_field(keys::hoop_velocity_gradient, Real(0));
}

/// J of particle i: det F, times F_tt when `hoop_stretch` (hoop_stretch_of) is not null. For loops outside the
/// step (energy, output, the guard's diagnosis); the kernels take the Coords branch at compile time.
template <int Dim>
Real volume_ratio(const ParticleSet<Dim>& p, Index i, const Real* hoop_stretch) {
  const Real det = p.F[i].determinant();
  return hoop_stretch ? det * hoop_stretch[i] : det;
}
/// F of particle i in 3x3: F_tt (axisymmetric) or 1 (plane strain, uniaxial strain) out of plane.
template <int Dim>
Mat3 deformation_gradient_3x3(const ParticleSet<Dim>& p, Index i, const Real* hoop_stretch) {
  return embed<Dim>(Mat<Dim>(p.F[i]), hoop_stretch ? hoop_stretch[i] : Real(1));
}

/// The area a node of a grid face carries, m^2 (m in 2D plane strain, 1 in 1D): the cell faces around it,
/// halved at the face's edges. Axisymmetric: the area of the revolved face (per full revolution): on a face
/// r = R, 2 pi R times the node's length along z; on a face z = const, 2 pi int N_I r dr over the node's hat
/// (2 pi h r_I inside, 2 pi h (r_I / 2 -+ h / 6) at the inner and outer edges; 0 on the axis r = 0).
template <int Dim>
Real face_node_area(const GridGeometry<Dim>& g, Index node, int normal_axis) {
  const auto ijk = g.node_indices(node);
  Real area = 1;
  for (int d = 0; d < Dim; ++d) {
    if (d == normal_axis) continue;
    const bool lower = ijk[d] == 0, upper = ijk[d] == g.nodes[d] - 1;
    area *= lower || upper ? 0.5 * g.h[d] : g.h[d];
  }
  if constexpr (Dim == 2) {
    if (g.coordinates == Coordinates::axisymmetric) {
      const Real h = g.h[0], r = g.origin[0] + h * ijk[0];
      if (normal_axis == 0) return two_pi * r * area;
      const bool inner = ijk[0] == 0, outer = ijk[0] == g.nodes[0] - 1;
      const Real ring = inner ? h * (r / 2 + h / 6) : (outer ? h * (r / 2 - h / 6) : h * r);
      return two_pi * ring;
    }
  }
  return area;
}

}  // namespace mpm::axisym
