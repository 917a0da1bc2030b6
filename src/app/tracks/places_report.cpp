#include "app/tracks/places_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "track/io/text_output.hpp"
#include "track/places/place_tags.hpp"

namespace trailray::app {

namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string list_of(const std::vector<track::places::PlaceVisit>& visits) {
  std::string out;
  for (const track::places::PlaceVisit& v : visits) {
    if (!out.empty()) out += ", ";
    out += track::places::place_label(v.place);
    if (std::isfinite(v.time_unix_s)) {
      // The time of day, UTC, from the ISO text ("2024-06-18T10:32:05Z").
      const std::string iso = track::format_iso_time(v.time_unix_s);
      out += fmt::format(" ({} UTC)", iso.substr(11, 8));
    }
  }
  return out;
}

}  // namespace

nlohmann::json place_visits_json(const std::vector<track::places::PlaceVisit>& visits) {
  nlohmann::json out = nlohmann::json::array();
  for (const track::places::PlaceVisit& v : visits)
    out.push_back({{"name", track::valid_utf8(v.place.name)},
                   {"ele", number_or_null(v.place.ele_m)},
                   {"lat", v.place.lat_deg},
                   {"lon", v.place.lon_deg},
                   {"time", std::isfinite(v.time_unix_s) ? nlohmann::json(track::format_iso_time(v.time_unix_s))
                                                         : nlohmann::json(nullptr)},
                   {"distance_m", std::round(v.distance_m * 10.0) / 10.0}});
  return out;
}

std::string places_visited_lines(const std::string& name, const track::places::PlacesVisited& visited) {
  std::string out;
  if (!visited.summits.empty())
    out += fmt::format("  {}: summits reached: {}\n", name, list_of(visited.summits));
  if (!visited.huts.empty()) out += fmt::format("  {}: huts passed: {}\n", name, list_of(visited.huts));
  return out;
}

}  // namespace trailray::app
