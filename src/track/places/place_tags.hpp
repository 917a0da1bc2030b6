#pragma once
// OpenStreetMap tags to places: which objects are places (the classifier) and their `ele` as real
// files write it. Ours, not libosmium's: both take plain strings, so the fuzzer and the tests
// reach them without an OSM file.

#include <optional>
#include <string>
#include <string_view>

#include "track/places/place.hpp"

namespace trailray::track::places {

// The tags the classifier looks at (empty: absent).
struct PlaceTags {
  std::string_view name, natural, water, mountain_pass, tourism, place;
};

// The kind of place an object with these tags is, or nullopt (not a place, or without a name:
// a label needs one). `area`: a way or multipolygon relation (only lakes are read from those;
// peaks, huts and villages are read from nodes).
std::optional<PlaceKind> classify_place(const PlaceTags& tags, bool area);

// `ele` in metres, as OSM files write it: "2317", "3143,45" (a decimal comma), "2317m", "2317 m",
// "8000 ft", "8000'", "8000 feet", "-12"; surrounding spaces allowed. NaN for anything else
// ("unknown", "2317;2320", "", a value beyond +-12000 m).
double parse_ele(std::string_view text);

// A place's label: "Eiger 3967 m" (its name and `ele` rounded to the metre) for peaks, volcanoes,
// saddles, passes and huts with an elevation; the name alone for the others (a village's or a
// lake's elevation is no part of its name). Bytes that are not UTF-8 replaced by U+FFFD.
std::string place_label(const Place& place);

}  // namespace trailray::track::places
