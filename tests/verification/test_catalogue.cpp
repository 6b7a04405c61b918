// The verification catalogue (catalogue.hpp) is the one interface through which the error-against-run-
// time report reaches every case: each entry must run at its coarsest resolution and give a finite
// error with its wall time.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "catalogue.hpp"

namespace mpm::verification {
namespace {

TEST(Catalogue, EveryCaseRunsAtItsCoarsestResolution) {
  const auto cases = catalogue(true);
  std::set<std::string> names;
  for (const auto& c : cases) {
    ASSERT_TRUE(names.insert(c.name).second) << "duplicate case " << c.name;
    ASSERT_FALSE(c.resolutions.empty()) << c.name;
    if (c.name.rfind("vortex", 0) == 0 || c.name.rfind("mms_3d", 0) == 0) continue;  // slow: run by their own tests
    const CaseRun r = c.run(c.resolutions.front());
    EXPECT_TRUE(r.failure.empty()) << c.name << ": " << r.failure;
    EXPECT_TRUE(std::isfinite(r.error)) << c.name;
    EXPECT_GT(r.wall_seconds, 0) << c.name;
    EXPECT_GT(r.steps, 0) << c.name;
  }
  EXPECT_GE(cases.size(), 39u);  // bar 8, MMS 24, vortex 3, 000 paper 4
}

}  // namespace
}  // namespace mpm::verification
