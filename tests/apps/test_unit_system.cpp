// A scene in a unit system (`units:`, core/units.hpp) runs as the same scene in SI: the Taylor anvil of
// examples/05 written in mm-ms-g (musl_mm_ms_g.yaml) writes the same bits as musl.yaml, field by field and row by
// row (`mpm diff --tolerance 0`), and `mpm check` names the system.
#include <gtest/gtest.h>

#include "run_mpm.hpp"

namespace {

using cli::fs::path;

TEST(UnitSystem, TaylorAnvilInMmMsGWritesTheSameBitsAsInSi) {
  const auto dir = cli::scratch("unit_system");
  const path examples = path(MPM_SOURCE_DIR) / "examples" / "05_taylor_anvil";
  for (const char* scene : {"musl", "musl_mm_ms_g"}) {
    const auto r = cli::mpm(
        "run " + (examples / (std::string(scene) + ".yaml")).string() + " --steps 20 -o " + (dir / scene).string(),
        dir);
    ASSERT_EQ(r.status, 0) << scene << ": " << r.err;
  }
  const auto diff = cli::mpm("diff " + (dir / "musl").string() + " " + (dir / "musl_mm_ms_g").string(), dir);
  EXPECT_EQ(diff.status, 0) << diff.out << diff.err;
  EXPECT_NE(diff.out.find("equal: 55 fields"), std::string::npos) << diff.out;
  const auto check = cli::mpm("check " + (examples / "musl_mm_ms_g.yaml").string(), dir);
  ASSERT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.out.find("units: the scene's numbers are in mm-ms-g"), std::string::npos) << check.out;
  cli::fs::remove_all(dir);
}

}  // namespace
