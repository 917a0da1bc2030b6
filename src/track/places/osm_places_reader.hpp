#pragma once
// Places read from OpenStreetMap files (.osm.pbf, .osm, .osm.gz, .osm.bz2) with libosmium,
// streaming: memory follows the places kept, not the file. Peaks, volcanoes, saddles, passes and
// huts and settlements are tagged nodes, kept inside the area; named lakes are ways or
// multipolygon relations, labelled at the mean of their (outer) ring's nodes. Lakes need node
// locations, but no index of every node is built: a first pass over the ways and relations
// collects the node ids of the wanted lakes (a small set), a last pass over the nodes keeps only
// those. This header does not include osmium (the browser build sees track/ but not libosmium:
// the .cpp is left out of it).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geo/bounds.hpp"
#include "track/places/place.hpp"

namespace trailray::track::places {

struct PlacesReadOptions {
  // Only places inside (a lake by its label point); nullopt: the whole file.
  std::optional<geo::LatLonBounds> area;
};

// The places of `path` in file order (nodes, then lakes), duplicates merged
// (merge_duplicate_places). Objects that are no place, have no name or no valid location are
// skipped; an `ele` that cannot be read is NaN. Throws std::runtime_error naming the file and what
// libosmium says for a file that cannot be opened or read.
std::vector<Place> read_osm_places(const std::string& path, const PlacesReadOptions& options = {});

// The same from bytes in memory: `format` is libosmium's name of it ("osm", "pbf", "osm.gz", ...);
// `name` names it in errors. The fuzzer's way in.
std::vector<Place> read_osm_places_from_memory(std::string_view bytes, const std::string& format,
                                               const std::string& name, const PlacesReadOptions& options = {});

}  // namespace trailray::track::places
