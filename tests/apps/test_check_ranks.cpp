// `mpm check SCENE --ranks N`: what a distributed run would hold, printed by any build; more ranks than
// the grid has tiles, or a rank count below 1, is refused with exit status 2 and a message naming the option.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_mpm.hpp"

namespace {

namespace fs = std::filesystem;
using cli::mpm;
using cli::scratch;

using cli::data;

// good_scene_2d.yaml: a 20 x 20 grid, 500 particles in 2 bodies, USL with cubic B-splines: the scatter's tiles are
// 8 x 5 cells (3 x 4 of them), 7 of which hold particles. Two ranks on that square grid take two runs of slabs;
// the halo (hand count): the 5 node layers of the overlap (2 below the cut, 3 above) x 21 nodes x 40 B, each way
// once, 1 scatter, 2 bodies = 16,800 B per step.
TEST(CheckRanks, PrintsTheTilesRanksAndHalo) {
  const auto dir = scratch("check_ranks");
  const auto r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 2", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("ranks: 2 on 12 tiles of 8 x 5 cells (3 x 4), each rank a box of tiles"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("7 tiles hold particles"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("     1        202      6"), std::string::npos) << r.out;  // rank 1: the upper 2 slabs
  EXPECT_NE(r.out.find("halo: 16.8 kB per step (1 scatter(s) x 2 bodies x 40 B"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at most 7 ranks get particles"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

#ifdef MPM_WITH_IMPLICIT
// The scheme's traits, not its name, give the scatters: the implicit scheme runs in one process, so the report says so
// and counts no halo (it counted MUSL's two scatters while the implicit scheme passed for MUSL).
TEST(CheckRanks, ASchemeThatRunsInOneProcessHasNoHalo) {
  const auto dir = scratch("check_ranks_implicit");
  const auto r = mpm(
      "check " + (fs::path(MPM_SOURCE_DIR) / "examples/17_love_sulsky_bar/implicit.yaml").string() + " --ranks 2", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  // the warning on stderr, the report on stdout
  EXPECT_NE(r.err.find("warning: scheme implicit runs in one process only"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("halo: none (scheme implicit runs in one process)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("scatter(s)"), std::string::npos) << r.out;
  fs::remove_all(dir);
}
#endif

TEST(CheckRanks, MoreRanksThanTilesIsRefused) {
  const auto dir = scratch("check_ranks_many");
  const auto r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 13", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--ranks 13: more ranks than the 12 tiles of 8 x 5 cells"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("good_scene_2d.yaml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at most 12 ranks"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.find("ranks:") == std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(CheckRanks, ARankCountBelowOneIsRefused) {
  const auto dir = scratch("check_ranks_zero");
  const auto r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 0", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--ranks"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

// More ranks than tiles holding particles, but not more than tiles: accepted, with a warning.
TEST(CheckRanks, IdleRanksAreWarnedAbout) {
  const auto dir = scratch("check_ranks_idle");
  const auto r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 9", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: only 7 tiles hold particles: 2 of the 9 ranks would start without any"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("at most 7 ranks get particles"), std::string::npos) << r.out;  // the report goes on
  fs::remove_all(dir);
}

}  // namespace
