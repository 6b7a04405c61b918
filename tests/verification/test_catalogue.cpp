// The verification catalogue (catalogue.hpp) is the one interface through which the error-against-run-
// time report reaches every case: each entry must run at its coarsest resolution and give a finite
// error with its wall time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "catalogue.hpp"
#include "mpm/schemes/scheme.hpp"

namespace mpm::verification {
namespace {

TEST(Catalogue, EveryCaseRunsAtItsCoarsestResolution) {
  const auto cases = catalogue(true);
  std::set<std::string> names;
  for (const auto& c : cases) {
    ASSERT_TRUE(names.insert(c.name).second) << "duplicate case " << c.name;
    ASSERT_FALSE(c.resolutions.empty()) << c.name;
    if (c.name.rfind("vortex", 0) == 0 || c.name.rfind("mms_3d", 0) == 0 || c.family == "taylor_anvil")
      continue;  // slow: run by their own tests
    const CaseRun r = c.run(c.resolutions.front());
    EXPECT_TRUE(r.failure.empty()) << c.name << ": " << r.failure;
    EXPECT_TRUE(std::isfinite(r.error)) << c.name;
    EXPECT_GT(r.wall_seconds, 0) << c.name;
    EXPECT_GT(r.steps, 0) << c.name;
  }
  // Bar and 1D/2D MMS: every method of their dimension (schemes x shape functions from the engine's tables).
  for (const auto& [scheme, shape] : methods(1)) {
    EXPECT_TRUE(names.count("bar_mode1/" + scheme + "/" + shape)) << scheme << "/" << shape;
    EXPECT_TRUE(names.count("mms_1d_large/" + scheme + "/" + shape)) << scheme << "/" << shape;
  }
  for (const auto& [scheme, shape] : methods(2)) EXPECT_TRUE(names.count("mms_2d_large/" + scheme + "/" + shape));
  for (const auto& [scheme, shape] : methods(1))  // negative weights: the loader accepts them with TLMPM only
    if (find_shape_function(shape)->tlmpm_only) {
      EXPECT_EQ(scheme, "tlmpm");
    }
  std::printf("[ measured ] %zu cases\n", cases.size());
}

}  // namespace
}  // namespace mpm::verification
