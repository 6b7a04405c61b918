#pragma once
/// \file run_record.hpp
/// What a run keeps besides the simulation and its output, and a checkpoint carries on (entries `run/...`): the
/// total energy at the start (the summary's relative energy change), per body whether its material's state warning
/// was logged (each body warns once), and the warnings logged while stepping.

#include <string>
#include <vector>

#include "mpm/core/state_archive.hpp"
#include "mpm/core/types.hpp"

namespace mpm {

struct RunRecord {
  Real initial_energy = 0;            ///< J
  std::vector<bool> warned;           ///< per body: its material's state warning was logged
  std::vector<std::string> warnings;  ///< logged while stepping (state and energy), in order

  void save(StateArchive& archive) const;
  /// Reads what save() wrote; the flags only when the body count matches.
  void restore(const StateArchive& archive);
};

}  // namespace mpm
