#pragma once
// Track files as a scene reads them: each file whole (tracks and routes), and what the scene
// needs of the recorded points before anything is cleaned: the lowest height (the neutral
// ground's), the first timestamp and where it was (the sun's day).

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "track/io/load.hpp"
#include "track/model.hpp"

namespace trailray::scene {

struct LoadedTrackFile {
  std::string path;
  track::TrackFile file;
};

// Reads a file; its warnings go to `diagnostics`. Throws std::runtime_error naming the file and
// the position for one that cannot be read, or naming the file when it has no point to draw (no
// track or route point and no waypoint).
LoadedTrackFile read_track_file(const std::string& path, const track::ReadOptions& read, Diagnostics& diagnostics);

// Every file (the first that fails throws, as read_track_file).
std::vector<LoadedTrackFile> read_track_files(const std::vector<std::string>& paths, const track::ReadOptions& read,
                                              Diagnostics& diagnostics);

// Facts of the recorded points (track and route points of every file).
struct RecordedPoints {
  double lowest_m = std::numeric_limits<double>::quiet_NaN();  // NaN: no point has a height
  std::optional<double> first_time_s;                          // of the first timed point
  double first_time_lon_deg = 0.0;                             // where that point was
  std::optional<double> any_lon_deg;                           // of the first point at all (a waypoint's without one)

  void add(const track::TrackFile& file);
  // Where points without an elevation are placed when there is no terrain under them: the
  // lowest recorded height, else sea level.
  double lowest_or_sea_level() const { return std::isnan(lowest_m) ? 0.0 : lowest_m; }
};
RecordedPoints recorded_points(const std::vector<LoadedTrackFile>& files);

// The sun's time when none is given: local solar noon on the tracks' first day, today's noon at
// tracks without times, now without tracks.
double default_sun_time(const RecordedPoints& points);

}  // namespace trailray::scene
