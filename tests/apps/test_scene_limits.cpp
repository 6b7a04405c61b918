// Scenes too big for the machine, and time steps collapsed by a typo, as a new user meets them:
// the examples with one number changed. A scene whose memory estimate exceeds the memory available is refused before
// anything is allocated (exit 2, file:line:column, the estimate and the memory available); `mpm check` and the start
// of `mpm run` warn when the step count or the wall time is absurd, naming the key that sets the time step.
// The fixtures of tests/data (body_particles_per_cell_too_many, memory_*, solver_dt_too_small_for_end_time,
// body_velocity_collapses_time_step) check the messages' places; these tests check the numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <string>

#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

using cli::mpm;
using cli::scratch;
using cli::slurp;

const fs::path examples = fs::path(MPM_SOURCE_DIR) / "examples";

/// `text` with its first `from` replaced by `to` (the test fails when `from` is absent).
std::string scene_limits_replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Writes an example's scene with one change into `dir` (beside copies of the files it reads).
fs::path changed_example(const fs::path& dir, const std::string& example, const std::string& scene,
                         const std::string& from, const std::string& to) {
  fs::copy(examples / example, dir / example, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  const fs::path file = dir / example / scene;
  const std::string text = scene_limits_replaced(slurp(file), from, to);
  std::ofstream(file) << text;
  return file;
}

/// The number after `before` in `text` (NaN when absent).
double number_after(const std::string& text, const std::string& before) {
  const auto at = text.find(before);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + before.size(), nullptr);
}

TEST(SceneLimits, TaylorAnvilAtAHundredParticlesPerCellIsRefusedWithItsEstimate) {
  const auto dir = scratch("limits_ppc");
  const fs::path scene =
      changed_example(dir, "05_taylor_anvil", "musl.yaml", "particles_per_cell: 2", "particles_per_cell: 100");
  const auto r = mpm("check " + scene.string(), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("musl.yaml:26:25: bodies[0].particles_per_cell: the scene needs about"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("available (MemAvailable"), std::string::npos) << r.err;
  // The fill would make pi r^2 L / (h/100)^3 = 9.218e9 particles; the estimate samples 32,768 lattice points.
  const double exact = std::numbers::pi * 3.8e-3 * 3.8e-3 * 25.4e-3 / std::pow(0.0005 / 100, 3);
  const double estimate = number_after(r.err, "body 'rod': ");
  EXPECT_NEAR(estimate / exact, 1.0, 0.02) << r.err;
  fs::remove_all(dir);
}

TEST(SceneLimits, ImageImpactWithANanometreCellIsRefusedAtTheCellSize) {
  const auto dir = scratch("limits_cell");
  const fs::path scene = changed_example(dir, "08_image_impact", "scene.yaml", "cell_size: 0.5e-3", "cell_size: 1e-9");
  const auto r = mpm("check " + scene.string(), dir);
  EXPECT_EQ(r.status, 2) << r.err;  // it was std::bad_alloc, exit 1
  EXPECT_NE(r.err.find("scene.yaml:9:14: grid.cell_size: the grid alone needs about"), std::string::npos) << r.err;
  // 5e7 x 3e7 cells: (5e7 + 1)(3e7 + 1) = 1.5e15 nodes.
  EXPECT_NEAR(number_after(r.err, "memory (") / 1.5e15, 1.0, 1e-6) << r.err;
  fs::remove_all(dir);
}

TEST(SceneLimits, AnAddressSpaceLimitIsObeyedAndNamed) {
#ifdef MPM_SANITIZE
  GTEST_SKIP() << "AddressSanitizer reserves ~14 TB of shadow address space at start: no program starts under "
                  "`ulimit -v 3000000` in a sanitizer build";
#endif
  // 16e6 particles (a 1 m box, 1 mm cells, 4 x 4 per cell), several GB: more than `ulimit -v` 3 GB allows.
  const auto dir = scratch("limits_ulimit");
  std::ofstream(dir / "big.yaml") << "dimension: 2\n"
                                     "grid: {extent: [1, 1], cell_size: 0.001}\n"
                                     "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1e6, "
                                     "poisson_ratio: 0.3}}\n"
                                     "bodies: [{material: m, shape: {type: box, min: [0, 0], max: [1, 1]}, "
                                     "particles_per_cell: 4}]\n"
                                     "solver: {end_time: 0.01, cfl: 0.5}\n";
  const std::string cmd = "ulimit -v 3000000 && " + std::string(MPM_EXECUTABLE) + " check " +
                          (dir / "big.yaml").string() + " > " + (dir / "stdout").string() + " 2> " +
                          (dir / "stderr").string() + " < /dev/null";
  const int raw = std::system(("bash -c '" + cmd + "'").c_str());
  const std::string err = slurp(dir / "stderr");
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 2) << err;
  EXPECT_NE(err.find("big.yaml:4:"), std::string::npos) << err;
  EXPECT_NE(err.find("bodies[0].particles_per_cell: the scene needs about"), std::string::npos) << err;
  EXPECT_NE(err.find("(ulimit -v less what the process maps)"), std::string::npos) << err;
  // The box's lattice is counted exactly in closed form: 1000 x 4 points per axis.
  EXPECT_EQ(number_after(err, "body 'body0': "), 16e6) << err;
  fs::remove_all(dir);
}

