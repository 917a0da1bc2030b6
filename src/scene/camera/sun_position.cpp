#include "scene/camera/sun_position.hpp"

#include <cmath>
#include <numbers>

namespace trailray::scene {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr double kSecondsPerDay = 86400.0;
constexpr double kUnixEpochJulianDay = 2440587.5;  // 1970-01-01T00:00Z
constexpr double kJ2000JulianDay = 2451545.0;      // 2000-01-01T12:00

double sin_deg(double d) { return std::sin(d * kRadPerDeg); }
double cos_deg(double d) { return std::cos(d * kRadPerDeg); }

// An angle in degrees brought into [-180, 180).
double wrapped_180(double deg) {
  double d = std::fmod(deg + 180.0, 360.0);
  if (d < 0.0) d += 360.0;
  return d - 180.0;
}

// What depends on the date alone (it barely changes within a day).
struct SunOrbit {
  double declination_deg;
  double equation_of_time_min;
};

// NOAA's spreadsheet, column by column (names as there).
SunOrbit sun_orbit(double unix_time_s) {
  const double julian_day = unix_time_s / kSecondsPerDay + kUnixEpochJulianDay;
  const double t = (julian_day - kJ2000JulianDay) / 36525.0;  // Julian centuries since J2000
  const double mean_long = std::fmod(280.46646 + t * (36000.76983 + t * 0.0003032), 360.0);
  const double mean_anom = 357.52911 + t * (35999.05029 - 0.0001537 * t);
  const double eccentricity = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
  const double eq_of_centre = sin_deg(mean_anom) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
                              sin_deg(2.0 * mean_anom) * (0.019993 - 0.000101 * t) +
                              sin_deg(3.0 * mean_anom) * 0.000289;
  const double true_long = mean_long + eq_of_centre;
  const double omega = 125.04 - 1934.136 * t;  // the Moon's ascending node: nutation and aberration terms
  const double apparent_long = true_long - 0.00569 - 0.00478 * sin_deg(omega);
  const double mean_obliquity = 23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
  const double obliquity = mean_obliquity + 0.00256 * cos_deg(omega);

  SunOrbit orbit{};
  orbit.declination_deg = std::asin(sin_deg(obliquity) * sin_deg(apparent_long)) * kDegPerRad;
  const double tan_half = std::tan(0.5 * obliquity * kRadPerDeg);
  const double y = tan_half * tan_half;
  const double e = eccentricity;
  orbit.equation_of_time_min = 4.0 * kDegPerRad *
                               (y * sin_deg(2.0 * mean_long) - 2.0 * e * sin_deg(mean_anom) +
                                4.0 * e * y * sin_deg(mean_anom) * cos_deg(2.0 * mean_long) -
                                0.5 * y * y * sin_deg(4.0 * mean_long) - 1.25 * e * e * sin_deg(2.0 * mean_anom));
  return orbit;
}

double minutes_past_utc_midnight(double unix_time_s) {
  double s = std::fmod(unix_time_s, kSecondsPerDay);
  if (s < 0.0) s += kSecondsPerDay;
  return s / 60.0;
}

// The hour angle at longitude 0, NOAA's way (0 at solar noon, positive in the afternoon):
// true solar time in minutes / 4 - 180. At longitude lon the hour angle is this + lon.
double hour_angle_at_greenwich_deg(double unix_time_s, const SunOrbit& orbit) {
  return wrapped_180(minutes_past_utc_midnight(unix_time_s) / 4.0 + orbit.equation_of_time_min / 4.0 - 180.0);
}

}  // namespace

double atmospheric_refraction_deg(double elevation_deg) {
  const double e = elevation_deg;
  if (!(e <= 85.0)) return 0.0;
  const double te = std::tan(e * kRadPerDeg);
  double arc_seconds = 0.0;
  if (e > 5.0) {
    arc_seconds = 58.1 / te - 0.07 / (te * te * te) + 0.000086 / std::pow(te, 5.0);
  } else if (e > -0.575) {
    arc_seconds = 1735.0 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
  } else {
    arc_seconds = -20.772 / te;
  }
  return arc_seconds / 3600.0;
}

SolarPosition solar_position(double unix_time_s, double lat_deg, double lon_deg) {
  const SunOrbit orbit = sun_orbit(unix_time_s);
  SolarPosition sun;
  sun.declination_deg = orbit.declination_deg;
  sun.equation_of_time_min = orbit.equation_of_time_min;
  sun.hour_angle_deg = wrapped_180(hour_angle_at_greenwich_deg(unix_time_s, orbit) + lon_deg);

  // The sun's direction in the east-north-up frame at the place (see sun_direction_ecef: the
  // same vector, rotated), rather than NOAA's acos forms, which lose precision near the zenith
  // and are undefined at the poles.
  const double phi = lat_deg * kRadPerDeg, delta = sun.declination_deg * kRadPerDeg;
  const double h = sun.hour_angle_deg * kRadPerDeg;
  const double east = -std::cos(delta) * std::sin(h);
  const double north = std::cos(phi) * std::sin(delta) - std::sin(phi) * std::cos(delta) * std::cos(h);
  const double up = std::sin(phi) * std::sin(delta) + std::cos(phi) * std::cos(delta) * std::cos(h);
  sun.elevation_deg = std::atan2(up, std::hypot(east, north)) * kDegPerRad;
  sun.apparent_elevation_deg = sun.elevation_deg + atmospheric_refraction_deg(sun.elevation_deg);
  double azimuth = std::atan2(east, north) * kDegPerRad;
  if (azimuth < 0.0) azimuth += 360.0;
  sun.azimuth_deg = azimuth >= 360.0 ? 0.0 : azimuth;
  return sun;
}

geo::Enu sun_direction_enu(const SolarPosition& sun) {
  const double el = sun.elevation_deg * kRadPerDeg, az = sun.azimuth_deg * kRadPerDeg;
  return geo::Enu{std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
}

glm::dvec3 sun_direction_ecef(double unix_time_s) {
  // The sun stands over the meridian where the hour angle is 0, at latitude = declination.
  const SunOrbit orbit = sun_orbit(unix_time_s);
  const double subsolar_lon = -hour_angle_at_greenwich_deg(unix_time_s, orbit) * kRadPerDeg;
  const double delta = orbit.declination_deg * kRadPerDeg;
  return {std::cos(delta) * std::cos(subsolar_lon), std::cos(delta) * std::sin(subsolar_lon), std::sin(delta)};
}

double solar_noon_utc(double unix_time_s, double lon_deg) {
  // The local day by mean solar time (UTC shifted by 4 minutes a degree of longitude).
  const double local_day_start = std::floor((unix_time_s + lon_deg * 240.0) / kSecondsPerDay) * kSecondsPerDay;
  const double mean_noon = local_day_start + 0.5 * kSecondsPerDay - lon_deg * 240.0;
  // Noon comes earlier by the equation of time, which moves by under 30 s a day: evaluated at
  // the mean noon and once more at the estimate, it is exact to well under a second.
  double noon = mean_noon;
  for (int i = 0; i < 2; ++i) noon = mean_noon - sun_orbit(noon).equation_of_time_min * 60.0;
  return noon;
}

}  // namespace trailray::scene
