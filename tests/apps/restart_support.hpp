#pragma once
// What the restart tests share: a small scene, the steps of a run and of its checkpoints, and the comparison of
// two output directories byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "mpm/checkpoint/checkpoint_file.hpp"
#include "run_mpm.hpp"

namespace restart_support {

namespace fs = std::filesystem;
using cli::Result;
using cli::scratch;
using cli::slurp;

struct Case {
  std::string name;
  std::string scene;  ///< ends with output.checkpoint at T/2
};
/// How GoogleTest prints a case: its name.
inline void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

/// Steps of a finished run ("done: N steps", the summary on stdout).
inline long long steps_done(const Result& r) {
  std::smatch m;
  if (!std::regex_search(r.out, m, std::regex(R"(done: (\d+) steps)"))) return -1;
  return std::stoll(m[1].str());
}

/// Steps of the checkpoints in `dir`, ascending.
inline std::vector<long long> checkpoint_steps(const fs::path& dir) {
  std::vector<long long> steps;
  for (const auto& f : mpm::checkpoint::checkpoint_files(dir))
    steps.push_back(std::stoll(f.filename().string().substr(11, 9)));
  std::sort(steps.begin(), steps.end());
  return steps;
}

inline bool killed(const Result& r) { return r.status == -1 || r.status == 128 + 9; }

/// The files of an output directory (relative paths), without its checkpoints and without the flight recorder's
/// failure/: its replay starts at the stability guard's last snapshot, which a restarted run takes anew at its
/// first step, so the two records cover different steps (each ends with the same failing step).
inline std::set<std::string> output_files(const fs::path& dir) {
  std::set<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (e.is_regular_file() && rel.rfind("checkpoints", 0) != 0 && rel.rfind("failure", 0) != 0) files.insert(rel);
  }
  return files;
}

/// A frame file: its field data describes the run that wrote it (threads, command line, ...), so it is
/// compared by value, not by bytes.
inline bool frame_file(const std::string& name) { return name.ends_with(".vtu") || name.ends_with(".vti"); }

/// Every output file of `b` is `a`'s: byte for byte, but the frames (.vtu, .vti), whose field data name the
/// run's threads and command line: every point coordinate and field value of those exactly equal, through
/// `mpm diff` with zero tolerances.
inline void expect_same_files(const fs::path& a, const fs::path& b) {
  const auto want = output_files(a), got = output_files(b);
  EXPECT_EQ(got, want);
  int compared = 0;
  for (const auto& f : want) {
    if (!got.count(f) || frame_file(f)) continue;
    EXPECT_TRUE(slurp(a / f) == slurp(b / f)) << f << " differs";
    ++compared;
  }
  EXPECT_GE(compared, 2);  // energy.csv and the .pvd at least
  const Result diff =
      cli::mpm("diff " + a.string() + " " + b.string() + " --tolerance 0 --absolute 0", a.parent_path());
  EXPECT_EQ(diff.status, 0) << diff.out << diff.err;
}

/// expect_same_files, and the final checkpoints hold the same state (the entries that name paths or the
/// run's own files aside).
inline void expect_same_output(const fs::path& reference, const fs::path& run, long long final_step) {
  expect_same_files(reference, run);
  const auto name = mpm::checkpoint::checkpoint_name(final_step);
  const auto a = mpm::checkpoint::read_checkpoint(reference / "checkpoints" / name);
  const auto b = mpm::checkpoint::read_checkpoint(run / "checkpoints" / name);
  int fields = 0;
  for (const auto& [key, array] : a.entries()) {
    if (key.rfind("run/", 0) == 0 || key.rfind("output/", 0) == 0 || key.ends_with("/path")) continue;
    ASSERT_TRUE(b.contains(key)) << key;
    EXPECT_TRUE(b.at(key).bytes == array.bytes) << key << " differs in the final checkpoint";
    if (key.rfind("bodies/", 0) == 0) ++fields;
  }
  EXPECT_GE(fields, 7);  // the core fields of one body at least
}

inline std::string checkpoint_at(double t) { return "  checkpoint: {interval: " + std::to_string(t) + "}\n"; }

