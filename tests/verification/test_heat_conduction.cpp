// The thermal verification tests of review §5.3.3 (digest C.5) with the thermal module: the 1D bar of eq. 5.27
// and the 2D plate of eq. 5.28, each at two resolutions, errors asserted against the series solutions with
// bounds a little above the measured values (printed as [ measured ]); the error must fall with h (second
// order for the linear functions: the ratio of the errors at h and h/2 is about 4).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <tuple>

#include "heat_conduction.hpp"
#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/scene_loader.hpp"

namespace mpm::verification {
namespace {

void print(const char* what, const HeatSpec& s, const HeatResult& r) {
  std::printf(
      "[ measured ] %s: %d cells, h = %.4g, dt = %.4g s (%lld steps), %lld particles: max nodal error %.4e, "
      "T(probe) = %.5f (exact %.5f), %.3f s\n",
      what, s.cells, r.h, r.dt, r.steps, r.particles, r.max_error, r.probe, r.probe_exact, r.wall_seconds);
}

TEST(HeatConduction, ExactSeriesValues) {
  // Digest C.5a table (series of eq. 5.27) and C.5b (eq. 5.28 at t = 0.05).
  EXPECT_NEAR(heat_bar_exact(0.5, 0.03), 0.04123, 1e-5);
  EXPECT_NEAR(heat_bar_exact(0.9, 0.05), 0.75183, 1e-5);
  EXPECT_NEAR(heat_bar_exact(0.75, 0.0075), 0.04123, 1e-5);
  EXPECT_NEAR(heat_plate_exact(0.5, 0.5, 0.05), 40.354, 1e-3);
  EXPECT_NEAR(heat_plate_exact(0.25, 0.25, 0.05), 69.400, 1e-3);
  EXPECT_NEAR(heat_plate_exact(0.25, 0.5, 0.05), 57.278, 1e-3);
}

TEST(HeatConduction, Bar1dAgainstEq527AtTwoResolutions) {
  // 1 particle per cell, T held on the end nodes, dt = 0.8 x h^2/(2k) (the paper's 8e-5 is above the bound).
  HeatSpec s;
  s.dimension = 1;
  s.particles_per_cell = 1;
  s.cells = 100;
  const HeatResult coarse = run_heat(s);
  print("1D bar eq. 5.27", s, coarse);
  s.cells = 200;
  const HeatResult fine = run_heat(s);
  print("1D bar eq. 5.27", s, fine);
  ASSERT_TRUE(coarse.failure.empty() && fine.failure.empty()) << coarse.failure << fine.failure;
  EXPECT_NEAR(coarse.dt, 0.8 * 0.5 * 0.01 * 0.01, 1e-12);  // the diffusion bound governs
  EXPECT_LT(coarse.max_error, 2.0e-4);
  EXPECT_LT(fine.max_error, 5.0e-5);
  EXPECT_GT(coarse.max_error / fine.max_error, 3.0);  // second order
  EXPECT_NEAR(coarse.probe, 0.11384, 3e-4);           // T(0.5, 0.05), digest table
}

TEST(HeatConduction, Bar1dWithEverySchemeAndSmoothFunctions) {
  // The same bar through the TLMPM path (reference weights, nominal flux), USL, USF, and the cubic and
  // quadratic B-splines. (With 1 particle at each cell centre the quadratic B-spline has the hat's weights and
  // gradients, so the same error; the cubic one's wider support smooths more: 7.1e-4.)
  for (const auto& [scheme, shape, bound] : {std::tuple<const char*, const char*, double>{"tlmpm", "linear", 2e-4},
                                             {"usl", "linear", 2e-4},
                                             {"usf", "linear", 2e-4},
                                             {"musl", "cubic_bspline", 1e-3},
                                             {"musl", "quadratic_bspline", 2e-4}}) {
    HeatSpec s;
    s.dimension = 1;
    s.cells = 100;
    s.scheme = scheme;
    s.shape_function = shape;
    const HeatResult r = run_heat(s);
    print((std::string("1D bar eq. 5.27, ") + scheme + "/" + shape).c_str(), s, r);
    ASSERT_TRUE(r.failure.empty()) << r.failure;
    EXPECT_LT(r.max_error, bound) << scheme << "/" << shape;
  }
}

TEST(HeatConduction, Plate2dAgainstEq528AtTwoResolutions) {
  // 2 x 2 = 4 particles per cell, T1 = 100 held on the face nodes, dt = 0.8 x h^2/(4k); centre 40.354 at t = 0.05.
  HeatSpec s;
  s.dimension = 2;
  s.particles_per_cell = 2;
  s.cells = 20;
  const HeatResult coarse = run_heat(s);
  print("2D plate eq. 5.28", s, coarse);
  s.cells = 40;
  const HeatResult fine = run_heat(s);
  print("2D plate eq. 5.28", s, fine);
  ASSERT_TRUE(coarse.failure.empty() && fine.failure.empty()) << coarse.failure << fine.failure;
  EXPECT_NEAR(coarse.probe_exact, 40.354, 1e-3);
  EXPECT_NEAR(coarse.probe, 40.354, 0.3);
  EXPECT_NEAR(fine.probe, 40.354, 0.08);
  EXPECT_LT(coarse.max_error, 3.5e-3);  // relative to T1 = 100
  EXPECT_LT(fine.max_error, 9.0e-4);
  EXPECT_GT(coarse.max_error / fine.max_error, 3.0);
}

TEST(HeatConduction, Plate2dWithTheBoundaryOnTheParticles) {
  // The paper's variant (review §5.3.3): the particles of the boundary cells held at T1. The effective
  // boundary then lies inside the plate, so the centre is hotter than the series; the error falls with h.
  HeatSpec s;
  s.dimension = 2;
  s.particles_per_cell = 2;
  s.particle_boundary = true;
  s.cells = 20;
  const HeatResult coarse = run_heat(s);
  print("2D plate eq. 5.28, particle boundary", s, coarse);
  s.cells = 40;
  const HeatResult fine = run_heat(s);
  print("2D plate eq. 5.28, particle boundary", s, fine);
  ASSERT_TRUE(coarse.failure.empty() && fine.failure.empty());
  EXPECT_GT(coarse.probe, 40.354);
  EXPECT_LT(std::abs(fine.probe - 40.354), std::abs(coarse.probe - 40.354));
}

TEST(HeatConduction, Example10PlateGivesTheNumbersOfItsReadme) {
  // examples/10_heat_plate/plate.yaml (20 x 20 cells, 4 PPC): centre 40.124 against the exact 40.354.
  app::register_modules();
  auto sim = app::build_simulation<2>(load_scene(std::string(MPM_SOURCE_DIR) + "/examples/10_heat_plate/plate.yaml"));
  EXPECT_EQ(sim->particle_count(), 1600);
  EXPECT_NE(sim->time_step_limiter().find("heat conduction"), std::string::npos);
  sim->run();
  const auto& T = sim->grid().node_fields.at("temperature");
  const double centre = T[10 + 21 * 10];
  std::printf("[ measured ] example 10: centre %.4f (exact %.4f)\n", centre, heat_plate_exact(0.5, 0.5, 0.05));
  EXPECT_NEAR(centre, 40.124, 0.01);
}

#ifdef MPM_WITH_PLASTICITY
TEST(HeatConduction, Example11TaylorSceneSharesTheTemperatureWithPlasticity) {
  // examples/11_thermal_taylor/tlmpm.yaml: one temperature field, from room temperature; the CFL bound
  // governs (the diffusion bound h^2 rho c/(6k) = 3.7e-7 s is above h/c = 1.0e-7 s).
  app::register_modules();
  auto sim =
      app::build_simulation<3>(load_scene(std::string(MPM_SOURCE_DIR) + "/examples/11_thermal_taylor/tlmpm.yaml"));
  EXPECT_EQ(sim->particle_count(), 9180);
  const auto& p = sim->bodies()[0].particles;
  ASSERT_TRUE(p.has_field("temperature") && p.has_field("heat_flux"));
  EXPECT_DOUBLE_EQ(p.field<Real>("temperature")[0], 293.15);
  EXPECT_EQ(sim->time_step_limiter(), "CFL bound h / (c + |v|), eq. 2.73");
  const double diffusion = 0.5e-3 * 0.5e-3 * 8940 * 383 / (6 * 386.0);
  EXPECT_NEAR(sim->modules().front()->stable_time_step(sim->bodies()), diffusion, 1e-12 * diffusion);
}
#endif

}  // namespace
}  // namespace mpm::verification
