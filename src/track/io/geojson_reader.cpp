// GeoJSON (RFC 7946) reader, streaming: nlohmann's SAX parser over the ByteSource, so memory
// follows the largest single Feature, not the file (a FeatureCollection's features are turned
// into tracks one at a time and dropped).
//
//   FeatureCollection / Feature / a bare geometry at the top level.
//   LineString            -> a Track with one Segment; MultiLineString -> one Segment per line;
//   GeometryCollection    -> its lines as Segments of one Track (togeojson writes gx:MultiTrack
//                            so), its points as Waypoints.
//   properties._gpxType "rte" (togeojson, and our writer) -> Routes instead of a Track.
//   Point / MultiPoint    -> Waypoints: properties name, desc|description, sym, time|timestamp.
//   Polygon, MultiPolygon, unknown types -> skipped with a counted warning.
//   positions [lon, lat, ele?] (further numbers ignored); properties.name -> Track.name,
//   desc|description -> description, type -> Track.type.
//   The top level's "name", "description" and "time" (foreign members) -> metadata.
//   Per-point values (togeojson's conventions), one value per position, an array per line for
//   multi-line geometries, null for none:
//     properties.coordTimes or coordinateProperties.times      ISO 8601 strings
//     coordinateProperties.heart, properties.heartRates         beats per minute
//     coordinateProperties.cads|cadences|cadence                 per minute
//     coordinateProperties.powers|power|watts                    watts
//     coordinateProperties.atemps|temperatures|temperature      degrees Celsius
//     coordinateProperties.speeds|speed                          metres per second
//   Arrays whose length does not match the coordinates are ignored with a warning.
// Unusable positions (not numbers, fewer than two, out of range) are dropped with a warning
// naming their JSON path (features[3].geometry.coordinates[17]); a JSON syntax error is the
// result's error at its line:column; a cut file keeps what was complete before the cut.
#include <exception>
#include <istream>
#include <string>

#include "track/io/geojson_handler.hpp"

namespace trailray::track {
namespace {

using geojson::GeoJsonHandler;
using json = nlohmann::json;

// nlohmann's message without its own "[json.exception...] parse error at line L, column C: "
// prefix (the position is ours), shortened: "last read" may quote a whole cut-off string.
std::string describe_syntax_error(const std::string& what) {
  std::string m = what;
  const auto colon = m.find(": ");
  if (m.starts_with("[json.exception") && colon != std::string::npos) m = m.substr(colon + 2);
  if (m.size() > 200) m = m.substr(0, 200) + "...";
  return "invalid JSON: " + m;
}

std::size_t point_total(const TrackFile& f) {
  std::size_t n = f.waypoints.size();
  for (const auto& t : f.tracks) n += t.point_count();
  for (const auto& r : f.routes) n += r.points.size();
  return n;
}

}  // namespace

ReadResult read_geojson(ByteSource& source, const ReadOptions& options) {
  ReadResult result;
  result.file.format = Format::GeoJson;
  const std::string& name = source.display_name();
  WarningCollector warnings(name);
  JsonSourceBuffer buffer(source);
  std::istream stream(&buffer);
  GeoJsonHandler handler(buffer, result.file, warnings);
  bool parsed = false;
  try {
    parsed = json::sax_parse(stream, &handler, json::input_format_t::json, true, true);
  } catch (const std::exception& e) {  // out of memory for a gigantic string, say: never across layers
    result.error = Diagnostic{name, buffer.here(), std::string("cannot read: ") + e.what()};
    finish_read(result, warnings, options);
    return result;
  }
  if (buffer.read_failed()) {
    result.error = Diagnostic{name, buffer.here(), "cannot read: " + buffer.read_error()};
  } else if (!handler.abort_message().empty()) {
    result.error = Diagnostic{name, buffer.here(), handler.abort_message()};
  } else if (!parsed) {
    const bool cut = buffer.at_end() && handler.error_offset() + 1 >= buffer.consumed();
    const SourcePosition at = buffer.position_of(handler.error_offset());
    if (cut) {
      handler.close_after_cut();
      warnings.add_single(at, "the file ends inside the JSON (cut off?); kept the " +
                                  std::to_string(point_total(result.file)) + " complete points before the cut");
    } else {
      result.error = Diagnostic{name, at, describe_syntax_error(handler.syntax_error())};
    }
  }
  if (!result.error) {
    const std::unique_ptr<GeoObject>& root = handler.root();
    // After a cut, a top level that has not said what it is yet is just empty.
    if (root && !root->has_features && root->type != "FeatureCollection" && !(handler.cut() && root->type.empty())) {
      if (root->type == "Feature" || is_geojson_geometry_type(root->type))
        add_geojson_feature(*root, handler.cut(), result.file, warnings);
      else
        result.error =
            Diagnostic{name,
                       {1, 1, 0},
                       root->type.empty() ? "not GeoJSON: the top-level object has no \"type\" (and no \"features\")"
                                          : "not GeoJSON: unknown top-level type '" + root->type.substr(0, 40) + "'"};
    }
  }
  finish_read(result, warnings, options);
  return result;
}

}  // namespace trailray::track
