// The three classes of a point against the terrain and surface models, at and around the
// tolerances, and without an elevation (on the ground, as drawn).
#include "track/cover.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace trailray::track {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Cover, OpenCoveredAndBelowGround) {
  // A forest 20 m tall on ground at 500 m.
  EXPECT_EQ(classify_cover(501.5, 500.0, 520.0), Cover::covered);  // a hiker under the trees
  EXPECT_EQ(classify_cover(kNaN, 500.0, 520.0), Cover::covered);   // no elevation: on the ground
  EXPECT_EQ(classify_cover(560.0, 500.0, 520.0), Cover::open);     // a paraglider above the canopy
  EXPECT_EQ(classify_cover(517.5, 500.0, 520.0), Cover::open);     // within the tolerance of the top
  EXPECT_EQ(classify_cover(516.5, 500.0, 520.0), Cover::covered);
  EXPECT_EQ(classify_cover(497.5, 500.0, 520.0), Cover::covered);  // a little under: GPS noise
  EXPECT_EQ(classify_cover(496.5, 500.0, 520.0), Cover::below_ground);
  EXPECT_EQ(classify_cover(430.0, 500.0, 520.0), Cover::below_ground);  // a tunnel
}

TEST(Cover, WhereTheModelsAgreeNothingCovers) {
  EXPECT_EQ(classify_cover(kNaN, 500.0, 501.0), Cover::open);  // a meadow: 1 m of grass
  EXPECT_EQ(classify_cover(500.5, 500.0, 498.0), Cover::open);  // the surface a little below (noise)
  EXPECT_EQ(classify_cover(480.0, 500.0, 501.0), Cover::below_ground);
  CoverOptions strict;
  strict.agree_m = 0.5;
  strict.tolerance_m = 0.5;
  EXPECT_EQ(classify_cover(kNaN, 500.0, 501.0, strict), Cover::covered);
}

TEST(Cover, NoClassWithoutBothModels) {
  EXPECT_FALSE(classify_cover(500.0, kNaN, 520.0));
  EXPECT_FALSE(classify_cover(500.0, 500.0, kNaN));
  EXPECT_EQ(cover_name(Cover::open), "open");
  EXPECT_EQ(cover_name(Cover::covered), "covered");
  EXPECT_EQ(cover_name(Cover::below_ground), "below_ground");
}

}  // namespace
}  // namespace trailray::track
