#include "track/io/parse_util.hpp"

#include <gtest/gtest.h>

using namespace trailray::track;

TEST(ParseDouble, AcceptsDecimalForms) {
  EXPECT_EQ(parse_double("12"), 12.0);
  EXPECT_EQ(parse_double(" -3.5\n"), -3.5);
  EXPECT_EQ(parse_double("+1e3"), 1000.0);
}

TEST(ParseDouble, RejectsGarbageAndNonFinite) {
  EXPECT_FALSE(parse_double(""));
  EXPECT_FALSE(parse_double("abc"));
  EXPECT_FALSE(parse_double("12abc"));
  EXPECT_FALSE(parse_double("nan"));
  EXPECT_FALSE(parse_double("inf"));
  EXPECT_FALSE(parse_double("1e999"));
}

TEST(ParseIso8601, UtcWithAndWithoutFraction) {
  EXPECT_EQ(parse_iso8601("1970-01-01T00:00:00Z"), 0.0);
  EXPECT_EQ(parse_iso8601("2023-05-06T09:45:34Z"), 1683366334.0);
  EXPECT_NEAR(*parse_iso8601("2023-05-06T09:45:34.250Z"), 1683366334.25, 1e-6);
}

TEST(ParseIso8601, OffsetsAreConvertedToUtc) {
  EXPECT_EQ(parse_iso8601("2023-05-06T11:45:34+02:00"), 1683366334.0);
  EXPECT_EQ(parse_iso8601("2023-05-06T04:15:34-0530"), 1683366334.0);
}

TEST(ParseIso8601, NoZoneIsUtcAndSpaceSeparatorIsAccepted) {
  EXPECT_EQ(parse_iso8601("2023-05-06 09:45:34"), 1683366334.0);
  EXPECT_EQ(parse_iso8601("2023-05-06T09:45:34"), 1683366334.0);
}

TEST(ParseIso8601, RejectsMalformed) {
  EXPECT_FALSE(parse_iso8601("2023-13-06T09:45:34Z"));
  EXPECT_FALSE(parse_iso8601("2023-05-06T25:00:00Z"));
  EXPECT_FALSE(parse_iso8601("yesterday"));
  EXPECT_FALSE(parse_iso8601("2023-05-06T09:45:34Zjunk"));
}

TEST(DaysFromCivil, KnownDates) {
  EXPECT_EQ(days_from_civil(1970, 1, 1), 0);
  EXPECT_EQ(days_from_civil(2000, 3, 1), 11017);
  EXPECT_EQ(days_from_civil(1969, 12, 31), -1);
}
