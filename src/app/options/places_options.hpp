#pragma once
// --places FILE, spelled the same in `stats`, `render`, `view`, `video` and `serve`: places from
// an OpenStreetMap file (.osm.pbf, .osm, .osm.gz, .osm.bz2; track/places). `stats` lists the
// summits each track reached and the huts it passed; the drawing commands label the peaks,
// saddles, passes, huts, settlements and lakes around the tracks.

#include <string>
#include <vector>

#include "geo/bounds.hpp"
#include "track/places/place.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

// What --places says, for `stats` (summits and huts) or for drawing (labels).
enum class PlacesUse { visits, labels };
void add_places_option(CLI::App& command, std::string& file, PlacesUse use);

// How far around the tracks' bounds places are labelled: the view reaches a little past them.
inline constexpr double kPlacesMarginM = 5000.0;

// Only the summits and huts of `places`: what track::places::places_visited looks for.
std::vector<track::places::Place> visit_places(std::vector<track::places::Place> places);

// The summits and huts of `file` (all of it: a country's peaks are a few thousand). Throws
// std::runtime_error naming the file when it cannot be read.
std::vector<track::places::Place> read_visit_places(const std::string& file);

// The places of `file` to label around `bounds` (grown by kPlacesMarginM; the whole file when
// `bounds` is empty). Throws std::runtime_error naming the file when it cannot be read.
std::vector<track::places::Place> read_label_places(const std::string& file, const geo::LatLonBounds& bounds);

}  // namespace trailray::app
