#include "scene/tracks/track_files.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scene/camera/sun_position.hpp"

namespace trailray::scene {

LoadedTrackFile read_track_file(const std::string& path, const track::ReadOptions& read, Diagnostics& diagnostics) {
  track::ReadResult result = track::load_track_file(path, read);
  for (const auto& w : result.warnings) diagnostics.warning(w.to_string());
  if (result.error) throw std::runtime_error(result.error->to_string());
  std::size_t points = 0;
  for (const auto& t : result.file.tracks) points += t.point_count();
  for (const auto& r : result.file.routes) points += r.points.size();
  // A file of waypoints alone (a GPX of wpt, a KML of Point placemarks) is drawn as its pins.
  if (points == 0 && result.file.waypoints.empty())
    throw std::runtime_error(path + ": has no track, route or waypoint to draw");
  return {path, std::move(result.file)};
}

std::vector<LoadedTrackFile> read_track_files(const std::vector<std::string>& paths, const track::ReadOptions& read,
                                              Diagnostics& diagnostics) {
  std::vector<LoadedTrackFile> files;
  files.reserve(paths.size());
  for (const std::string& path : paths) files.push_back(read_track_file(path, read, diagnostics));
  return files;
}

void RecordedPoints::add(const track::TrackFile& file) {
  const auto add_point = [&](const track::TrackPoint& p) {
    if (p.has_ele() && !(p.ele >= lowest_m)) lowest_m = p.ele;
    if (!any_lon_deg) any_lon_deg = p.lon;
    if (!first_time_s && !std::isnan(p.time)) {
      first_time_s = p.time;
      first_time_lon_deg = p.lon;
    }
  };
  for (const auto& t : file.tracks)
    for (const auto& s : t.segments)
      for (const auto& p : s.points) add_point(p);
  for (const auto& r : file.routes)
    for (const auto& p : r.points) add_point(p);
  // A file of waypoints alone (a list of stops, a KML of places) still says where on Earth it is,
  // so its sun stands at that place's noon rather than at "now", which may be night there.
  for (const auto& w : file.waypoints)
    if (!any_lon_deg) any_lon_deg = w.point.lon;
}

RecordedPoints recorded_points(const std::vector<LoadedTrackFile>& files) {
  RecordedPoints out;
  for (const LoadedTrackFile& f : files) out.add(f.file);
  return out;
}

double default_sun_time(const RecordedPoints& points) {
  if (points.first_time_s) return solar_noon_utc(*points.first_time_s, points.first_time_lon_deg);
  const double now = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  // Tracks without times (planned routes): today's noon there, not the dark of "now" at night.
  if (points.any_lon_deg) return solar_noon_utc(now, *points.any_lon_deg);
  return now;
}

}  // namespace trailray::scene
