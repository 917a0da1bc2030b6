// JSON shape of `trailray flight --json` (also in its --help). Times are ISO 8601 UTC; NaN
// figures (no altitude, a glide that lost no height) are null.
//   {"files": [{"path", "format", "warnings": [...], "error" (only when unreadable),
//     "tracks": [{"name", "index", "points", "points_used", "has_altitude", "fix_interval_s" (median),
//       "note" (why there is no flight, or null),
//       "flights": [{"takeoff": PLACE, "landing": PLACE, "duration_s", "distance_m",
//         "max_alt_m", "min_alt_m", "circling_share", "circling_s", "circling_left_s",
//         "circling_right_s", "gliding_s", "unknown_s", "thermal_count", "mean_thermal_climb_ms",
//         "best_climb_ms", "best_glide" (index into glides or null), "longest_glide",
//         "phases": [{"phase": ground|circling-left|circling-right|gliding|unknown,
//                     "start", "end" (times), "duration_s", "start_point", "end_point"}],
//         "thermals": [{"start": PLACE, "end": PLACE, "direction": left|right, "duration_s",
//                       "entry_alt_m", "exit_alt_m", "gain_m", "mean_climb_ms", "best_climb_ms",
//                       "turns", "drift_m", "drift_to_deg", "wind_speed_ms", "wind_from_deg",
//                       "wind_from_centres", "phase"}],
//         "glides": [{"start": PLACE, "end": PLACE, "duration_s", "distance_m", "height_lost_m",
//                     "glide_ratio", "mean_speed_ms", "phase"}],
//         "wind": [{"floor_m", "ceiling_m", "speed_ms", "from_deg", "thermals"}]}]}]}],
//    "settings": {the analysis constants: windows, thresholds, minimum durations}}
//   PLACE = {"time", "lat", "lon", "alt_m", "point"} (point: index among the track's points).
#include "app/flight/flight_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "track/io/load.hpp"
#include "track/io/text_output.hpp"

