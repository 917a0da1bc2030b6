#pragma once
// Where the sun is: NOAA's solar position algorithm (the one behind NOAA's Solar Calculator and
// its spreadsheets, after Meeus, "Astronomical Algorithms"): declination and equation of time
// from the date, hour angle from the time and longitude, then azimuth and elevation at a place.
// Good to about 0.01 degrees between 1800 and 2100, far below what lighting can show.
//
// Times are seconds since 1970-01-01T00:00:00Z (UTC), as the track model stores them. The
// difference between UTC and UT1 (under a second) is ignored.

#include <glm/glm.hpp>

#include "geo/local_frame.hpp"

namespace trailray::scene {

struct SolarPosition {
  double declination_deg = 0.0;         // the sun's declination
  double equation_of_time_min = 0.0;    // apparent minus mean solar time, minutes
  double hour_angle_deg = 0.0;          // at the place, -180..180, 0 at local solar noon, positive after
  double elevation_deg = 0.0;           // geometric, above the horizontal plane
  double apparent_elevation_deg = 0.0;  // with NOAA's atmospheric refraction correction
  double azimuth_deg = 0.0;             // clockwise from north, [0, 360)
};

// The sun seen from (lat, lon) at a UTC time. The azimuth and elevation are relative to the
// ellipsoid's normal at that latitude (geodetic), as the renderer's east-north-up frames are.
SolarPosition solar_position(double unix_time_s, double lat_deg, double lon_deg);

// NOAA's refraction correction (degrees to add) for a geometric elevation: 0 above 85 degrees,
// about 0.48 degrees at the horizon.
double atmospheric_refraction_deg(double elevation_deg);

// Unit vector towards the sun in the local east-north-up frame, from its geometric elevation
// (light travels straight through the renderer's atmosphere).
geo::Enu sun_direction_enu(const SolarPosition& sun);

// Unit vector towards the sun in ECEF at a UTC time: the same for every place on Earth (the sun's
// parallax, 9 arc seconds, is ignored), so one direction lights a scene however wide. Its
// east-north-up components at any place are those of sun_direction_enu there.
glm::dvec3 sun_direction_ecef(double unix_time_s);

// The UTC time of local solar noon on the day that `unix_time_s` falls in at longitude `lon_deg`
// (the local day by mean solar time, not by UTC: a track starting at 20:00 UTC in New Zealand
// started on the next day there). The renderer's default sun for a track is this, for its first
// timestamp and longitude.
double solar_noon_utc(double unix_time_s, double lon_deg);

}  // namespace trailray::scene
