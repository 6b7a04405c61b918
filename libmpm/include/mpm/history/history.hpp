#pragma once
/// \file history.hpp
/// A history: a few numbers measured on a running simulation at a time (a probe's value, a support's
/// reaction, a body's energies, a front position), written as one row of its own CSV
/// (`output.histories`, docs/scene-reference.md#histories). A kind of history is one small file in
/// src/history/ registered in history_kind.hpp; the writer (history_writer.hpp) and `mpm verify` only see
/// this interface.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mpm/core/state_archive.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm {

/// The values of output fields (output_fields.hpp) of the bodies at one time, appended once per body and
/// field however many histories read them: histories sampled together share one cache.
template <int Dim>
class OutputFieldCache {
 public:
  explicit OutputFieldCache(const Simulation<Dim>& sim) : sim_(sim) {}
  /// body.particles.size() * components values of field `name` for body `b`, in particle order.
  const std::vector<double>& values(const std::string& name, int b);

 private:
  const Simulation<Dim>& sim_;
  std::map<std::pair<std::string, int>, std::vector<double>> values_;
};

template <int Dim>
class History {
 public:
  virtual ~History() = default;
  /// Names of the columns after `time [s]` and `step`, each "name [unit]" (units SI; extensive quantities
  /// per unit out-of-plane size in 2D and 1D, e.g. N/m).
  virtual std::vector<std::string> columns() const = 0;
  /// Appends one value per column for the current state of `sim`.
  virtual void sample(const Simulation<Dim>& sim, OutputFieldCache<Dim>& fields, std::vector<double>& row) = 0;
  /// What the history carries between two rows (a reaction's impulse since the last row), as entries
  /// `prefix`NAME of a checkpoint (state_archive.hpp), so that a restart writes the same rows. Most
  /// histories read the state at the row's time and carry nothing.
  virtual void save_state(StateArchive& /*archive*/, const std::string& /*prefix*/) const {}
  virtual void restore_state(const StateArchive& /*archive*/, const std::string& /*prefix*/) {}
};

/// The unit of an extensive quantity in a Dim-dimensional run: "N" in 3D and in axisymmetric 2D (per full
/// revolution), "N/m" in plane 2D (per unit thickness), "N/m^2" in 1D (per unit cross-section).
std::string extensive_unit(const std::string& unit, int dim, Coordinates coordinates);
/// "name [unit]" ("-" for a pure number).
std::string column_name(const std::string& name, const std::string& unit);

}  // namespace mpm
