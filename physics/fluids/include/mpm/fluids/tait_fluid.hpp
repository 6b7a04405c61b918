#pragma once
/// \file tait_fluid.hpp
/// Weakly compressible Newtonian fluid (review §5.4, eqs 5.29-5.31):
///   sigma = 2 mu dev(D) + zeta tr(D) I - p I,   p = kappa [(rho/rho0)^gamma - 1] = kappa (J^-gamma - 1),
/// with D = sym(L), the shear viscosity mu, the bulk viscosity zeta = lambda_N + 2 mu/3 (0 by default: the
/// Stokes condition lambda_N = -2 mu/3, docs/errata.md #10), and the density rho = rho0/J from
/// det F (eq. 2.55c). Stateless: F carries the whole history, so the law batches like the elastic ones.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "mpm/materials/material.hpp"

namespace mpm::fluids {

struct TaitFluid {
  static constexpr const char* key = "newtonian_fluid";
  struct Params {
    Real density;                   ///< rho0, kg/m^3
    Real bulk_modulus;              ///< kappa, Pa (may be reduced below the physical value: weak compressibility)
    Real gamma;                     ///< Tait exponent (7 water, 1.4 air)
    Real viscosity;                 ///< mu, Pa s
    Real bulk_viscosity;            ///< zeta, Pa s
    Real density_tolerance = 0.03;  ///< largest |rho/rho0 - 1| of a valid weakly compressible run
    /// p_c, Pa (<= 0, gauge like p): the pressure never falls below it (the liquid cavitates, a free-surface
    /// particle separates instead of pulling with a tension up to K); -infinity: no limit.
    Real cavitation_pressure = -std::numeric_limits<Real>::infinity();
    /// Keep only the volume of F (F = J^(1/Dim) I after every step, material_batch.hpp): the law reads J alone.
    bool volumetric_deformation = false;
  };

  static inline bool volumetric_only(const Params& c) { return c.volumetric_deformation; }

  /// p = max(kappa (J^-gamma - 1), p_c).
  static inline Real pressure(const Params& c, Real J) {
    return std::max(c.bulk_modulus * (std::pow(J, -c.gamma) - 1), c.cavitation_pressure);
  }
  /// J_c, where the Tait pressure reaches p_c: (1 + p_c / kappa)^(-1/gamma) (>= 1); +infinity without a limit
  /// (or p_c <= -kappa, below every Tait pressure).
  static inline Real cavitation_volume_ratio(const Params& c) {
    const Real s = 1 + c.cavitation_pressure / c.bulk_modulus;
    return s > 0 ? std::pow(s, -1 / c.gamma) : std::numeric_limits<Real>::infinity();
  }

  static inline Mat3 update_point(const Params& c, const PointKinematics& k, const Mat3&) {
    const Mat3 D = 0.5 * (k.L + k.L.transpose());
    const Real trD = D.trace();
    const Mat3 dev = D - trD / 3 * Mat3::Identity();
    return 2 * c.viscosity * dev + (c.bulk_viscosity * trD - pressure(c, k.J)) * Mat3::Identity();
  }
  /// Sound speed c^2 = dp/drho = gamma kappa / rho0 J^(1 - gamma).
  static inline Real wave_speed(const Params& c, Real J) {
    return std::sqrt(c.gamma * c.bulk_modulus * std::pow(J, 1 - c.gamma) / c.density);
  }
  /// nu of the longitudinal (fastest-diffusing) viscous mode, (4 mu / 3 + zeta) / rho0: the bound
  /// dt <= h^2 / (2 Dim nu) of explicit viscous diffusion (J near 1: weak compressibility).
  static inline Real kinematic_viscosity(const Params& c) {
    return (4 * c.viscosity / 3 + c.bulk_viscosity) / c.density;
  }
  /// Weak compressibility holds while rho/rho0 = 1/J stays within the tolerance (default 3%); past it the
  /// bulk modulus is too small for the flow (the pressure is no longer an incompressibility constraint).
  /// With a cavitation pressure only compression counts: an expanded particle carries p_c, a separated spray
  /// particle or cavity, not a bulk modulus too small for the flow.
  static inline std::string state_warning(const Params& c, Real J_min, Real J_max) {
    const bool cavitates = c.cavitation_pressure > -std::numeric_limits<Real>::infinity();
    const Real deviation = std::max(1 / J_min - 1, cavitates ? Real(0) : 1 - 1 / J_max);
    if (!(deviation > c.density_tolerance)) return {};
    return fmt::format(
        "newtonian_fluid: the density deviates from rho0 by {:.3g}% (rho/rho0 in [{:.4g}, {:.4g}]), more than "
        "density_tolerance = {:.3g}%: raise bulk_modulus (the sound speed should be about 10x the flow speed)",
        100 * deviation, 1 / J_max, 1 / J_min, 100 * c.density_tolerance);
  }
  /// Stored energy per reference volume, W(J) = -int_1^J p dJ = kappa [(J^(1-gamma) - 1)/(gamma - 1) + J - 1]
  /// up to J_c, and W(J_c) - p_c (J - J_c) beyond (dW/dJ = -p, so the audit stays exact with a cavitation
  /// pressure; p_c = 0: no energy in expansion). Viscous stresses store nothing.
  static inline Real energy_density(const Params& c, const Mat3& F, const Mat3&) {
    const auto tait = [&](Real J) { return c.bulk_modulus * ((std::pow(J, 1 - c.gamma) - 1) / (c.gamma - 1) + J - 1); };
    const Real J = F.determinant();
    const Real J_c = cavitation_volume_ratio(c);
    return J <= J_c ? tait(J) : tait(J_c) - c.cavitation_pressure * (J - J_c);
  }
};

}  // namespace mpm::fluids
