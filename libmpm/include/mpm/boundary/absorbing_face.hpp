#pragma once
/// \file boundary/absorbing_face.hpp
/// An absorbing (viscous) face, what the kind `absorbing` makes (docs/theory.md §19): Lysmer & Kuhlemeyer's
/// (1969) dashpots, a traction t = -rho c_p v_n n - rho c_s v_t (eq. 19.1) on the face's nodes, that takes out a
/// plane wave arriving at normal incidence without reflection; with an input motion (Joyner & Chen 1975), the
/// compliant base of a site response: t = rho c (2 v_in - v) per component (eq. 19.3), which sends the incident
/// wave v_in into the body and lets the reflected wave out. Engine layer: the input is a function of time, built by
/// the kind (an expression or a CSV table, src/boundary/absorbing_kind.cpp).

#include <array>
#include <functional>
#include <vector>

#include "mpm/boundary/face_condition.hpp"

namespace mpm {

struct AbsorbingFaceSpec {
  Real density = 0;       ///< kg/m^3 of the material beyond the face (the body's, for a body that continues)
  Real p_wave_speed = 0;  ///< m/s, c_p = sqrt((lambda + 2 mu) / rho): the normal dashpot rho c_p
  Real s_wave_speed = 0;  ///< m/s, c_s = sqrt(mu / rho): the tangential dashpots rho c_s
  /// The velocity (m/s, x, y, z) of the incident wave at time t (s), or empty: none (a pure absorbing face).
  std::function<std::array<Real, 3>(Real)> input;
};

template <int Dim>
class AbsorbingFace final : public FaceCondition<Dim> {
 public:
  AbsorbingFace(const GridGeometry<Dim>& g, int face, AbsorbingFaceSpec spec);

  bool has_traction() const override { return true; }
  /// f_I += A_I rho c_d (2 v_in,d(t) - v_I,d) per component d (eq. 19.3; v_in = 0 without input), with v_I =
  /// p_I / m_I the node's velocity at t from the mapping and A_I its face area (VelocityFace's: per unit out-of-plane
  /// size in 1D/2D, the revolved face in axisymmetric coordinates). Explicit in v_I: stable while dt < 2 m_I /
  /// (rho c_p A_I), that is dt < h / c_p for a face cell full of material (m_I = rho A_I h / 2), which the CFL step
  /// (cfl <= 1) keeps. Nodes without mass get nothing.
  void add_traction(NodeArray<NodeRecord<Dim>>& node, Real t, NodeRuns nodes) const override;
  /// Nothing: contact is refused for this kind (its force depends on the node's velocity, which contact splits per
  /// body); the kind's traits say so before a run is built.
  void traction_forces(Real t, NodeRuns nodes, const std::function<void(Index, int, Real)>& f) const override;
  bool does_work() const override { return true; }
  /// f_I . v dt with f_I the force add_traction() added (recomputed from the same p_I / m_I, which no stage changes
  /// between P2G and the grid update) and v the mean of the node's velocity at t and t + dt, as for a traction: the
  /// nodal kinetic energy changes by exactly that work, so the energy the dashpots take out (and the input puts in)
  /// is booked in W and the balance stays closed.
  void add_work(ExactSum& w, const NodeArray<NodeRecord<Dim>>& node, const NodeArray<NodeVelocity<Dim>>& velocity,
                const Vec<Dim>& gravity, Real mass_cutoff, Real t, Real dt, NodeMask owned,
                NodeRuns nodes) const override;

 private:
  /// The force on node j (index into nodes_) of mass m and momentum p at time t, input velocity `in`.
  Vec<Dim> force(std::size_t j, const NodeRecord<Dim>& n, const std::array<Real, 3>& in) const;
  std::array<Real, 3> input_at(Real t) const;

  std::vector<Index> nodes_;
  std::vector<Real> area_;  ///< m^2 per node of nodes_
  Vec<Dim> impedance_;      ///< kg/(m^2 s) per component: rho c_p on the normal axis, rho c_s on the others
  AbsorbingFaceSpec spec_;
};

}  // namespace mpm
