// A 4340 steel disk (Johnson-Cook, Mie-Gruneisen) at 10 km/s onto a fixed wall. MUSL: the EOS
// holds it: det F stops at 0.335, just above the Mie-Gruneisen limit 1 - 1/S = 0.329 where its pressure diverges
// (1D Hugoniot of the impact: J_H = 0.486, p_H = 1.52e12 Pa; the largest particle pressure is 3.6e14 Pa, at the
// particles closest to that limit); the run completes with every value finite, and the energy sentinel warns at
// step 350 (strain energy, +13.7% at most), quoting the FLIP-with-hats hint. USL: the guard stops it (an inverted
// particle at step 913). USF: the guard stops it (a jetting particle leaves the grid at step 1264). Setups:
// extended_stability_cases.cpp.
#include <gtest/gtest.h>

#include <cstdio>

#include "stability_test_support.hpp"

namespace mpm::verification {
namespace {

namespace fs = std::filesystem;

#ifdef MPM_WITH_PLASTICITY
TEST(HypervelocityEos, MuslTheEosHoldsAndTheSentinelWarns) {
  const auto dir = scratch("impact10_musl");
  const StabilityOutcome o = run_stability_case("impact_10km_s_musl", dir);
  std::printf("[ measured ] %s\n", o.summary.c_str());
  ASSERT_TRUE(o.completed()) << o.message;
  EXPECT_GT(o.output.min_det_F, 1 - 1 / 1.49);         // the EOS's singular compression is never reached
  EXPECT_LT(o.output.min_det_F, 0.40);                 // measured 0.335: beyond the 1D Hugoniot's 0.486
  EXPECT_GT(o.measures.at("max_pressure"), 1.524e12);  // measured 3.64e14 Pa
  EXPECT_LT(o.measures.at("max_pressure"), 1e15);
  EXPECT_GT(o.measures.at("energy_growth"), 0.05);  // measured +0.137
  EXPECT_LT(o.measures.at("energy_growth"), 0.25);
  // The user is warned during the run (measured: at step 350), not at its end; the step itself is not the
  // property and moves with any change of the scheme.
  EXPECT_GE(o.measures.at("warning_step"), 1) << o.log;
  EXPECT_LT(o.measures.at("warning_step"), o.steps) << o.log;
  EXPECT_NE(o.log.find("Hint: pure FLIP with linear hats"), std::string::npos) << o.log;
  EXPECT_GT(o.largest_energy_ratio, 1);  // measured 2.40
  expect_clean_output(o);
  fs::remove_all(dir);
}

TEST(HypervelocityEos, UslAndUsfAreStoppedByTheGuard) {
  const auto dir = scratch("impact10");
  const StabilityOutcome usl = run_stability_case("impact_10km_s_usl", dir / "usl");
  const StabilityOutcome usf = run_stability_case("impact_10km_s_usf", dir / "usf");
  std::printf("[ measured ] USL: %s\n[ measured ] USF: %s\n", usl.summary.c_str(), usf.summary.c_str());
  ASSERT_TRUE(usl.stopped()) << usl.summary;
  EXPECT_NE(usl.message.find("body 'projectile'"), std::string::npos) << usl.message;
  EXPECT_NE(usl.message.find("field 'deformation_gradient': det F = -"), std::string::npos) << usl.message;
  EXPECT_GT(usl.time, 1e-6);  // well into the impact (the disk reaches the wall at 0.6 us)
  ASSERT_TRUE(usf.stopped()) << usf.summary;
  EXPECT_NE(usf.message.find("field 'position'"), std::string::npos) << usf.message;
  EXPECT_NE(usf.message.find("left the grid box"), std::string::npos) << usf.message;
  for (const auto* o : {&usl, &usf}) {
    EXPECT_GT(o->output.min_det_F, 1 - 1 / 1.49);  // in the frames written before the stop
    expect_clean_output(*o);
  }
  expect_flight_record(dir / "usl", usl);
  expect_flight_record(dir / "usf", usf);
  fs::remove_all(dir);
}
#endif

}  // namespace
}  // namespace mpm::verification
