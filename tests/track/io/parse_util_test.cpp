#include "track/io/parse_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

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

TEST(ParseDouble, AgreesWithFromCharsExactly) {
  // Correctly rounded, short decimals and Garmin's 30-digit expansions alike.
  std::uint64_t x = 88172645463325252ull;
  for (int n = 0; n < 20000; ++n) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    const int int_digits = static_cast<int>(x % 4);
    const int frac_digits = static_cast<int>((x >> 8) % 32);
    std::string text = (x >> 16) % 2 ? "-" : "";
    std::uint64_t y = x;
    for (int k = 0; k < int_digits + 1; ++k, y /= 7) text += static_cast<char>('0' + y % 10);
    text += '.';
    for (int k = 0; k < frac_digits; ++k, y = y * 6364136223846793005ull + 1)
      text += static_cast<char>('0' + (y >> 33) % 10);
    const double want = std::strtod(text.c_str(), nullptr);  // correctly rounded in glibc and musl
    auto got = parse_double(text);
    ASSERT_TRUE(got) << text;
    EXPECT_EQ(*got, want) << text;
  }
  EXPECT_EQ(parse_double("47.05000556074082851409912109375"), 47.05000556074082851409912109375);
  EXPECT_EQ(parse_double("000123.4500"), 123.45);
  EXPECT_EQ(parse_double(".5"), 0.5);
  EXPECT_EQ(parse_double("5."), 5.0);
  EXPECT_FALSE(parse_double("."));
  EXPECT_FALSE(parse_double("-"));
  EXPECT_FALSE(parse_double("1.2.3"));
  EXPECT_EQ(parse_double("123456789012345678901234"), 123456789012345678901234.0);
}
