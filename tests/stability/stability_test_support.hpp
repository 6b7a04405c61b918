#pragma once
// Shared by the stability tests: a scratch directory per test and the check that a run wrote only finite
// numbers.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "stability_cases.hpp"

namespace mpm::verification {

inline std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("mpm_stability_" + name + "_" + std::to_string(::getpid()));
}

/// Frames were written (at least the first and the last good one) and every value in them is finite.
inline void expect_clean_output(const StabilityOutcome& o) {
  EXPECT_GE(o.output.vtu_files, 2);
  EXPECT_FALSE(o.output.energy.empty());
  EXPECT_TRUE(o.output.all_finite()) << o.output.bad.front();
}

}  // namespace mpm::verification
