#pragma once
// Shared by the stability tests: a scratch directory per test and the check that a run wrote only finite
// numbers.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

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

/// The flight recorder's record of a run the guard stopped (apps flight_recorder.hpp), in `output`/failure: the
/// replay from the guard's snapshot has one frame per step and ends with the failing step (the step of the
/// guard's message), particle.csv has the failing particle on every one of those steps, nodes.csv its nodes on
/// the failing step, and diagnosis.txt names the check, a documented cause and the command.
inline void expect_flight_record(const std::filesystem::path& output, const StabilityOutcome& o) {
  namespace fs = std::filesystem;
  ASSERT_TRUE(o.stopped()) << o.summary;
  const auto step_at = o.message.find("step ");
  const auto particle_at = o.message.find(", particle ");
  ASSERT_NE(step_at, std::string::npos);
  ASSERT_NE(particle_at, std::string::npos);
  const long long failing = std::stoll(o.message.substr(step_at + 5));
  const long long particle = std::stoll(o.message.substr(particle_at + 11));
  const fs::path dir = output / "failure";
  ASSERT_TRUE(fs::is_directory(dir)) << dir;
  EXPECT_FALSE(fs::exists(output / ".failure.partial"));
  auto rows = [](const fs::path& csv) {
    std::ifstream in(csv);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  };
  const auto particle_rows = rows(dir / "particle.csv");
  ASSERT_GE(particle_rows.size(), 3u);  // the header, the snapshot's state and at least the failing step
  EXPECT_EQ(particle_rows.front().rfind("step,time,dt,x_x", 0), 0u) << particle_rows.front();
  EXPECT_NE(particle_rows.front().find(",det_F,stress_xx"), std::string::npos) << particle_rows.front();
  EXPECT_EQ(std::stoll(particle_rows.back()), failing) << "the last row is not the failing step";
  const long long first = std::stoll(particle_rows[1]);
  EXPECT_EQ(failing - first + 2, static_cast<long long>(particle_rows.size())) << "not one row per step";
  EXPECT_LE(failing - first, 20);  // the guard's snapshot interval
  int frames = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".vtu") ++frames;
  EXPECT_EQ(frames + 1, static_cast<int>(particle_rows.size())) << "not one frame per row";
  EXPECT_TRUE(fs::exists(dir / "particles.pvd"));
  const auto node_rows = rows(dir / "nodes.csv");
  ASSERT_GE(node_rows.size(), 2u);
  EXPECT_EQ(std::stoll(node_rows.back()), failing);
  std::ifstream in(dir / "diagnosis.txt");
  const std::string diagnosis((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::vector<std::string> parts{"check that failed: ", "of particle " + std::to_string(particle) + " ",
                                       "nearest documented cause (", "measured: ", "reproduce: "};
  for (const std::string& part : parts)
    EXPECT_NE(diagnosis.find(part), std::string::npos) << "missing '" << part << "' in:\n" << diagnosis;
}

}  // namespace mpm::verification
