// `mpm verify` (apps/verify_command.hpp) on catalogue cases whose exact answer is known: the GCI band on the
// finest run contains the true error, and the observed order is within 0.3 of the rate the verification report
// measures for the same method (docs/VERIFICATION.md); a quantity that does not converge (hat functions with
// FLIP and particles crossing cells) is reported as not in the asymptotic range. The Taylor anvil is checked in
// its axisymmetric form against its finest run (the 3D check is a benchmark, bench/run_verify_taylor.sh; numbers
// in docs/verify.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/solution_verification.hpp"
#include "mpm/app/verify_command.hpp"
#ifdef MPM_WITH_THERMAL
#include "heat_conduction.hpp"
#endif

namespace mpm::test {
namespace {

namespace fs = std::filesystem;

fs::path write_scene(const std::string& name, const std::string& yaml) {
  const fs::path dir = fs::path(MPM_BINARY_DIR) / "tests" / "verify_scenes";
  fs::create_directories(dir);
  std::ofstream(dir / name) << yaml;
  return dir / name;
}

app::VerifyReport verify(const fs::path& scene, int runs, std::vector<std::string> quantities) {
  app::register_modules();
  app::VerifyOptions o;
  o.scene = scene;
  o.runs = runs;
  o.quantities = std::move(quantities);
  o.output = fs::path(MPM_BINARY_DIR) / "tests" / "verify_scenes" / (scene.stem().string() + "_verify");
  std::ostringstream log;
  return app::run_verification(o, log);
}

/// The bar of review §6.1.1 (mode 1, E = 100, rho = 1, L = 25, c = 10, fixed at x = 0), MUSL with hat
/// functions and FLIP, 8 cells on the bar (2 free beyond its end), 2 particles per cell, dt = 0.1 h / c:
/// the catalogue case bar_mode1 (tests/verification/catalogue.cpp). `v0` is the amplitude of the initial
/// velocity v0 sin(pi x / 50).
std::string bar(double v0) {
  return "dimension: 1\n"
         "grid: {origin: [0], extent: [31.25], cell_size: 3.125, boundary: {x_min: fixed}}\n"
         "materials: {bar: {model: linear_elastic, density: 1, youngs_modulus: 100, poisson_ratio: 0}}\n"
         "bodies: [{name: bar, material: bar, shape: {type: box, min: [0], max: [25]}, particles_per_cell: 2,\n"
         "          velocity: [\"" +
         std::to_string(v0) +
         "*sin(_pi*x/50)\"]}]\n"
         "solver: {scheme: musl, shape_function: linear, flip_fraction: 1, dt: 0.03125, end_time: 10}\n"
         "output: {interval: 0.5, histories: [{name: bar, type: energy}]}\n";
}

TEST(Verify, BarVibrationBandHoldsTheTrueError) {
  // v_cm(t) = v0 / (beta L) cos(omega t) (eq. 6.4): 0 at t = 7.5 (three quarters of the period 10).
  const auto r = verify(write_scene("bar.yaml", bar(0.1)), 3, {"bar.velocity_cm_x@7.5"});
  ASSERT_EQ(r.runs.size(), 3u);
  const auto& q = r.quantities[0].result;
  ASSERT_TRUE(q.asymptotic) << q.verdict;
  const double exact = 0, finest = r.runs.back().values[0];
  std::printf("[ measured ] bar v_cm(7.5): %.6g (8, 16, 32 cells: %.4g, %.4g), order %.3f, GCI %.3g, true error %.3g\n",
              finest, r.runs[0].values[0], r.runs[1].values[0], q.order, q.gci, std::abs(finest - exact));
  EXPECT_LT(std::abs(finest - exact), q.gci);
  // docs/VERIFICATION.md, bar_mode1, MUSL linear on 8, 16, 32 cells: rates 1.82 and 1.91 (max |v_cm error|).
  EXPECT_NEAR(q.order, 1.87, 0.3);
  EXPECT_NEAR(r.runs[2].h, 3.125 / 4, 1e-12);
  // each run's histories, as `mpm run` writes them
  EXPECT_TRUE(fs::exists(fs::path(MPM_BINARY_DIR) / "tests" / "verify_scenes" / "bar_verify" / "run_3" / "bar.csv"));
}

TEST(Verify, CellCrossingWithHatsAndFlipIsNotAsymptotic) {
  // Ten times the amplitude: the end particles cross into the empty cells beyond the bar at every
  // resolution, the known defect of hat functions (review eq. 2.62): the quantities do not converge.
  const auto r = verify(write_scene("bar_crossing.yaml", bar(1.0)), 3, {"bar.velocity_cm_x", "bar.velocity_cm_x@5"});
  for (const auto& q : r.quantities) {
    EXPECT_FALSE(q.result.asymptotic) << q.name;
    EXPECT_EQ(q.result.gci, 0.0);
    std::printf("[ measured ] %s: %s\n", q.name.c_str(), q.result.verdict.c_str());
  }
}

/// A disk falling under gravity; `volume` "lattice" (each particle its sub-cell) or "exact" (the disk's area).
std::string falling_disk(const std::string& volume) {
  return "dimension: 2\n"
         "grid: {extent: [1, 1], cell_size: 0.1}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
         "bodies: [{name: disk, material: m, shape: {type: disk, center: [0.5, 0.5], radius: 0.23}, volume: " +
         volume +
         "}]\n"
         "solver: {scheme: musl, cfl: 0.5, gravity: [0, -9.81], end_time: 0.02}\n"
         "output: {histories: [{name: e, type: energy, interval: 0.005}]}\n";
}

// The lattice fill of a disk follows the cells, so its mass changes across the runs: measured 170, 167.5, 165.6 kg/m
// over 10, 20, 40 cells against pi r^2 rho = 166.19 (2.57% between runs); `mpm verify` says so, and not with
// `volume: exact`.
TEST(Verify, WarnsWhenABodysMassChangesAcrossTheRuns) {
  const auto lattice = verify(write_scene("disk_lattice.yaml", falling_disk("lattice")), 3, {"e.velocity_cm_y"});
  ASSERT_EQ(lattice.warnings.size(), 1u);
  EXPECT_NE(lattice.warnings[0].find("body 'disk': its mass changes by up to"), std::string::npos)
      << lattice.warnings[0];
  EXPECT_NE(lattice.warnings[0].find("volume: exact"), std::string::npos);
  std::printf("[ measured ] %s\n", lattice.warnings[0].c_str());
  const auto exact = verify(write_scene("disk_exact.yaml", falling_disk("exact")), 3, {"e.velocity_cm_y"});
  EXPECT_TRUE(exact.warnings.empty());
  for (const auto& run : exact.runs) EXPECT_NEAR(run.body_masses[0], 1000 * M_PI * 0.23 * 0.23, 1e-9);
}

#ifdef MPM_WITH_THERMAL
TEST(Verify, HeatPlateBandHoldsTheTrueError) {
  // The plate of review §5.3.3 (examples/10_heat_plate) on 10, 20, 40 cells; the temperature at the centre at
  // t = 0.02 s against the series solution (eq. 5.28), from the particles (moving least squares) and the grid.
  const auto scene = write_scene("plate.yaml", R"(
dimension: 2
grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.1}
materials:
  plate: {model: linear_elastic, density: 1, youngs_modulus: 1.0e-9, poisson_ratio: 0, specific_heat: 1, thermal_conductivity: 1}
bodies:
  - {name: plate, material: plate, shape: {type: box, min: [0, 0], max: [1, 1]}, particles_per_cell: 2}
solver: {scheme: musl, cfl: 0.8, end_time: 0.02}
thermal:
  initial_temperature: 0
  boundary: {x_min: {temperature: 100}, x_max: {temperature: 100}, y_min: {temperature: 100}, y_max: {temperature: 100}}
output:
  interval: 0.01
  histories:
    - {name: centre, type: probe, point: [0.5, 0.5], fields: [temperature]}
)");
  const auto r = verify(scene, 3, {"centre.temperature"});
  const auto& q = r.quantities[0].result;
  ASSERT_TRUE(q.asymptotic) << q.verdict;
  const double exact = verification::heat_plate_exact(0.5, 0.5, 0.02), finest = r.runs.back().values[0];
  std::printf("[ measured ] plate T(centre, 0.02 s): %.6g against %.6g, order %.3f, GCI %.3g\n", finest, exact, q.order,
              q.gci);
  EXPECT_LT(std::abs(finest - exact), q.gci);
  // docs/VERIFICATION.md, heat_plate_2d, MUSL linear: rate 2.06.
  EXPECT_NEAR(q.order, 2.06, 0.3);
}
#endif

#ifdef MPM_WITH_PLASTICITY
/// Least-squares slope of log e against log h (how docs/VERIFICATION.md computes a rate).
double rate(const std::vector<double>& h, const std::vector<double>& e) {
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < h.size(); ++k) {
    mx += std::log(h[k]) / static_cast<double>(h.size());
    my += std::log(e[k]) / static_cast<double>(h.size());
  }
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < h.size(); ++k) {
    sxy += (std::log(h[k]) - mx) * (std::log(e[k]) - my);
    sxx += (std::log(h[k]) - mx) * (std::log(h[k]) - mx);
  }
  return sxy / sxx;
}

