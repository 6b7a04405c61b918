// "Did you mean": the valid name closest to a misspelt one (mpm/core/closest_name.hpp).
#include "mpm/core/closest_name.hpp"

#include <gtest/gtest.h>

namespace mpm {
namespace {

TEST(ClosestName, EditDistance) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // the textbook case
  EXPECT_EQ(edit_distance("musl", "musl"), 0u);
  EXPECT_EQ(edit_distance("MUSL", "musl"), 0u);  // case does not count
  EXPECT_EQ(edit_distance("mulsl", "musl"), 1u);
  EXPECT_EQ(edit_distance("msul", "musl"), 1u);  // a swap of neighbours is one edit
  EXPECT_EQ(edit_distance("", "usf"), 3u);
}

TEST(ClosestName, SuggestsOnlyAClearSlip) {
  const std::vector<std::string> schemes{"usl", "musl", "usf", "tlmpm", "implicit"};
  EXPECT_EQ(closest_name("mulsl", schemes), "musl");
  EXPECT_EQ(closest_name("implicite", schemes), "implicit");
  EXPECT_EQ(closest_name("MUSL", schemes), "musl");
  EXPECT_EQ(closest_name("musl", schemes), std::nullopt);      // exact: nothing to suggest
  EXPECT_EQ(closest_name("leapfrog", schemes), std::nullopt);  // nothing within a third of its letters
  EXPECT_EQ(closest_name("us", schemes), std::nullopt);        // usl and usf equally close: no guess
  const std::vector<std::string> keys{"scheme", "shape_function", "velocity_transfer", "flip_fraction", "dt", "cfl"};
  EXPECT_EQ(closest_name("shape_functon", keys), "shape_function");
  EXPECT_EQ(closest_name("flip_fractoin", keys), "flip_fraction");
  EXPECT_EQ(did_you_mean("shape_functon", keys), " (did you mean 'shape_function'?)");
  EXPECT_EQ(did_you_mean("time_step", keys), "");
}

}  // namespace
}  // namespace mpm
