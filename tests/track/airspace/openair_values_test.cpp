// OpenAir heights and coordinates: every form the shared files use, and text that must be refused.
#include <gtest/gtest.h>

#include "track/airspace/openair_values.hpp"

using namespace trailray::track::airspace;

namespace {

void expect_limit(const char* text, AltitudeReference ref, double metres) {
  SCOPED_TRACE(text);
  const auto l = parse_openair_altitude(text);
  ASSERT_TRUE(l.has_value());
  EXPECT_EQ(l->reference, ref);
  EXPECT_NEAR(l->metres, metres, 1e-9);
}

}  // namespace

TEST(OpenAirAltitude, FlightLevelsArePressureAltitudeInHundredsOfFeet) {
  expect_limit("FL 65", AltitudeReference::Std, 65 * 30.48);
  expect_limit("FL65", AltitudeReference::Std, 65 * 30.48);
  expect_limit("fl195", AltitudeReference::Std, 195 * 30.48);
  expect_limit("5000 STD", AltitudeReference::Std, 5000 * 0.3048);
}

TEST(OpenAirAltitude, FeetAndMetresAboveSeaLevel) {
  expect_limit("1000 ft", AltitudeReference::Msl, 304.8);
  expect_limit("1000ft MSL", AltitudeReference::Msl, 304.8);
  expect_limit("2500FT AMSL", AltitudeReference::Msl, 762.0);
  expect_limit("3346", AltitudeReference::Msl, 3346 * 0.3048);  // no unit: feet
  expect_limit("100m", AltitudeReference::Msl, 100.0);
  expect_limit("450 m MSL", AltitudeReference::Msl, 450.0);
  expect_limit("0", AltitudeReference::Msl, 0.0);
  expect_limit("1000 MSL", AltitudeReference::Msl, 304.8);
  expect_limit("1000m MSL", AltitudeReference::Msl, 1000.0);
}

TEST(OpenAirAltitude, AboveGround) {
  expect_limit("GND", AltitudeReference::Agl, 0.0);
  expect_limit("SFC", AltitudeReference::Agl, 0.0);
  expect_limit("100 Agl", AltitudeReference::Agl, 30.48);
  expect_limit("1000 ft AGL", AltitudeReference::Agl, 304.8);
  expect_limit("100m GND", AltitudeReference::Agl, 100.0);
  expect_limit("50 GND", AltitudeReference::Agl, 15.24);
  EXPECT_TRUE(parse_openair_altitude("SFC")->is_ground());
  EXPECT_FALSE(parse_openair_altitude("50 GND")->is_ground());
}

TEST(OpenAirAltitude, Unlimited) {
  for (const char* t : {"UNL", "UNLIM", "UNLIMITED", "unlimited"}) {
    SCOPED_TRACE(t);
    ASSERT_TRUE(parse_openair_altitude(t));
    EXPECT_EQ(parse_openair_altitude(t)->reference, AltitudeReference::Unlimited);
  }
}

TEST(OpenAirAltitude, RefusesWhatItCannotRead) {
  for (const char* t : {"", "FL", "FL 1O0", "abc", "100 parsecs", "ft", "100 ft AGL extra"}) {
    SCOPED_TRACE(t);
    EXPECT_FALSE(parse_openair_altitude(t).has_value());
  }
}

TEST(OpenAirCoordinate, DegreesMinutesSecondsAndDecimalMinutes) {
  auto p = parse_openair_coordinate("43:38:59 N 008:01:50 E");
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->lat, 43 + 38 / 60.0 + 59 / 3600.0, 1e-12);
  EXPECT_NEAR(p->lon, 8 + 1 / 60.0 + 50 / 3600.0, 1e-12);
  p = parse_openair_coordinate("01:05.5 N 000:05.5 E");
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->lat, 1 + 5.5 / 60.0, 1e-12);
  EXPECT_NEAR(p->lon, 5.5 / 60.0, 1e-12);
  p = parse_openair_coordinate("01:30:30 S 001:30:30 W");
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->lat, -(1 + 30 / 60.0 + 30 / 3600.0), 1e-12);
  EXPECT_NEAR(p->lon, -(1 + 30 / 60.0 + 30 / 3600.0), 1e-12);
  p = parse_openair_coordinate("47:30:00.5N 7:15:00E");
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->lat, 47.5 + 0.5 / 3600.0, 1e-12);
}

TEST(OpenAirCoordinate, RestAfterTheCoordinateIsReturned) {
  std::string_view rest;
  auto p = parse_openair_coordinate("43:32:48 N 008:24:29 E,43:04:57 N 007:58:39 E", &rest);
  ASSERT_TRUE(p);
  EXPECT_EQ(rest, ",43:04:57 N 007:58:39 E");
}

TEST(OpenAirCoordinate, RefusesOutOfRange) {
  for (const char* t : {"91:00:00 N 008:00:00 E", "45:61:00 N 008:00:00 E", "45:00:00 N 181:00:00 E",
                        "45:00:00 E 008:00:00 N", "45:00:00 N", "", "N E"}) {
    SCOPED_TRACE(t);
    EXPECT_FALSE(parse_openair_coordinate(t).has_value());
  }
}
