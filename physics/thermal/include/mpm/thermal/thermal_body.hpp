#pragma once
/// \file thermal_body.hpp
/// The thermal constants of one body, from its material's parameters (docs/scene-reference.md).

#include "mpm/core/types.hpp"

namespace mpm::thermal {

template <int Dim>
struct ThermalBody {
  Real specific_heat = 0;                    ///< c, J/(kg K)
  Mat<Dim> conductivity = Mat<Dim>::Zero();  ///< k (tensor; k I when isotropic), W/(m K)
  Real max_conductivity = 0;                 ///< largest eigenvalue bound of k (for the time step), W/(m K)
  Real density = 0;                          ///< rho0, kg/m^3
  Real reference_temperature = 293.15;       ///< T_ref of the thermal energy (room_temperature), K
  /// Thermal expansion handled by this module (eq. 5.26 on the hypoelastic linear_elastic law): alpha, 1/K;
  /// 0 when the body does not expand or its law handles the expansion itself (plasticity).
  Real expansion = 0;
  Real lambda = 0, mu = 0;  ///< Lame constants of the linear_elastic law, Pa
};

}  // namespace mpm::thermal
