#pragma once
/// \file stability_error.hpp
/// Thrown when the stability guard stops a run: non-finite values, inverted deformation (det F <= 0)
/// or a particle outside the grid. The simulation has already been rolled back to the last good state.
/// Also thrown by the run loop when the energy sentinel stops a run (`solver.on_energy_drift: stop`): field
/// "energy_balance", no particle, `detail` the whole message; the state is then that of the step it found.

#include <stdexcept>
#include <string>

#include "mpm/core/types.hpp"

namespace mpm {

struct StabilityReport {
  Index step = 0;       ///< the step that failed
  Real time = 0;        ///< s, at the start of the failing step
  std::string body;     ///< body name
  Index particle = -1;  ///< particle id (its index at creation, stable under reordering)
  std::string field;    ///< "position", "velocity", "deformation_gradient", "stress", ..., "energy_balance"
  std::string detail;   ///< the offending value, e.g. "det F = -0.2"
  std::string face;     ///< field "position": the face of the grid box the particle left through ("y_min"), or empty
};

class StabilityError : public std::runtime_error {
 public:
  explicit StabilityError(const StabilityReport& r);
  const StabilityReport& report() const { return report_; }

 private:
  StabilityReport report_;
};

}  // namespace mpm
