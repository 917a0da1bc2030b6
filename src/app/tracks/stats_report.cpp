#include "app/tracks/stats_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "app/tracks/places_report.hpp"
#include "track/clean.hpp"
#include "track/io/load.hpp"

namespace trailray::app {
namespace {

nlohmann::json opt(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::string plural(std::size_t n, const char* word) { return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s"); }

std::string hms(const std::optional<double>& s) {
  if (!s) return "-";
  auto t = static_cast<long long>(std::llround(*s));
  return fmt::format("{}:{:02}:{:02}", t / 3600, (t / 60) % 60, t % 60);
}

std::string num(const std::optional<double>& v, int decimals, const char* prefix = "") {
  if (!v) return "-";
  return fmt::format("{}{:.{}f}", prefix, *v, decimals);
}

}  // namespace

FileStats compute_file_stats(const std::string& path, const track::ReadOptions& read,
                             const track::AnalysisOptions& analysis,
                             const std::vector<track::places::Place>* places, const StatsPhotos* photos) {
  FileStats f;
  f.with_places = places != nullptr;
  f.path = path;
  track::ReadResult r = track::load_track_file(path, read);
  for (const auto& w : r.warnings) f.warnings.push_back(w.to_string());
  if (!r.ok()) {
    f.error = r.error->to_string();
    return f;
  }
  f.format = r.file.format;
  f.routes = r.file.routes.size();
  f.waypoints = r.file.waypoints.size();
  std::vector<track::Track> cleaned;  // --photos only
  for (std::size_t i = 0; i < r.file.tracks.size(); ++i) {
    const track::Track& t = r.file.tracks[i];
    if (photos != nullptr) {
      // --photos: the cleaned track kept to place the photos on, so their distances are the table's.
      track::CleanReport cleaning;
      cleaned.push_back(track::clean_track(t, analysis.clean, cleaning));
      const track::TrackMetrics metrics = track::compute_metrics(cleaned.back(), analysis.metrics);
      f.tracks.push_back(track::summarize_cleaned_track(t, cleaned.back(), cleaning, metrics, analysis));
    } else {
      f.tracks.push_back(track::summarize_track(t, analysis));
    }
    if (places != nullptr) f.places_visited.push_back(track::places::places_visited(t, *places));
    const track::CleanReport& c = f.tracks.back().cleaning;
    const std::string display = path == "-" ? "<stdin>" : path;
    const std::string which = t.name.empty() ? fmt::format("track {}", i + 1) : fmt::format("track '{}'", t.name);
    auto warn = [&](std::size_t n, const char* what) {
      if (n > 0) f.warnings.push_back(fmt::format("{}: {}: {} {}", display, which, plural(n, "point"), what));
    };
    warn(c.duplicate_points, "repeating the previous fix exactly (time and place) dropped by cleaning");
    warn(c.spread_time, "sharing a timestamp with the point before got evenly spread sub-second times");
    warn(c.non_increasing_time, "with a backward timestamp dropped by cleaning");
    warn(c.frozen_time, "with a placeholder timestamp (the clock never advances) kept without time");
    warn(c.invalid_coordinates, "with invalid coordinates dropped by cleaning");
  }
  if (photos != nullptr) {
    std::vector<const track::Track*> on;
    for (const track::Track& t : cleaned) on.push_back(&t);
    f.photos = track::place_photos(photos->photos, on, photos->options);
    f.photo_count = photos->photos.size();
    for (const auto& w : f.photos->warnings) f.warnings.push_back(w.to_string());
  }
  return f;
}

nlohmann::json statistics_json(const track::Statistics& s) {
  nlohmann::json j;
  j["points"] = s.points;
  j["segments"] = s.segments;
  j["distance_2d_m"] = s.distance_2d_m;
  j["distance_3d_m"] = s.distance_3d_m;
  j["duration_s"] = opt(s.duration_s);
  j["elapsed_s"] = opt(s.elapsed_s);
  j["moving_time_s"] = opt(s.moving_time_s);
  j["elevation_gain_m"] = opt(s.elevation_gain_m);
  j["elevation_loss_m"] = opt(s.elevation_loss_m);
  j["min_elevation_m"] = opt(s.min_elevation_m);
  j["max_elevation_m"] = opt(s.max_elevation_m);
  j["max_speed_kmh"] = opt(s.max_speed_kmh);
  j["avg_speed_kmh"] = opt(s.avg_speed_kmh);
  j["max_climb_ms"] = opt(s.max_climb_ms);
  j["max_sink_ms"] = opt(s.max_sink_ms);
  if (s.bbox && !s.bbox->empty())
    j["bbox"] = {s.bbox->min_lat, s.bbox->min_lon, s.bbox->max_lat, s.bbox->max_lon};
  else
    j["bbox"] = nullptr;
  return j;
}

nlohmann::json file_stats_json(const FileStats& f) {
  nlohmann::json j;
  j["path"] = f.path;
  j["format"] = f.format ? nlohmann::json(track::format_name(*f.format)) : nlohmann::json(nullptr);
  nlohmann::json tracks = nlohmann::json::array();
  for (std::size_t i = 0; i < f.tracks.size(); ++i) {
    const auto& t = f.tracks[i];
    nlohmann::json segments = nlohmann::json::array();
    for (const auto& s : t.segments)
      segments.push_back({{"raw", statistics_json(s.raw)}, {"clean", statistics_json(s.clean)}});
    tracks.push_back({{"name", t.name},
                      {"raw", statistics_json(t.raw)},
                      {"clean", statistics_json(t.clean)},
                      {"segments", std::move(segments)}});
    if (f.with_places && i < f.places_visited.size()) {
      tracks.back()["summits"] = place_visits_json(f.places_visited[i].summits);
      tracks.back()["huts"] = place_visits_json(f.places_visited[i].huts);
    }
  }
  j["tracks"] = std::move(tracks);
  if (f.photos) j["photos"] = placed_photos_json(*f.photos);
  j["routes"] = f.routes;
  j["waypoints"] = f.waypoints;
  j["warnings"] = f.warnings;
  if (f.error) j["error"] = *f.error;
  return j;
}

std::string file_stats_table(const FileStats& f) {
  std::string out =
      fmt::format("{} ({}, {}, {}, {})\n", f.path, f.format ? track::format_name(*f.format) : "?",
                  plural(f.tracks.size(), "track"), plural(f.routes, "route"), plural(f.waypoints, "waypoint"));
  if (f.tracks.empty()) return out;
  out += fmt::format("  {:<32} {:>7} {:>4} {:>10} {:>9} {:>9} {:>7} {:>7} {:>7} {:>7} {:>6} {:>6}\n", "track", "points",
                     "segs", "distance", "duration", "moving", "gain", "loss", "min", "max", "avg", "max");
  out += fmt::format("  {:<32} {:>7} {:>4} {:>10} {:>9} {:>9} {:>7} {:>7} {:>7} {:>7} {:>6} {:>6}\n", "", "", "", "km",
                     "h:mm:ss", "h:mm:ss", "m", "m", "m", "m", "km/h", "km/h");
  for (std::size_t i = 0; i < f.tracks.size(); ++i) {
    const auto& t = f.tracks[i];
    const auto& s = t.clean;
    std::string name = t.name.empty() ? fmt::format("#{}", i + 1) : t.name;
    if (name.size() > 32) {
      std::size_t cut = 31;
      while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
      name = name.substr(0, cut) + "~";
    }
    out += fmt::format("  {:<32} {:>7} {:>4} {:>10.3f} {:>9} {:>9} {:>7} {:>7} {:>7} {:>7} {:>6} {:>6}\n", name,
                       s.points, s.segments, s.distance_2d_m / 1000.0, hms(s.duration_s), hms(s.moving_time_s),
                       num(s.elevation_gain_m, 0, "+"), num(s.elevation_loss_m, 0, "-"), num(s.min_elevation_m, 0),
                       num(s.max_elevation_m, 0), num(s.avg_speed_kmh, 1), num(s.max_speed_kmh, 1));
  }
  // --places: the summits and huts of each track, under the table.
  for (std::size_t i = 0; i < f.places_visited.size() && i < f.tracks.size(); ++i)
    out += places_visited_lines(f.tracks[i].name.empty() ? fmt::format("#{}", i + 1) : f.tracks[i].name,
                                f.places_visited[i]);
  // --photos: where they were taken, under the table.
  if (f.photos) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < f.tracks.size(); ++i)
      names.push_back(f.tracks[i].name.empty() ? fmt::format("#{}", i + 1) : f.tracks[i].name);
    out += placed_photos_lines(*f.photos, f.photo_count, names);
  }
  // The figures are the cleaned tracks': say so, and how many points the files recorded.
  std::size_t recorded = 0, kept = 0;
  for (const auto& t : f.tracks) {
    recorded += t.raw.points;
    kept += t.clean.points;
  }
  out += fmt::format("  (of the cleaned tracks: {} of {} recorded points kept; --json has the figures as recorded too)\n",
                     kept, recorded);
  return out;
}

}  // namespace trailray::app