TEST(Verify, AxisymmetricTaylorAnvilBandHoldsTheErrorAgainstTheFinestRun) {
  // The Taylor anvil (review §6.3.1; TLMPM, hat, 1 particle per cell) as the axisymmetric run of
  // examples/16_axisymmetric_taylor/verify.yaml (the 3D rod at 1/50 of its cost, within 2% of it): the rod's
  // shortening from 0 to 80 us. `mpm verify --refine 3` (h = 1.27, 0.635, 0.3175 mm: the first three runs of
  // --refine 4, the same scenes) against the fourth run, h = 0.15875 mm, as the true value. There is no exact
  // answer: the band must hold the error against the finest run, and the observed order must match the rate
  // the verification report measures for this case and method (docs/VERIFICATION.md, taylor_anvil, TLMPM
  // linear: 0.81, the 3D rod against the experiment). The rate of the errors against the finest run is printed
  // only: with a reference one level finer it is biased upwards (1.18 here, while four runs give 0.62).
  const fs::path scene = fs::path(MPM_SOURCE_DIR) / "examples" / "16_axisymmetric_taylor" / "verify.yaml";
  const auto r = verify(scene, 4, {"length.y_span@0:8e-5"});
  ASSERT_EQ(r.runs.size(), 4u);
  std::vector<ConvergenceRun> three;
  for (std::size_t k = 0; k < 3; ++k) three.push_back({r.runs[k].h, r.runs[k].values[0], r.runs[k].seconds});
  const ConvergenceResult q = analyse_convergence(three);
  const double reference = r.runs[3].values[0], finest = three[2].value;
  std::vector<double> h, error;
  for (const auto& run : three) {
    h.push_back(run.h);
    error.push_back(std::abs(run.value - reference));
  }
  const double true_rate = rate(h, error);
  for (const auto& run : r.runs)
    std::printf("[ measured ] h = %.6g mm: %lld particles, %lld steps, %.2f s, shortening %.6f mm\n", run.h * 1e3,
                run.particles, run.steps, run.seconds, run.values[0] * 1e3);
  std::printf(
      "[ measured ] 3 runs: order %.3f, extrapolated %.6f mm, GCI %.4f mm; true error %.4f mm (rate %.3f, local "
      "%.3f); 4 runs: %s\n",
      q.order, q.extrapolated * 1e3, q.gci * 1e3, std::abs(finest - reference) * 1e3, true_rate,
      std::log(error[1] / error[2]) / std::log(h[1] / h[2]), r.quantities[0].result.verdict.c_str());
  ASSERT_TRUE(q.asymptotic) << q.verdict;
  EXPECT_LT(std::abs(finest - reference), q.gci);
  constexpr double report_rate = 0.81;  // docs/VERIFICATION.md, rates table, TLMPM linear, taylor_anvil
  EXPECT_NEAR(q.order, report_rate, 0.3);
}
#endif

}  // namespace
}  // namespace mpm::test