TEST(SceneLimits, CheckPrintsTheEstimate) {
  const auto dir = scratch("limits_check");
  const auto r = mpm("check " + (examples / "02_two_disks" / "scene.yaml").string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  const double built = number_after(r.out, "valid. 2D, ");
  const double estimated = number_after(r.out, "estimated before building (");
  EXPECT_GT(built, 0) << r.out;
  EXPECT_NEAR(estimated / built, 1.0, 0.02) << r.out;
  fs::remove_all(dir);
}

TEST(SceneLimits, NeckingWithANanoDensityWarnsAtTheDensity) {
  const auto dir = scratch("limits_density");
  const fs::path original = examples / "06_tensile_necking" / "scene.yaml";
  const auto before = mpm("check " + original.string(), dir);
  ASSERT_EQ(before.status, 0) << before.err;
  EXPECT_EQ(before.err.find("warning"), std::string::npos) << before.err;  // no false alarm
  const double steps = number_after(before.out, "about ");
  const fs::path scene = changed_example(dir, "06_tensile_necking", "scene.yaml", "density: 7750 ", "density: 1e-9 ");
  const auto r = mpm("check " + scene.string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  // The warning on stderr, the report still on stdout.
  EXPECT_NE(r.err.find("warning: " + scene.string() + ":14:14: materials.weldox_460e.density: about "),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(": valid."), std::string::npos) << r.out;
  // c = sqrt(modulus / density): the steps grow as sqrt(7750 / 1e-9) = 2.78e6, to about 6e11.
  const double warned = number_after(r.err, "materials.weldox_460e.density: about ");
  EXPECT_NEAR(warned / (steps * std::sqrt(7750 / 1e-9)), 1.0, 0.01) << r.err;
  EXPECT_NE(r.err.find("above 1e+07 steps or 1e+06 s of wall time"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

std::string block(const std::string& velocity, const std::string& end_time) {
  return "dimension: 2\n"
         "grid: {extent: [1, 1], cell_size: 0.05}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
         "bodies: [{name: block, material: m, shape: {type: box, min: [0.3, 0.3], max: [0.6, 0.6]}, velocity: " +
         velocity + "}]\nsolver: {cfl: 0.5, end_time: " + end_time + "}\n";
}

TEST(SceneLimits, TheWarningNamesTheVelocityOrTheEndTimeWhenTheyGovern) {
  const auto dir = scratch("limits_keys");
  // 2e5 m/s against c = 3.7 m/s: dt = 0.5 x 0.05 / 2e5 = 1.25e-7 s, 8e7 steps to 10 s.
  std::ofstream(dir / "fast.yaml") << block("[2.0e5, 0]", "10");
  auto r = mpm("check " + (dir / "fast.yaml").string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("fast.yaml:4:"), std::string::npos) << r.err;  // check's warnings go to stderr
  EXPECT_NE(r.err.find("bodies[0].velocity: about 8e+07 steps"), std::string::npos) << r.err;
  // At rest, 1e6 s: the wave crosses the 1 m grid 3.7e6 times; the end time is the typo.
  std::ofstream(dir / "long.yaml") << block("[0, 0]", "1.0e6");
  r = mpm("check " + (dir / "long.yaml").string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("long.yaml:5:30: solver.end_time: about"), std::string::npos) << r.err;
  // `mpm run` says it at the start too.
  r = mpm("run " + (dir / "long.yaml").string() + " --steps 1 -o " + (dir / "out").string(), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("warning: " + (dir / "long.yaml").string() + ":5:30: solver.end_time: about"), 0u) << r.err;
  fs::remove_all(dir);
}

TEST(SceneLimits, ParticlesCommandIsBounded) {
  const auto dir = scratch("limits_particles");
  const fs::path mesh = fs::path(MPM_SOURCE_DIR) / "examples" / "15_stl_cylinder";
  fs::path stl;
  for (const auto& e : fs::directory_iterator(mesh))
    if (e.path().extension() == ".stl") stl = e.path();
  ASSERT_FALSE(stl.empty());
  auto r = mpm("particles " + stl.string() + " --spacing 0.001 --ppc 101 -o " + (dir / "p.vtu").string(), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--ppc must be between 1 and 100"), std::string::npos) << r.err;
  r = mpm("particles " + stl.string() + " --spacing 1e-9 -o " + (dir / "p.vtu").string(), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--spacing 1e-09 m makes 7.6e+09 cells on an axis of the input (at most 1e9)"),
            std::string::npos)
      << r.err;
  r = mpm("particles " + stl.string() + " --spacing 1e-5 -o " + (dir / "p.vtu").string(), dir);  // ~1e17 particles
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("use a smaller --ppc or a larger --spacing"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "p.vtu"));
  fs::remove_all(dir);
}

}  // namespace
