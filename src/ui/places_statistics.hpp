#pragma once
// The Statistics panel's summits and huts (--places): those the selected track reached and passed
// (track/places/summits), worked out once per track revision and kept.

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "scene/tracks/track_set.hpp"
#include "track/places/summits.hpp"

namespace trailray::ui {

class PlacesVisitCache {
 public:
  // The summits and huts `track` reached among `places`, from the cache while its revision holds.
  const track::places::PlacesVisited& of(const scene::Track& track, const std::vector<track::places::Place>& places);

 private:
  std::unordered_map<scene::TrackId, std::pair<std::uint64_t, track::places::PlacesVisited>> kept_;
};

// The panel's lines: "Summits reached", then "  Naafkopf 2571 m  08:12:40 UTC" (the time when the
// track has times), then "Huts passed" alike; nothing when it reached none.
std::vector<std::string> places_visited_panel_lines(const track::places::PlacesVisited& visited);

}  // namespace trailray::ui
