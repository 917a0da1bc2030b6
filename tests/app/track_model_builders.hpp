#pragma once
// Track files held in memory for the tests of scene::build_tracks and the viewer: straight lines
// heading east with known spacing, times and elevations, so distances, speeds and positions are
// known in advance.

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "app/track_cli_support.hpp"
#include "scene/tracks/track_files.hpp"
#include "track/model.hpp"

namespace trailray::app::test_tracks {

constexpr double kLat = 46.70, kLon = 7.85;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z
constexpr double kNoTime = std::numeric_limits<double>::quiet_NaN();

// `count` points heading east, `spacing_m` apart, `interval_s` apart in time (NaN: no times).
inline track::Segment line(int count, double spacing_m, double interval_s, double ele, double start_east_m = 0.0,
                           double t0 = kT0) {
  track::Segment s;
  for (const auto& g : trailray::test::east_line(kLat, kLon, start_east_m, count, spacing_m, t0, interval_s, ele)) {
    track::TrackPoint p;
    p.lat = g.lat;
    p.lon = g.lon;
    p.ele = g.ele;
    p.time = std::isnan(interval_s) ? track::kMissing : g.time;
    s.points.push_back(p);
  }
  return s;
}

inline track::Track track_of(std::string name, std::vector<track::Segment> segments) {
  track::Track t;
  t.name = std::move(name);
  t.segments = std::move(segments);
  return t;
}

inline scene::LoadedTrackFile file_of(std::string path, std::vector<track::Track> tracks) {
  scene::LoadedTrackFile f;
  f.path = std::move(path);
  f.file.tracks = std::move(tracks);
  return f;
}

}  // namespace trailray::app::test_tracks
