#pragma once
// Synthetic tracks with known geometry for the metrics and statistics tests.

#include <GeographicLib/Geodesic.hpp>

#include <utility>
#include <vector>

#include "track/model.hpp"

namespace trailray::track::test {

constexpr double kLat0 = 46.5;
constexpr double kLon0 = 7.5;

// A point `s` metres north of (kLat0, kLon0) along the meridian.
inline TrackPoint north(double s, double ele = kMissing, double time = kMissing) {
  TrackPoint p;
  GeographicLib::Geodesic::WGS84().Direct(kLat0, kLon0, 0.0, s, p.lat, p.lon);
  p.ele = ele;
  p.time = time;
  return p;
}

inline Track one_segment(std::vector<TrackPoint> pts) {
  Track t;
  t.segments.push_back(Segment{std::move(pts)});
  return t;
}

}  // namespace trailray::track::test