inline Case two_disks() {
  return {"two_disks_musl",
          "dimension: 2\n"
          "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
          "materials: {elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1000, poisson_ratio: 0.3}}\n"
          "bodies:\n"
          "  - {name: lower_left, material: elastic, shape: {type: disk, center: [0.3, 0.3], radius: 0.15}, "
          "velocity: [0.5, 0.5]}\n"
          "  - {name: upper_right, material: elastic, shape: {type: disk, center: [0.7, 0.7], radius: 0.15}, "
          "velocity: [-0.5, -0.5]}\n"
          "solver: {scheme: musl, shape_function: linear, dt: 0.002, end_time: 0.4}\n"
          "output:\n"
          "  interval: 0.05\n"
          "  fields: [velocity, stress, body]\n" +
              checkpoint_at(0.2)};
}

/// `text` with its first `from` replaced by `to` (a test failure when there is none).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// `scene` (the two disks') with its checkpoint line replaced by `checkpoint` (empty: no checkpoints).
inline std::string with_checkpoint(std::string scene, const std::string& checkpoint) {
  return scene.replace(scene.find("  checkpoint:"), std::string::npos, checkpoint);
}

/// `scene` (the two disks') with its two body lines replaced by `bodies`.
inline std::string with_bodies(std::string scene, const std::string& bodies) {
  const auto first = scene.find("  - {name: lower_left");
  return scene.replace(first, scene.find("solver:") - first, bodies);
}

/// The check of test_restart.cpp (its file comment): the reference run, then SIGTERM, restart, SIGKILL after the
/// checkpoint at T/2, restart at one thread; the output must be the reference's, byte for byte.
inline void check_interrupted_run_reaches_the_same_bits(const Case& c) {
  const fs::path dir = scratch("restart_" + c.name);
  std::ofstream(dir / "scene.yaml") << c.scene;
  const std::string scene = (dir / "scene.yaml").string();
  const fs::path reference = dir / "reference", run = dir / "run";

  const Result ref = cli::mpm("run " + scene + " --threads 2 -o " + reference.string(), dir);
  ASSERT_EQ(ref.status, 0) << ref.err;
  const long long total = steps_done(ref);
  const auto steps = checkpoint_steps(reference / "checkpoints");
  ASSERT_EQ(steps.size(), 2u) << ref.err;  // at T/2 and at the end (keep: 2)
  ASSERT_EQ(steps[1], total);
  const long long half = steps[0], term_at = std::max(1LL, half / 2), kill_at = (half + total + 1) / 2;
  ASSERT_LT(term_at, half);
  ASSERT_LT(half, kill_at);
  ASSERT_LT(kill_at, total);

  const std::string args = "run " + scene + " --threads 2 -o " + run.string();
  const Result term = cli::mpm(args + " --test-signal-at " + std::to_string(term_at) + ":TERM", dir);
  EXPECT_EQ(term.status, 128 + 15) << term.err;
  EXPECT_NE(term.err.find("stopped by SIGTERM at step " + std::to_string(term_at)), std::string::npos) << term.err;
  EXPECT_NE(term.err.find("resume with: mpm run " + scene + " --restart"), std::string::npos) << term.err;

  const Result kill = cli::mpm(
      args + " --restart " + (run / "checkpoints").string() + " --test-signal-at " + std::to_string(kill_at) + ":KILL",
      dir);
  EXPECT_TRUE(killed(kill)) << kill.status << "\n" << kill.err;
  EXPECT_NE(kill.err.find("at step " + std::to_string(term_at)), std::string::npos) << kill.err;

  const Result last = cli::mpm(
      "run " + scene + " --threads 1 -o " + run.string() + " --restart " + (run / "checkpoints").string(), dir);
  ASSERT_EQ(last.status, 0) << last.err;
  EXPECT_NE(last.err.find(mpm::checkpoint::checkpoint_name(half) + " at step " + std::to_string(half)),
            std::string::npos)
      << last.err;
  expect_same_output(reference, run, total);
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

}  // namespace restart_support
