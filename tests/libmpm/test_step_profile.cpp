// The per-phase profile (step_profile.hpp, `mpm run --profile`): off by default and then all zero; on, it
// accounts for every step and every particle-update, each scheme's transfer and stress phases get time,
// the unaccounted rest ("other") is not negative, and the numbers of the run are bit-identical with and
// without it. No timing is compared with a bound: only the bookkeeping is checked.
#include <gtest/gtest.h>

#include "scene_fixture.hpp"

namespace mpm {
namespace {

std::string scene(const std::string& scheme, const std::string& shape) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05, boundary: {y_min: fixed}}\n"
         "materials: {m: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
         "bodies: [{material: m, shape: {type: box, min: [0.2, 0.0], max: [0.8, 0.5]}, particles_per_cell: 2,\n"
         "          velocity: [\"0.2*sin(5*y)\", \"-0.1*x\"]}]\n"
         "solver: {scheme: " +
         scheme + ", shape_function: " + shape + ", cfl: 0.5, end_time: 1, snapshot_interval: 5}\n";
}

std::vector<double> positions(const Simulation<2>& sim) {
  std::vector<double> x;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) x.insert(x.end(), {b.particles.x[i][0], b.particles.x[i][1]});
  return x;
}

TEST(StepProfile, OffByDefaultAndAccountsForEveryStepWhenOn) {
  for (const char* scheme : {"usl", "musl", "usf", "tlmpm"}) {
    SCOPED_TRACE(scheme);
    auto plain = test::simulation_from_yaml<2>(scene(scheme, "cubic_bspline"));
    auto profiled = test::simulation_from_yaml<2>(scene(scheme, "cubic_bspline"));
    profiled->enable_profiling();
    double enclosing = 0;  // wall seconds of the profiled advance() calls, timed from outside
    for (int s = 0; s < 12; ++s) {
      plain->advance(plain->next_time_step());
      const auto t0 = StepProfile::Clock::now();
      profiled->advance(profiled->next_time_step());
      enclosing += StepProfile::since(t0);
    }
    EXPECT_EQ(plain->profile().total_seconds(), 0.0);
    EXPECT_EQ(plain->profile().steps, 0);
    EXPECT_EQ(positions(*plain), positions(*profiled));  // timing changes nothing

    const StepProfile& p = profiled->profile();
    EXPECT_EQ(p.steps, 12);
    EXPECT_EQ(p.particle_updates, 12 * profiled->particle_count());
    // Every phase a scheme runs was timed (a phase whose timer is missing stays exactly 0), no phase is
    // negative, the phases of a distributed run and of output were not entered, and the phases, read on the same
    // clock inside advance(), add up to no more than the wall time of the advance() calls measured around them.
    for (StepPhase phase : {StepPhase::p2g, StepPhase::grid_update, StepPhase::g2p, StepPhase::stress_update})
      EXPECT_NE(p[phase], 0) << step_phase_names[static_cast<int>(phase)];
    for (int k = 0; k < step_phase_count; ++k) EXPECT_GE(p.seconds[k], -1e-9) << step_phase_names[k];
    for (StepPhase phase : {StepPhase::halo, StepPhase::migrate, StepPhase::rebalance, StepPhase::output})
      EXPECT_EQ(p[phase], 0) << step_phase_names[static_cast<int>(phase)];
    EXPECT_LE(p.total_seconds(), enclosing);
    EXPECT_DOUBLE_EQ(p.stepping_seconds(), p.total_seconds());

    profiled->add_to_profile(StepPhase::output, 0.5);
    EXPECT_DOUBLE_EQ(profiled->profile()[StepPhase::output], 0.5);
    plain->add_to_profile(StepPhase::output, 0.5);  // ignored without profiling
    EXPECT_EQ(plain->profile().total_seconds(), 0.0);
  }
}

TEST(StepProfile, TableNamesEveryPhase) {
  StepProfile p;
  p.add(StepPhase::p2g, 2);
  p.add(StepPhase::stress_update, 1);
  p.add(StepPhase::other, 1);
  p.steps = 10;
  p.particle_updates = 1000;
  const std::string table = format_profile(p);
  for (auto name : step_phase_names) EXPECT_NE(table.find(name), std::string::npos) << name;
  EXPECT_NE(table.find("50.0%"), std::string::npos) << table;       // P2G: 2 of 4 s
  EXPECT_NE(table.find("2000000.00"), std::string::npos) << table;  // P2G: 2 s / 1000 updates, in ns
  EXPECT_NE(table.find("10 steps, 1000 particle-updates"), std::string::npos) << table;
}

}  // namespace
}  // namespace mpm
