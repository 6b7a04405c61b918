// `mpm check SCENE --ranks N` (issue 18): what a distributed run would hold, printed by any build; more ranks than
// the grid has tiles, or a rank count below 1, is refused with exit status 2 and a message naming the option.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_mpm.hpp"

namespace {

namespace fs = std::filesystem;
using cli::mpm;
using cli::scratch;

const fs::path data = fs::path(MPM_SOURCE_DIR) / "tests" / "data";

// good_scene_2d.yaml: a 20 x 20 grid (tiles of 8 cells: 3 x 3), 500 particles, cubic B-splines.
TEST(CheckRanks, PrintsTheTilesRanksAndHalo) {
  const auto dir = scratch("check_ranks");
  const auto r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 3", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("ranks: 3 on 9 tiles of 8 x 8 cells (3 x 3)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ghost nodes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("halo: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("5 doubles each way"), std::string::npos) << r.out;  // USL in 2D: mass, momentum, force
  EXPECT_NE(r.out.find("at most 5 ranks get particles"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

// What `mpirun -np 3 mpm run` does today: 4 slabs of 5 cells (cubic B-splines) along y; the halo model of the two
// rank boundaries: 5 node layers (2 below, 3 above the face) x 21 nodes x 40 B, 2 messages, 1 scatter (USL), 2 bodies.
TEST(CheckRanks, PrintsTheSlabsMpirunUses) {
  const auto dir = scratch("check_ranks_slabs");
  auto r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 3", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("mpirun today: 4 slabs of 5 cells along y (at most 4 ranks)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("halo: 33.6 kB per step (1 scatter(s) x 2 bodies x 2 messages per rank boundary)"),
            std::string::npos)
      << r.out;
  r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 5", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("`mpirun -np 5` would be refused (at most 4 ranks)"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(CheckRanks, MoreRanksThanTilesIsRefused) {
  const auto dir = scratch("check_ranks_many");
  const auto r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 10", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--ranks 10: more ranks than the 9 tiles"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("good_scene_2d.yaml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at most 9 ranks"), std::string::npos) << r.err;
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
  const auto r = mpm("check " + (data / "good_scene_2d.yaml").string() + " --ranks 7", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("warning: only 5 tiles hold particles: 2 of the 7 ranks would start without any"),
            std::string::npos)
      << r.out;
  fs::remove_all(dir);
}

}  // namespace
