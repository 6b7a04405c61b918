#pragma once
/// \file solver_options.hpp
/// The choices of the scene's `solver:` section as enums (docs/scene-reference.md, solver), each with its
/// names written once (enum_names.hpp). The loader validates the names; everything after it compares enums.
/// The scheme is not among them: it is a registered kind (scheme_registry.hpp), asked for its traits.

#include <array>
#include <string_view>
#include <utility>

#include "mpm/core/enum_names.hpp"

namespace mpm {

/// Grid-to-particle velocity transfer: the PIC/FLIP blend (eq. 2.53), APIC (review §5.5.1) or PolyPIC with
/// linear hats (Fu et al. 2017: APIC plus the multilinear modes; docs/theory.md §2, velocity transfers).
enum class VelocityTransfer { flip, apic, polypic };

template <>
struct EnumNames<VelocityTransfer> {
  static constexpr std::array<std::pair<VelocityTransfer, std::string_view>, 3> table{
      {{VelocityTransfer::flip, "flip"}, {VelocityTransfer::apic, "apic"}, {VelocityTransfer::polypic, "polypic"}}};
};

/// True for the transfers whose particles carry the affine velocity C_p (APIC and PolyPIC).
constexpr bool carries_affine_velocity(VelocityTransfer transfer) { return transfer != VelocityTransfer::flip; }

/// How CPDI particle domains move: corners x_p + F (X_c - X_p) (eq. 3.27) or tracked corners (CPDI2, eq. 3.38).
enum class CpdiDomainUpdate { deformation_gradient, corners };

template <>
struct EnumNames<CpdiDomainUpdate> {
  static constexpr std::array<std::pair<CpdiDomainUpdate, std::string_view>, 2> table{
      {{CpdiDomainUpdate::deformation_gradient, "deformation_gradient"}, {CpdiDomainUpdate::corners, "corners"}}};
};

/// What the energy sentinel (energy_sentinel.hpp) does when the energy balance exceeds solver.energy_tolerance:
/// log one warning and go on, or also end the run through the stability path (exit 3).
enum class EnergyDriftAction { warn, stop };

template <>
struct EnumNames<EnergyDriftAction> {
  static constexpr std::array<std::pair<EnergyDriftAction, std::string_view>, 2> table{
      {{EnergyDriftAction::warn, "warn"}, {EnergyDriftAction::stop, "stop"}}};
};

/// What a run does when its gravity stage (`solver.gravity_stage`) does not reach equilibrium within its steps:
/// stop with a message, or warn and start the run from the state reached.
enum class NoEquilibriumAction { stop, warn };

template <>
struct EnumNames<NoEquilibriumAction> {
  static constexpr std::array<std::pair<NoEquilibriumAction, std::string_view>, 2> table{
      {{NoEquilibriumAction::stop, "stop"}, {NoEquilibriumAction::warn, "warn"}}};
};

}  // namespace mpm
