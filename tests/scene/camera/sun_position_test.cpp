#include "scene/camera/sun_position.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/camera/camera.hpp"

namespace trailray::scene {
namespace {

constexpr double kHour = 3600.0;

// Seconds since 1970-01-01T00:00Z of a UTC date and time (proleptic Gregorian; days from civil
// after H. Hinnant's algorithm).
double utc(int year, int month, int day, int hour = 0, int minute = 0, double second = 0.0) {
  year -= month <= 2 ? 1 : 0;
  const int era = (year >= 0 ? year : year - 399) / 400;
  const int yoe = year - era * 400;
  const int doy = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
  const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  const double days = static_cast<double>(era) * 146097.0 + doe - 719468.0;
  return days * 86400.0 + hour * kHour + minute * 60.0 + second;
}

TEST(SunPosition, TestDatesAreRight) {
  EXPECT_EQ(utc(1970, 1, 1), 0.0);
  EXPECT_EQ(utc(2000, 1, 1, 12), 946728000.0);
  EXPECT_EQ(utc(2024, 3, 20, 3, 6), 1710903960.0);
  EXPECT_EQ(utc(1969, 12, 31, 23), -3600.0);
}

// Equinoxes and solstices of 2024 (times from the US Naval Observatory's Earth's Seasons table):
// the declination is 0 at the equinoxes and +-the obliquity of the ecliptic (23.436 degrees in
// 2024) at the solstices.
TEST(SunPosition, DeclinationAtEquinoxesAndSolstices) {
  EXPECT_NEAR(solar_position(utc(2024, 3, 20, 3, 6), 0.0, 0.0).declination_deg, 0.0, 0.01);
  EXPECT_NEAR(solar_position(utc(2024, 9, 22, 12, 44), 0.0, 0.0).declination_deg, 0.0, 0.01);
  EXPECT_NEAR(solar_position(utc(2024, 6, 20, 20, 51), 0.0, 0.0).declination_deg, 23.436, 0.01);
  EXPECT_NEAR(solar_position(utc(2024, 12, 21, 9, 20), 0.0, 0.0).declination_deg, -23.436, 0.01);
  // Before 1970 too (negative times): the June solstice of 1969 (June 21, 19:55 UTC).
  EXPECT_NEAR(solar_position(utc(1969, 6, 21, 19, 55), 0.0, 0.0).declination_deg, 23.44, 0.01);
}

// The equation of time reaches about -14.2 minutes around 11 February and +16.4 minutes around
// 3 November (its two extremes in the almanacs), and is near 0 around 15 April, 13 June,
// 1 September and 25 December.
TEST(SunPosition, EquationOfTimeExtremesAndZeros) {
  EXPECT_NEAR(solar_position(utc(2024, 2, 11, 12), 0.0, 0.0).equation_of_time_min, -14.2, 0.15);
  EXPECT_NEAR(solar_position(utc(2024, 11, 3, 12), 0.0, 0.0).equation_of_time_min, 16.4, 0.15);
  for (const double t : {utc(2024, 4, 15, 12), utc(2024, 6, 13, 12), utc(2024, 9, 1, 12), utc(2024, 12, 25, 12)}) {
    EXPECT_NEAR(solar_position(t, 0.0, 0.0).equation_of_time_min, 0.0, 0.6);
  }
}

// At local solar noon the sun is due south in the northern mid-latitudes (due north in the
// southern ones) at elevation 90 - |lat - declination|.
TEST(SunPosition, NoonElevationAndAzimuth) {
  struct Place {
    double lat, lon;
  };
  for (const Place place : {Place{46.69, 7.86}, Place{40.0, -105.0}, Place{-43.5, 172.6}, Place{23.44, 0.0}}) {
    for (const double day : {utc(2024, 3, 20), utc(2024, 6, 21), utc(2024, 12, 21)}) {
      const double noon = solar_noon_utc(day + 12 * kHour - place.lon * 240.0, place.lon);
      const SolarPosition sun = solar_position(noon, place.lat, place.lon);
      EXPECT_NEAR(sun.hour_angle_deg, 0.0, 0.01);
      EXPECT_NEAR(sun.elevation_deg, 90.0 - std::abs(place.lat - sun.declination_deg), 0.02);
      if (place.lat - sun.declination_deg > 1.0) {
        EXPECT_NEAR(sun.azimuth_deg, 180.0, 0.05);
      }
      if (place.lat - sun.declination_deg < -1.0) {
        EXPECT_NEAR(std::remainder(sun.azimuth_deg, 360.0), 0.0, 0.05);
      }
      // Noon is the day's highest sun.
      EXPECT_LT(solar_position(noon - 900.0, place.lat, place.lon).elevation_deg, sun.elevation_deg);
      EXPECT_LT(solar_position(noon + 900.0, place.lat, place.lon).elevation_deg, sun.elevation_deg);
    }
  }
  // On the Tropic of Cancer at the June solstice the noon sun is overhead.
  const double noon = solar_noon_utc(utc(2024, 6, 20, 12), 0.0);
  EXPECT_NEAR(solar_position(noon, 23.436, 0.0).elevation_deg, 90.0, 0.05);
}

// At an equinox the sun rises due east and sets due west everywhere (its declination is 0);
// on the equator at 6:00 and 18:00 local solar time.
TEST(SunPosition, EquinoxSunriseIsDueEast) {
  for (const double lat : {0.0, 46.69, -33.9}) {
    // The geometric sunrise: bisection on the elevation between 04:00 and 08:00 solar time.
    double before = utc(2024, 3, 20, 4), after = utc(2024, 3, 20, 8);
    while (after - before > 1.0) {
      const double mid = 0.5 * (before + after);
      (solar_position(mid, lat, 0.0).elevation_deg < 0.0 ? before : after) = mid;
    }
    const SolarPosition rise = solar_position(after, lat, 0.0);
    EXPECT_NEAR(rise.azimuth_deg, 90.0, 0.2) << "latitude " << lat;
    if (lat == 0.0) {
      EXPECT_NEAR(after, utc(2024, 3, 20, 6) - rise.equation_of_time_min * 60.0, 60.0);
    }
  }
  // Sunset on the equator at the September equinox: 18:00 solar time, 17:53 UTC (the equation of
  // time is +7.4 minutes then).
  EXPECT_NEAR(solar_position(utc(2024, 9, 22, 17, 53), 0.0, 0.0).azimuth_deg, 270.0, 0.3);
  EXPECT_NEAR(solar_position(utc(2024, 9, 22, 17, 53), 0.0, 0.0).elevation_deg, 0.0, 0.3);
}

TEST(SunPosition, MorningSunIsInTheEastAfternoonSunInTheWest) {
  const double noon = solar_noon_utc(utc(2024, 7, 15, 8), 7.86);
  const SolarPosition morning = solar_position(noon - 3 * kHour, 46.69, 7.86);
  const SolarPosition afternoon = solar_position(noon + 3 * kHour, 46.69, 7.86);
  EXPECT_GT(morning.azimuth_deg, 90.0);
  EXPECT_LT(morning.azimuth_deg, 180.0);
  EXPECT_LT(morning.hour_angle_deg, 0.0);
  EXPECT_GT(afternoon.azimuth_deg, 180.0);
  EXPECT_LT(afternoon.azimuth_deg, 270.0);
  EXPECT_NEAR(afternoon.hour_angle_deg, 45.0, 0.05);  // 15 degrees an hour
  // Symmetric about noon (the declination barely moves in six hours).
  EXPECT_NEAR(morning.azimuth_deg + afternoon.azimuth_deg, 360.0, 0.1);
  EXPECT_NEAR(morning.elevation_deg, afternoon.elevation_deg, 0.05);
  // Midnight: below the horizon in July at 46 N.
  EXPECT_LT(solar_position(noon + 12 * kHour, 46.69, 7.86).elevation_deg, 0.0);
}

// NOAA's refraction: 1735 arc seconds at the horizon, 58.1 / tan(e) - ... above 5 degrees, none
// near the zenith; a standard refraction table gives 5.3 arc minutes at 10 degrees.
TEST(SunPosition, RefractionLiftsTheLowSun) {
  EXPECT_NEAR(atmospheric_refraction_deg(0.0), 1735.0 / 3600.0, 1e-12);
  EXPECT_NEAR(atmospheric_refraction_deg(10.0) * 60.0, 5.3, 0.1);
  EXPECT_NEAR(atmospheric_refraction_deg(45.0) * 3600.0, 58.1 - 0.07 + 0.000086, 1e-9);
  EXPECT_EQ(atmospheric_refraction_deg(89.0), 0.0);
  EXPECT_LT(std::abs(atmospheric_refraction_deg(-10.0)), 0.05);  // NOAA keeps a small term below the horizon
  const SolarPosition low = solar_position(utc(2024, 3, 20, 6, 5), 0.0, 0.0);
  EXPECT_NEAR(low.apparent_elevation_deg - low.elevation_deg, atmospheric_refraction_deg(low.elevation_deg), 1e-12);
}

TEST(SunPosition, EcefDirectionMatchesAzimuthAndElevationEverywhere) {
  struct Place {
    double lat, lon;
  };
  for (const double t : {utc(2024, 6, 21, 9, 30), utc(2023, 1, 5, 17), utc(2031, 10, 30, 2, 15)}) {
    const glm::dvec3 sun = sun_direction_ecef(t);
    EXPECT_NEAR(glm::length(sun), 1.0, 1e-12);
    for (const Place p : {Place{46.69, 7.86}, Place{-54.9, -67.6}, Place{89.0, 10.0}, Place{0.0, 179.9}}) {
      const geo::Enu expected = sun_direction_enu(solar_position(t, p.lat, p.lon));
      const EnuAxes enu = enu_axes_at(p.lat, p.lon);
      EXPECT_NEAR(glm::dot(sun, enu.east), expected.east, 1e-9);
      EXPECT_NEAR(glm::dot(sun, enu.north), expected.north, 1e-9);
      EXPECT_NEAR(glm::dot(sun, enu.up), expected.up, 1e-9);
    }
  }
  // Sun due south at 30 degrees: the vector points south and up.
  SolarPosition s;
  s.azimuth_deg = 180.0;
  s.elevation_deg = 30.0;
  const geo::Enu d = sun_direction_enu(s);
  EXPECT_NEAR(d.east, 0.0, 1e-12);
  EXPECT_NEAR(d.north, -std::cos(std::numbers::pi / 6.0), 1e-12);
  EXPECT_NEAR(d.up, 0.5, 1e-12);
}

// The default sun of a track: noon on the day the track was recorded, as the day is there.
TEST(SunPosition, SolarNoonIsOnTheLocalDay) {
  // Interlaken, a track starting at 06:00 UTC on 15 July 2024: noon that day, about 11:34 UTC
  // (12:00 less 31.4 minutes of longitude, plus 6 minutes of equation of time).
  const double swiss = solar_noon_utc(utc(2024, 7, 15, 6), 7.86);
  EXPECT_NEAR(swiss, utc(2024, 7, 15, 11, 34), 90.0);
  EXPECT_NEAR(solar_position(swiss, 46.69, 7.86).hour_angle_deg, 0.0, 0.005);  // within 1.2 s
  // The same day whatever the hour of the track.
  EXPECT_DOUBLE_EQ(solar_noon_utc(utc(2024, 7, 15, 0, 0, 1), 7.86), swiss);
  EXPECT_NEAR(solar_noon_utc(utc(2024, 7, 15, 21, 30), 7.86), swiss, 1e-6);
  // New Zealand: 20:00 UTC on 1 June is the morning of 2 June there; noon is 2 June about
  // 00:38 UTC (12:00 less 11 h 20 min of longitude less 2 minutes of equation of time).
  const double nz = solar_noon_utc(utc(2024, 6, 1, 20), 170.0);
  EXPECT_GT(nz, utc(2024, 6, 2, 0, 30));
  EXPECT_LT(nz, utc(2024, 6, 2, 0, 45));
  EXPECT_NEAR(solar_position(nz, -43.5, 170.0).hour_angle_deg, 0.0, 0.005);
  // West of Greenwich: 03:00 UTC on 10 March in Colorado is still 9 March there; noon is about
  // 19:10 UTC (12:00 plus 7 hours of longitude plus 10.5 minutes of equation of time).
  const double colorado = solar_noon_utc(utc(2024, 3, 10, 3), -105.0);
  EXPECT_NEAR(colorado, utc(2024, 3, 9, 19, 10, 30), 60.0);
}

}  // namespace
}  // namespace trailray::scene
