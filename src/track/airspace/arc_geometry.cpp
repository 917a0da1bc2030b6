#include "track/airspace/arc_geometry.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trailray::track::airspace {

double arc_step_deg(double radius_m) {
  if (!(radius_m > kMaxChordErrorM)) return kMaxArcStepDeg;
  // sagitta r (1 - cos(step/2)) <= e  <=>  step <= 2 acos(1 - e/r)
  const double step = 2.0 * std::acos(1.0 - kMaxChordErrorM / radius_m) * 180.0 / std::numbers::pi;
  return std::clamp(step, 0.01, kMaxArcStepDeg);  // the floor keeps absurd radii finite
}

geo::LatLon geodesic_destination(geo::LatLon from, double azimuth_deg, double distance_m) {
  geo::LatLon out;
  GeographicLib::Geodesic::WGS84().Direct(from.lat, from.lon, azimuth_deg, distance_m, out.lat, out.lon);
  return out;
}

void geodesic_inverse(geo::LatLon from, geo::LatLon to, double& distance_m, double& azimuth_deg) {
  double azi2 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(from.lat, from.lon, to.lat, to.lon, distance_m, azimuth_deg, azi2);
}

void append_arc(std::vector<geo::LatLon>& out, geo::LatLon centre, double start_radius_m, double end_radius_m,
                double start_deg, double end_deg, bool clockwise) {
  // The swept angle, in the arc's direction, in [0, 360); equal start and end make a full circle.
  double sweep = clockwise ? end_deg - start_deg : start_deg - end_deg;
  sweep = std::fmod(sweep, 360.0);
  if (sweep < 0.0) sweep += 360.0;
  if (sweep < 1e-9) sweep = 360.0;
  const double step = arc_step_deg(std::max(start_radius_m, end_radius_m));
  const int steps = std::max(1, static_cast<int>(std::ceil(sweep / step - 1e-9)));
  const double sign = clockwise ? 1.0 : -1.0;
  for (int i = 0; i <= steps; ++i) {
    const double f = static_cast<double>(i) / steps;
    const double radius = start_radius_m + (end_radius_m - start_radius_m) * f;
    out.push_back(geodesic_destination(centre, start_deg + sign * sweep * f, radius));
  }
}

std::vector<geo::LatLon> circle_points(geo::LatLon centre, double radius_m) {
  std::vector<geo::LatLon> out;
  append_arc(out, centre, radius_m, radius_m, 0.0, 360.0, true);
  out.pop_back();  // the same point as the first
  return out;
}

std::vector<geo::LatLon> airway_outline(const std::vector<geo::LatLon>& centreline, double half_width_m) {
  std::vector<geo::LatLon> line;
  for (const geo::LatLon& p : centreline)
    if (line.empty() || p.lat != line.back().lat || p.lon != line.back().lon) line.push_back(p);
  std::vector<geo::LatLon> out;
  if (line.size() < 2 || !(half_width_m > 0.0)) return out;
  // The azimuth of each leg where it leaves its first point, and where it arrives at its last.
  std::vector<double> leave(line.size() - 1), arrive(line.size() - 1);
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    double d = 0.0;
    geodesic_inverse(line[i], line[i + 1], d, leave[i]);
    double back = 0.0;
    geodesic_inverse(line[i + 1], line[i], d, back);
    arrive[i] = back + 180.0;
  }
  // Left side forward, the round end, right side back, the round start: clockwise.
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    out.push_back(geodesic_destination(line[i], leave[i] - 90.0, half_width_m));
    out.push_back(geodesic_destination(line[i + 1], arrive[i] - 90.0, half_width_m));
  }
  const double end = arrive.back();
  append_arc(out, line.back(), half_width_m, half_width_m, end - 90.0, end + 90.0, true);
  for (std::size_t i = line.size() - 1; i-- > 0;) {
    out.push_back(geodesic_destination(line[i + 1], arrive[i] + 90.0, half_width_m));
    out.push_back(geodesic_destination(line[i], leave[i] + 90.0, half_width_m));
  }
  const double start = leave.front();
  append_arc(out, line.front(), half_width_m, half_width_m, start + 90.0, start + 270.0, true);
  out.pop_back();  // the first point again
  return out;
}

}  // namespace trailray::track::airspace
