// Very stiff (E = 1e12 Pa) and nearly incompressible (nu = 0.4999) materials: the adaptive or fixed time
// step follows the wave speed, the runs stay stable and keep their accuracy, and every file written is
// finite. Cases and setups: stability_cases.cpp; numbers measured on the development machine.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "stability_test_support.hpp"

namespace mpm::verification {
namespace {

namespace fs = std::filesystem;

// The bar of review §6.1.1 with the velocity amplitude scaled with c: at E = 1e12 Pa the relative error
// must be the one of E = 100 Pa (9.2243e-3, 0.1 h/c, 16 cells): nothing in the engine may depend on the
// absolute scale of the stress or the time step (cut-offs, tolerances).
TEST(StiffMaterial, BarAtE1e12KeepsTheAccuracyOfTheSoftBar) {
  const auto dir = scratch("stiff_bar");
  const BarRun soft = run_bar(dir / "soft", 100, 16, 0.1, 1, 40);
  const BarRun stiff = run_bar(dir / "stiff", 1e12, 16, 0.1, 1, 40);
  ASSERT_TRUE(stiff.outcome.completed()) << stiff.outcome.message;
  std::printf("[ measured ] error/amplitude E=100: %.10e, E=1e12: %.10e; dt %.4g s; energy change %.3e\n",
              soft.outcome.measured, stiff.outcome.measured, 0.1 * stiff.stable_dt,
              stiff.outcome.output.energy_change());
  EXPECT_NEAR(stiff.outcome.measured, soft.outcome.measured, 1e-9);
  EXPECT_LT(stiff.outcome.measured, 0.012);
  EXPECT_NEAR(stiff.stable_dt * 1e6, soft.stable_dt * 10, 1e-9 * soft.stable_dt * 10);  // dt scales with 1/c
  EXPECT_LT(std::abs(stiff.outcome.output.energy_change()), 1e-3);
  expect_clean_output(stiff.outcome);
  fs::remove_all(dir);
}

// A block of E = 1e12 Pa at 100 m/s onto a fixed wall (c_p = 1.31e4 m/s, 398 steps): it rebounds at
// -87.0 m/s; the total energy over the 31 frames grows by at most 2.4% (during the contact, then +0.5%).
TEST(StiffMaterial, BlockImpactAtE1e12Rebounds) {
  const auto dir = scratch("stiff_block");
  const StabilityOutcome o = run_stability_case("stiff_block_impact", dir);
  std::printf("[ measured ] %s\n", o.summary.c_str());
  ASSERT_TRUE(o.completed()) << o.message;
  EXPECT_GT(o.measured, -95);
  EXPECT_LT(o.measured, -80);
  EXPECT_LT(o.output.max_energy_growth(), 0.04);
  expect_clean_output(o);
  fs::remove_all(dir);
}

// Neo-Hookean disk with nu = 0.4999 spinning rigidly at 2 rad/s for 0.1 s: the time step follows c_p =
// 1291 m/s (5168 steps), det F stays within 4.8e-5 of 1 and the energy within 3.6e-5. The pressure is
// noise: max |sigma| 8.0e4 Pa where the exact rigid rotation has about 180 Pa (volumetric locking of the
// linear hat functions, review §3.6); asserted as a bound so that a change shows.
TEST(StiffMaterial, NearlyIncompressibleDiskStaysIsochoric) {
  const auto dir = scratch("incompressible");
  const StabilityOutcome o = run_stability_case("nearly_incompressible", dir);
  std::printf("[ measured ] %s\n", o.summary.c_str());
  ASSERT_TRUE(o.completed()) << o.message;
  EXPECT_GT(o.steps, 5000);
  EXPECT_LT(o.measured, 2e-4);
  EXPECT_LT(std::abs(o.output.energy_change()), 1e-3);
  EXPECT_LT(o.output.max_abs_stress, 2e5);
  expect_clean_output(o);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mpm::verification
