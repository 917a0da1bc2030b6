#pragma once
// What the GeoJSON reader collects from one JSON object before it knows what the object is
// (keys come in any order: gpsbabel writes "geometry" before "properties" and "type" last), and
// how a finished Feature becomes tracks, routes and waypoints (geojson_features.cpp).

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/model.hpp"

namespace trailray::track {

// Per-point values from the properties: flat for one line ([v, v, ...]) or one array per line
// ([[v, ...], [v, ...]]) for MultiLineString / GeometryCollection. Missing values (null, text
// that is not a number or a time) are NaN, so indices stay aligned with the coordinates.
struct GeoSeries {
  bool present = false;
  bool nested = false;
  std::vector<double> values;
  std::vector<std::size_t> part_ends;  // nested: end index in `values` of each inner array
  std::string path;                    // JSON path, for warnings
  SourcePosition where;

  std::size_t parts() const { return nested ? part_ends.size() : (present ? 1 : 0); }
  std::size_t part_begin(std::size_t i) const { return nested ? (i == 0 ? 0 : part_ends[i - 1]) : 0; }
  std::size_t part_end(std::size_t i) const { return nested ? part_ends[i] : values.size(); }
};

enum class GeoChannel { Time, Heart, Cadence, Power, Temperature, Speed, Count };

struct GeoProperties {
  std::string name, description, symbol, type, gpx_type, time;
  GeoSeries series[static_cast<int>(GeoChannel::Count)];
  GeoSeries& of(GeoChannel c) { return series[static_cast<int>(c)]; }
  const GeoSeries& of(GeoChannel c) const { return series[static_cast<int>(c)]; }
};

// A Feature, a geometry, or the top-level object, as collected.
struct GeoObject {
  std::string type;
  std::string path;  // JSON path of the object ("features[3].geometry"); "" for the top level
  SourcePosition where;
  // Positions in file order; an unusable one (not numbers, out of range) is kept with a NaN
  // latitude so that per-point properties stay aligned, and dropped when the track is built.
  std::vector<TrackPoint> points;
  // Arrays that hold positions (or nothing): where each ends in `points`, and its nesting under
  // "coordinates" (1 = the coordinates array itself). Lines are those one level above positions.
  std::vector<std::size_t> part_ends;
  std::vector<int> part_levels;
  int position_level = 0;     // nesting of positions under "coordinates": 1 Point, 2 LineString...
  bool mixed_levels = false;  // positions at different depths: not a valid geometry
  bool has_coordinates = false;
  std::unique_ptr<GeoObject> geometry;                 // a Feature's "geometry"
  std::vector<std::unique_ptr<GeoObject>> geometries;  // a GeometryCollection's members
  std::unique_ptr<GeoProperties> properties;           // a Feature's "properties" (object)
  bool has_features = false;                           // a FeatureCollection (its features are already out)
};

// Adds what a finished Feature (or a bare geometry at the top level) holds to `file`. `cut`: the
// file ended inside it (per-point arrays longer than the coordinates read are then expected).
// Takes the points out of `feature` (it is dropped afterwards).
void add_geojson_feature(GeoObject& feature, bool cut, TrackFile& file, WarningCollector& warnings);

// True for the GeoJSON geometry type names.
bool is_geojson_geometry_type(const std::string& type);

}  // namespace trailray::track
