#pragma once
// What `stats --places` prints of a track: the summits it reached and the huts it passed
// (track/places/summits), as JSON ("summits": [{"name", "ele", "lat", "lon", "time"}], "huts"
// alike) and as lines under the table.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "track/places/summits.hpp"

namespace trailray::app {

// [{"name", "ele" (null without), "lat", "lon" (the place's), "time" (ISO 8601 UTC of the nearest
// approach; null when the track has no times), "distance_m" (horizontal, at that approach)}].
nlohmann::json place_visits_json(const std::vector<track::places::PlaceVisit>& visits);

// "    summits: Hohe Warte 2596 m (10:32:05), Kleiner Solstein 2637 m (11:10:40)\n" and the huts
// alike, for the track called `name`; nothing when it reached none of either.
std::string places_visited_lines(const std::string& name, const track::places::PlacesVisited& visited);

}  // namespace trailray::app
