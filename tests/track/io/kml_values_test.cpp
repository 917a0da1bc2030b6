// The grammars inside KML elements (kml_values.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "track/io/kml_values.hpp"

using namespace trailray::track;

TEST(KmlValues, TuplesSplitOnWhitespaceAndKeepTheirOffsets) {
  std::vector<KmlTuple> t;
  split_kml_tuples("\n  1,2,3\t4,5\r\n6 , 7 , 8   x,1 ", t);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].offset, 3u);
  EXPECT_EQ(t[0].text, "1,2,3");
  ASSERT_TRUE(t[0].value);
  EXPECT_DOUBLE_EQ(t[0].value->alt, 3.0);
  ASSERT_TRUE(t[1].value);
  EXPECT_TRUE(std::isnan(t[1].value->alt));
  EXPECT_EQ(t[2].text, "6 , 7 , 8");
  ASSERT_TRUE(t[2].value);
  EXPECT_DOUBLE_EQ(t[2].value->lat, 7.0);
  EXPECT_EQ(t[3].text, "x,1");
  EXPECT_FALSE(t[3].value);
}

TEST(KmlValues, TuplesWithTooFewOrTooManyComponentsAreUnreadable) {
  std::vector<KmlTuple> t;
  split_kml_tuples("1 1,2,3,4 1,,2 , 9 1,2,3,4,5,6,7", t);
  ASSERT_EQ(t.size(), 4u);  // the comma after "1,,2" continues it to the 9
  for (const auto& x : t) EXPECT_FALSE(x.value) << x.text;
  t.clear();
  split_kml_tuples("   \n ", t);
  EXPECT_TRUE(t.empty());
}

TEST(KmlValues, GxCoord) {
  auto c = parse_gx_coord(" -122.207881 37.371915 156.000000 ");
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->lon, -122.207881);
  EXPECT_DOUBLE_EQ(c->lat, 37.371915);
  EXPECT_DOUBLE_EQ(c->alt, 156.0);
  auto two = parse_gx_coord("1 2");
  ASSERT_TRUE(two);
  EXPECT_TRUE(std::isnan(two->alt));
  EXPECT_TRUE(parse_gx_coord("1,2,3"));  // commas tolerated
  EXPECT_FALSE(parse_gx_coord("1"));
  EXPECT_FALSE(parse_gx_coord("1 2 3 4"));
  EXPECT_FALSE(parse_gx_coord("1 nan 3"));
  EXPECT_FALSE(parse_gx_coord(""));
}

TEST(KmlValues, AltitudeModes) {
  EXPECT_EQ(parse_altitude_mode(" absolute\n"), AltitudeMode::Absolute);
  EXPECT_EQ(parse_altitude_mode("clampToGround"), AltitudeMode::ClampToGround);
  EXPECT_EQ(parse_altitude_mode("relativeToGround"), AltitudeMode::RelativeToGround);
  EXPECT_EQ(parse_altitude_mode("clampToSeaFloor"), AltitudeMode::ClampToSeaFloor);
  EXPECT_EQ(parse_altitude_mode("relativeToSeaFloor"), AltitudeMode::RelativeToSeaFloor);
  EXPECT_FALSE(parse_altitude_mode("Absolute"));  // KML values are case-sensitive
  EXPECT_FALSE(parse_altitude_mode(""));
}

TEST(KmlValues, ArrayChannelNamesAreMatchedWithoutCase) {
  EXPECT_EQ(array_channel("heartrate"), ArrayChannel::HeartRate);
  EXPECT_EQ(array_channel("heart_rate"), ArrayChannel::HeartRate);
  EXPECT_EQ(array_channel("HR"), ArrayChannel::HeartRate);
  EXPECT_EQ(array_channel("Cadence"), ArrayChannel::Cadence);
  EXPECT_EQ(array_channel("POWER"), ArrayChannel::Power);
  EXPECT_EQ(array_channel("temperature"), ArrayChannel::Temperature);
  EXPECT_EQ(array_channel("speed"), ArrayChannel::None);
  EXPECT_EQ(array_channel(""), ArrayChannel::None);
}
