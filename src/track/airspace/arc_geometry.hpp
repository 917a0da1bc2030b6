#pragma once
// Arcs and circles of OpenAir files as boundary points on the WGS84 ellipsoid: every point is a
// geodesic (GeographicLib Direct) from the centre, so its distance from the centre is exact.
// Step: the angle whose chord leaves the true arc by at most kMaxChordErrorM (sagitta
// r(1 - cos(step/2)) <= 1 m), and never more than 2 degrees: a 5 NM circle gets 180 points, a
// 50 NM one about 360, a 100 km arc about one point every 0.5 degrees.

#include <vector>

#include "geo/web_mercator.hpp"

namespace trailray::track::airspace {

inline constexpr double kMaxChordErrorM = 1.0;
inline constexpr double kMaxArcStepDeg = 2.0;
inline constexpr double kMetresPerNauticalMile = 1852.0;

// The angular step (degrees) for an arc of `radius_m`.
double arc_step_deg(double radius_m);

// The point at `distance_m` along the geodesic leaving `from` at `azimuth_deg` (clockwise from
// north), and the inverse (distance and azimuth from `from` to `to`).
geo::LatLon geodesic_destination(geo::LatLon from, double azimuth_deg, double distance_m);
void geodesic_inverse(geo::LatLon from, geo::LatLon to, double& distance_m, double& azimuth_deg);

// Appends an arc around `centre` from azimuth `start_deg` to `end_deg`, clockwise when
// `clockwise`, with the radius going linearly from `start_radius_m` to `end_radius_m` along the
// angle (equal for DA; for DB the two given points' distances, so both lie exactly on it).
// Both end points are included.
void append_arc(std::vector<geo::LatLon>& out, geo::LatLon centre, double start_radius_m, double end_radius_m,
                double start_deg, double end_deg, bool clockwise);

// A full circle, clockwise from north, first point not repeated.
std::vector<geo::LatLon> circle_points(geo::LatLon centre, double radius_m);

// An airway (OpenAir DY points and V W= width): the ring `half_width_m` either side of the
// centreline, round at both ends, clockwise. Consecutive duplicate points are ignored; empty for
// fewer than two distinct points. Sharp bends fold the inner side over itself (as a buffer would
// not): airways bend gently.
std::vector<geo::LatLon> airway_outline(const std::vector<geo::LatLon>& centreline, double half_width_m);

}  // namespace trailray::track::airspace
