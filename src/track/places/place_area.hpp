#pragma once
// Which places matter and which are the same: the area around the tracks (their bounds and a
// margin) and duplicates merged (Liechtenstein 2013 maps Naafkopf twice, 0.1 m apart).

#include <vector>

#include "geo/bounds.hpp"
#include "track/places/place.hpp"

namespace trailray::track::places {

// `bounds` grown by `margin_m` on every side (longitudes by the margin at the bounds' latitude
// nearest a pole; the poles clamp). Empty bounds stay empty.
geo::LatLonBounds grown_bounds(const geo::LatLonBounds& bounds, double margin_m);

inline bool contains(const geo::LatLonBounds& b, double lat, double lon) {
  return lat >= b.min_lat && lat <= b.max_lat && lon >= b.min_lon && lon <= b.max_lon;
}

// Places of the same kind and name within `radius_m` of each other merged into the first of them
// in the list (its elevation taken from a later one when it has none). Order kept otherwise.
void merge_duplicate_places(std::vector<Place>& places, double radius_m = 25.0);

}  // namespace trailray::track::places
