#pragma once
/// \file material.hpp
/// The material interface. A material updates the stress of a whole range of particles in one call
/// (one virtual call per body per step); the per-point law is an inlined `update_point` of the
/// concrete model, which the batch loop in MaterialBatch calls without any virtual dispatch.

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/core/exact_sum.hpp"
#include "mpm/particles/particle_set.hpp"

namespace mpm {

/// Per-axis maximum of (c_p + |v_p,axis|) over a batch: the denominator of the CFL condition
/// (review eq. 2.72), gathered while the stress is updated so the time step costs no extra pass.
template <int Dim>
struct WaveSpeedBound {
  Vec<Dim> max_speed = Vec<Dim>::Zero();  ///< m/s
  bool finite = true;                     ///< false if any updated stress was not finite (guard)
  void merge(const WaveSpeedBound& o) {
    max_speed = max_speed.cwiseMax(o.max_speed);
    finite = finite && o.finite;
  }
};

/// Kinematics a point update receives: the deformation gradient at the end of the step (already
/// updated by the scheme, eq. 2.55b) and the velocity gradient over the step, both embedded in 3x3.
struct PointKinematics {
  Mat3 F;   ///< deformation gradient F^{t+dt}
  Mat3 L;   ///< velocity gradient L^{t+dt}, 1/s
  Real J;   ///< det F
  Real dt;  ///< s
};

template <int Dim>
class Material {
 public:
  virtual ~Material() = default;
  /// The registry key of the model ("linear_elastic", ...).
  virtual std::string_view model() const = 0;
  /// Reference density, kg/m^3.
  virtual Real density() const = 0;
  /// Updates the stress of particles [begin, end), serially, from their (already updated) F and the
  /// velocity gradients L[i - begin] of the step; returns the CFL speed bound. The schemes call it on
  /// blocks of about a thousand particles right after the grid-to-particle transfer of that block,
  /// while its data is still in cache (one virtual call per block).
  virtual WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L,
                                            Real dt) = 0;
  /// The CFL speed bound of the current state, without updating anything (used before the first step).
  virtual WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const = 0;
  /// Adds the stored (strain) energy of each particle to `sum`, J (per unit out-of-plane size in 1D/2D):
  /// one term per particle, summed exactly, so the total does not depend on the particles' order.
  virtual void add_strain_energy(const ParticleSet<Dim>& p, ExactSum& sum) const = 0;
  /// Adds the energy each particle has dissipated so far (plastic work), J; nothing for elastic models.
  virtual void add_dissipated_energy(const ParticleSet<Dim>&, ExactSum&) const {}
  /// The sums of the two above over `p`, J.
  Real strain_energy(const ParticleSet<Dim>& p) const {
    ExactSum s;
    add_strain_energy(p, s);
    return s.value();
  }
  Real dissipated_energy(const ParticleSet<Dim>& p) const {
    ExactSum s;
    add_dissipated_energy(p, s);
    return s.value();
  }
  /// Adds and initialises the on-demand particle fields the model keeps (history variables such as the
  /// plastic strain). Called once by the simulation builder after the body's particles are created.
  virtual void prepare_particles(ParticleSet<Dim>&) const {}
  /// Appends one value per particle of a model-specific output field (e.g. "plastic_strain") and returns
  /// true, or returns false if the model has no such field.
  virtual bool append_output(std::string_view /*field*/, const ParticleSet<Dim>&, std::vector<double>&) const {
    return false;
  }
  /// Kinematic viscosity nu (m^2/s) of the model's viscous stress, 0 if it has none: the simulation adds the
  /// explicit diffusion bound dt <= h^2 / (2 Dim nu) to the CFL bound (review §5.4).
  virtual Real kinematic_viscosity() const { return 0; }
  /// False for a model that reads no deformation gradient (the incompressible fluid, whose particles keep their
  /// volume): the explicit schemes then leave F = I instead of updating it, and an update that would invert it (a
  /// splash's velocity gradient over a step the flow's CFL allows) is not an error.
  virtual bool tracks_deformation() const { return true; }
  /// Each particle's dilatational wave speed c (m/s) in its current state, into `c` (resized to p.size()), for the
  /// failure criterion min_time_step (eq. 16.3); false when the model cannot give it per particle.
  virtual bool particle_wave_speeds(const ParticleSet<Dim>&, std::vector<Real>& /*c*/) const { return false; }
  /// The particles `which` failed (failure/failure_criteria.hpp, action fail): a model with a failed state of its own
  /// enters it (plasticity: damage D = 1, which stops plastic flow and tension, eq. B.16), so that its history stays
  /// consistent with the pressure-only stress the failure wrapper gives them. Nothing for the others.
  virtual void mark_failed(ParticleSet<Dim>&, std::span<const Index> /*which*/) const {}
  /// A message when the particles' state has left the range in which the model is valid (e.g. a weakly
  /// compressible fluid compressed beyond its stated tolerance), empty otherwise. The run checks it at each
  /// output frame and logs the first message of every body.
  virtual std::string state_warning(const ParticleSet<Dim>&) const { return {}; }
};

}  // namespace mpm