namespace trailray::app {
namespace {

namespace fl = track::flight;

nlohmann::json num(double v, double scale = 1000.0) {
  if (!std::isfinite(v)) return nullptr;
  return std::round(v * scale) / scale;
}

nlohmann::json place_json(const fl::Place& p) {
  return {{"time", track::format_iso_time(p.time)},
          {"lat", num(p.lat, 1e7)},
          {"lon", num(p.lon, 1e7)},
          {"alt_m", num(p.alt, 10)},
          {"point", p.point}};
}

nlohmann::json index_or_null(int i) { return i < 0 ? nlohmann::json(nullptr) : nlohmann::json(i); }

nlohmann::json flight_json(const fl::Flight& f) {
  nlohmann::json j;
  j["takeoff"] = place_json(f.takeoff);
  j["landing"] = place_json(f.landing);
  j["duration_s"] = num(f.duration_s);
  j["distance_m"] = num(f.distance_m, 10);
  j["max_alt_m"] = num(f.max_alt_m, 10);
  j["min_alt_m"] = num(f.min_alt_m, 10);
  j["circling_share"] = num(f.circling_share, 1e4);
  j["circling_s"] = num(f.circling_s);
  j["circling_left_s"] = num(f.circling_left_s);
  j["circling_right_s"] = num(f.circling_right_s);
  j["gliding_s"] = num(f.gliding_s);
  j["unknown_s"] = num(f.unknown_s);
  j["thermal_count"] = f.thermals.size();
  j["mean_thermal_climb_ms"] = num(f.mean_thermal_climb_ms, 100);
  j["best_climb_ms"] = num(f.best_climb_ms, 100);
  j["best_glide"] = index_or_null(f.best_glide);
  j["longest_glide"] = index_or_null(f.longest_glide);
  j["phases"] = nlohmann::json::array();
  for (const fl::PhaseSpan& p : f.phases)
    j["phases"].push_back({{"phase", fl::phase_name(p.phase)},
                           {"start", track::format_iso_time(p.start.time)},
                           {"end", track::format_iso_time(p.end.time)},
                           {"duration_s", num(p.duration_s())},
                           {"start_point", p.start.point},
                           {"end_point", p.end.point}});
  j["thermals"] = nlohmann::json::array();
  for (const fl::Thermal& t : f.thermals)
    j["thermals"].push_back({{"start", place_json(t.start)},
                             {"end", place_json(t.end)},
                             {"direction", t.direction == fl::Phase::CirclingLeft ? "left" : "right"},
                             {"duration_s", num(t.duration_s)},
                             {"entry_alt_m", num(t.start.alt, 10)},
                             {"exit_alt_m", num(t.end.alt, 10)},
                             {"gain_m", num(t.gain_m, 10)},
                             {"mean_climb_ms", num(t.mean_climb_ms, 100)},
                             {"best_climb_ms", num(t.best_climb_ms, 100)},
                             {"turns", num(t.turns, 10)},
                             {"drift_m", num(t.drift_m, 10)},
                             {"drift_to_deg", num(t.drift_to_deg, 10)},
                             {"wind_speed_ms", num(t.wind_speed_ms, 100)},
                             {"wind_from_deg", num(t.wind_from_deg, 10)},
                             {"wind_from_centres", t.wind_from_centres},
                             {"phase", t.phase}});
  j["glides"] = nlohmann::json::array();
  for (const fl::Glide& g : f.glides)
    j["glides"].push_back({{"start", place_json(g.start)},
                           {"end", place_json(g.end)},
                           {"duration_s", num(g.duration_s)},
                           {"distance_m", num(g.distance_m, 10)},
                           {"height_lost_m", num(g.height_lost_m, 10)},
                           {"glide_ratio", num(g.glide_ratio, 10)},
                           {"mean_speed_ms", num(g.mean_speed_ms, 100)},
                           {"phase", g.phase}});
  j["wind"] = nlohmann::json::array();
  for (const fl::WindBand& w : f.wind)
    j["wind"].push_back({{"floor_m", w.floor_m},
                         {"ceiling_m", w.ceiling_m},
                         {"speed_ms", num(w.speed_ms, 100)},
                         {"from_deg", num(w.from_deg, 10)},
                         {"thermals", w.thermals}});
  return j;
}

}  // namespace

FileFlights analyse_flight_file(const std::string& path, const track::ReadOptions& read,
                                const track::flight::FlightOptions& options, const FlightTask* task) {
  FileFlights f;
  f.path = path;
  const track::ReadResult r = track::load_track_file(path, read);
  for (const auto& w : r.warnings) f.warnings.push_back(w.to_string());
  if (r.error) {
    f.error = r.error->to_string();
    return f;
  }
  f.format = r.file.format;
  for (std::size_t i = 0; i < r.file.tracks.size(); ++i)
    f.tracks.push_back({r.file.tracks[i].name, i, fl::analyse_flights(r.file.tracks[i], options),
                        median_fix_interval(r.file.tracks[i])});
  if (task != nullptr) f.task = task_flight_report(path, r.file, task->task, task->distances, task->tolerance);
  return f;
}

double median_fix_interval(const track::Track& t) {
  std::vector<double> steps;
  double last = track::kMissing;
  for (const track::Segment& seg : t.segments)
    for (const track::TrackPoint& p : seg.points) {
      if (!p.has_time()) continue;
      if (p.time > last) steps.push_back(p.time - last);
      if (!(p.time <= last)) last = p.time;
    }
  if (steps.empty()) return 0.0;
  auto mid = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
  std::nth_element(steps.begin(), mid, steps.end());
  return *mid;
}

std::string no_flight_reason(const fl::FlightAnalysis& a) {
  if (!a.flights.empty()) return {};
  if (a.points == 0) return "no points";
  if (a.points_used == 0) return "no times: flight analysis needs timed points";
  if (!a.has_altitude) return "no elevation: take-off and landing are found from the climb";
  if (a.points_used < 2) return "a single timed point";
  return "no flight found (never fast and climbing or sinking for a minute: ground time or a walk)";
}

nlohmann::json flight_file_json(const FileFlights& f, const FlightTask* task) {
  nlohmann::json j;
  j["path"] = f.path;  // as given, like `stats`
  j["format"] = f.format ? nlohmann::json(track::format_name(*f.format)) : nlohmann::json(nullptr);
  j["warnings"] = f.warnings;
  if (f.error) j["error"] = *f.error;
  j["tracks"] = nlohmann::json::array();
  for (const TrackFlights& t : f.tracks) {
    nlohmann::json tj;
    tj["name"] = track::valid_utf8(t.name);
    tj["index"] = t.index;
    tj["points"] = t.analysis.points;
    tj["points_used"] = t.analysis.points_used;
    tj["has_altitude"] = t.analysis.has_altitude;
    tj["fix_interval_s"] = num(t.fix_interval_s);
    const std::string note = no_flight_reason(t.analysis);
    tj["note"] = note.empty() ? nlohmann::json(nullptr) : nlohmann::json(note);
    tj["flights"] = nlohmann::json::array();
    for (const fl::Flight& flight : t.analysis.flights) tj["flights"].push_back(flight_json(flight));
    j["tracks"].push_back(tj);
  }
  if (task != nullptr && f.task) j["task"] = task_flight_json(task->task, *f.task);
  return j;
}

nlohmann::json flight_settings_json(const fl::FlightOptions& o) {
  return {{"turn_window_s", o.turn_window_s},
          {"circling_enter_deg_s", o.circling_enter_deg_s},
          {"circling_exit_deg_s", o.circling_exit_deg_s},
          {"min_thermal_s", o.min_thermal_s},
          {"min_glide_s", o.min_glide_s},
          {"max_gap_s", o.max_gap_s},
          {"best_climb_window_s", o.best_climb_window_s},
          {"best_glide_min_m", o.best_glide_min_m},
          {"best_glide_min_loss_m", o.best_glide_min_loss_m},
          {"wind_band_m", o.wind_band_m}};
}

}  // namespace trailray::app
