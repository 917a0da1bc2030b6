#include "ui/places_statistics.hpp"

#include <cmath>

#include "track/io/text_output.hpp"
#include "track/places/place_tags.hpp"

namespace trailray::ui {

const track::places::PlacesVisited& PlacesVisitCache::of(const scene::Track& track,
                                                         const std::vector<track::places::Place>& places) {
  auto found = kept_.find(track.id);
  if (found == kept_.end() || found->second.first != track.revision)
    found = kept_.insert_or_assign(track.id, std::pair{track.revision, track::places::places_visited(track.cleaned, places)})
                .first;
  return found->second.second;
}

namespace {

void add_lines(std::vector<std::string>& out, const char* title, const std::vector<track::places::PlaceVisit>& visits) {
  if (visits.empty()) return;
  out.emplace_back(title);
  for (const track::places::PlaceVisit& v : visits) {
    std::string line = "  " + track::places::place_label(v.place);
    if (std::isfinite(v.time_unix_s)) line += "  " + track::format_iso_time(v.time_unix_s).substr(11, 8) + " UTC";
    out.push_back(std::move(line));
  }
}

}  // namespace

std::vector<std::string> places_visited_panel_lines(const track::places::PlacesVisited& visited) {
  std::vector<std::string> out;
  add_lines(out, "Summits reached", visited.summits);
  add_lines(out, "Huts passed", visited.huts);
  return out;
}

}  // namespace trailray::ui
