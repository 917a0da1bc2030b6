#pragma once
// A named place from OpenStreetMap as trailray sees it: a peak, a saddle or pass, a hut, a
// settlement or a lake, with its position and elevation. Plain data: the reading (libosmium,
// osm_places_reader) and the tag handling (place_tags) live beside this header; the scene's
// labels and the summits reached (summits.hpp) take these structs. Nothing here includes osmium,
// so the browser build sees it.

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace trailray::track::places {

enum class PlaceKind {
  Peak,           // natural=peak
  Volcano,        // natural=volcano
  Saddle,         // natural=saddle
  Pass,           // mountain_pass=yes
  AlpineHut,      // tourism=alpine_hut
  WildernessHut,  // tourism=wilderness_hut
  City,           // place=city
  Town,           // place=town
  Village,        // place=village
  Hamlet,         // place=hamlet
  Lake,           // natural=water (a lake, reservoir or pond, or without water=*), named
};

struct Place {
  std::string name;
  PlaceKind kind = PlaceKind::Peak;
  double lat_deg = 0.0, lon_deg = 0.0;  // a lake's: the mean of its (outer) ring's nodes
  double ele_m = std::numeric_limits<double>::quiet_NaN();  // `ele` in metres (NaN: none or unreadable)
  char osm_type = 'n';       // 'n' node, 'w' way, 'r' relation
  std::int64_t osm_id = 0;
};

// "peak", "alpine_hut", ... (the tag value it comes from; "pass" for mountain_pass=yes).
std::string_view kind_name(PlaceKind kind);

// Summits: what `stats --places` lists as reached (peaks and volcanoes).
inline bool is_summit(PlaceKind k) { return k == PlaceKind::Peak || k == PlaceKind::Volcano; }
// Huts: what it lists as passed.
inline bool is_hut(PlaceKind k) { return k == PlaceKind::AlpineHut || k == PlaceKind::WildernessHut; }

}  // namespace trailray::track::places
