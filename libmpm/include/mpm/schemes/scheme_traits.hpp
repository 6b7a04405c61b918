#pragma once
/// \file scheme_traits.hpp
/// What a time-integration scheme works with, declared once by its registration (scheme_registry.hpp) and asked
/// by every check, estimate and hint that depends on the scheme: the scene loader (shape functions, transfers,
/// CPDI domains), contact, heat conduction, the memory estimate, `mpm check --ranks` and the energy hints. No code
/// compares scheme names; it asks these.

#include <cstddef>
#include <string>
#include <utility>

namespace mpm {

/// Whether a scheme works with something and, when it does not, why: the refusal quotes the reason.
struct Support {
  bool yes = true;
  std::string why_not{};  ///< empty when supported

  static Support no(std::string why) { return {false, std::move(why)}; }
  explicit operator bool() const { return yes; }
};

/// Bytes a scheme keeps per particle beyond the particle fields (the memory estimate), for a shape function
/// reaching `shape_support` nodes per axis in `dimension` dimensions.
using SchemeBytesPerParticle = std::size_t (*)(int dimension, int shape_support);

/// The traits of a scheme. The defaults describe an explicit updated-Lagrangian scheme that re-maps the grid
/// velocity before its stress update (MUSL) and runs in one process.
struct SchemeTraits {
  /// Weights and gradients at the fixed reference positions (TLMPM, review §2.6): shape functions with negative
  /// weights are allowed (ShapeFunctionInfo::tlmpm_only), CPDI domains follow F, particles are never reordered.
  bool total_lagrangian = false;
  /// Takes `velocity_transfer: apic` and `polypic` (particles carrying an affine velocity); else why not.
  Support affine_transfers{};
  /// The multi-velocity contact module may run with it; else why not.
  Support contact{};
  /// Takes `solver.damping`, the local damping of its explicit grid momentum update (eq. 2.74); else why not.
  Support local_damping{};
  /// With contact's node criterion, a node whose two deformable bodies separate at v^t is released rather than
  /// corrected: true where the corrections' impulses would add energy (MUSL and USF, whose kinetic energy changes
  /// by J.v^t); false for USL, which is dissipative with contact (docs/theory.md §11, "Energy").
  bool contact_releases_separating_nodes = true;
  /// The stress update takes the velocity gradient from the grid velocities just solved for, with no re-map through
  /// the particles (USL, review Alg. 1): the least stable explicit scheme (docs/VERIFICATION.md, "Largest stable CFL
  /// factor"); the energy hints name it.
  bool stress_update_without_remap = false;
  /// A fixed dt needs no stability bound (an implicit scheme): the builder does not refuse a dt above the CFL bound,
  /// and the hints that rest on explicit-step measurements do not apply.
  bool unconditionally_stable = false;
  /// Runs on several ranks (its scatters exchange ghost nodes, tile_halo.hpp); Scheme::runs_distributed() agrees.
  bool runs_distributed = false;
  /// Grid scatters (particle-to-grid maps) per step, each one halo exchange in a distributed run: 1 for USL, 2 for
  /// the schemes that map the velocities back to the grid.
  int scatters_per_step = 0;
  /// Bytes it keeps per particle (TLMPM's cached reference stencils); null: none.
  SchemeBytesPerParticle bytes_per_particle = nullptr;
};

}  // namespace mpm
