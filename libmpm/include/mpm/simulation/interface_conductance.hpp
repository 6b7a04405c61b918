#pragma once
/// \file interface_conductance.hpp
/// What a module that knows the pairs of bodies in contact (contact/: `thermal_conductance` of the `contact:`
/// section) tells heat conduction (physics/thermal) about the interfaces between bodies, without either module
/// naming the other: the thermal contact conductance of each pair (docs/theory.md §12, eq. TC.1).

#include "mpm/core/types.hpp"

namespace mpm {

/// Implemented by a Module besides Module<Dim>; heat conduction finds it by dynamic_cast among the run's modules
/// (StepContext::hooks) at its first step. Without one, every pair is in perfect thermal contact.
class InterfaceConductance {
 public:
  virtual ~InterfaceConductance() = default;
  /// h of the pair of bodies (a, b) (indices into the scene's bodies, a != b), W/(m^2 K): the heat flux across
  /// their interface per kelvin of temperature jump, q = h (T_b - T_a). +infinity: perfect contact (the bodies
  /// share the temperature at their common nodes); 0: an insulated interface.
  virtual Real interface_conductance(int a, int b) const = 0;
};

}  // namespace mpm
