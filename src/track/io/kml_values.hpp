#pragma once
// The small grammars inside KML elements, apart from the document's structure (kml_document.cpp):
// <coordinates> tuples, gx:coord triples, altitudeMode values, and the names devices give the
// gx:SimpleArrayData channels of a gx:Track.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace trailray::track {

// How a geometry's altitudes are meant (KML 2.2 altitudeMode and gx:altitudeMode).
enum class AltitudeMode { ClampToGround, RelativeToGround, Absolute, ClampToSeaFloor, RelativeToSeaFloor };

// The mode named by `text` (surrounding whitespace ignored); nullopt for an unknown value.
std::optional<AltitudeMode> parse_altitude_mode(std::string_view text);

struct KmlCoordinate {
  double lon = 0.0;
  double lat = 0.0;
  double alt = 0.0;  // NaN when the tuple has no altitude
};

// One tuple of a <coordinates> text: where it starts in the text, its characters, and its value
// (nullopt when a component is not a number, or it has fewer than 2 or more than 3 components).
// The range of lon/lat is not checked here.
struct KmlTuple {
  std::size_t offset = 0;
  std::string_view text;
  std::optional<KmlCoordinate> value;
};

// Splits a <coordinates> text into its "lon,lat[,alt]" tuples, which whitespace separates.
// Whitespace next to a comma stays inside the tuple ("8.5, 48.2" is one tuple), as Google Earth
// and GDAL read it.
void split_kml_tuples(std::string_view text, std::vector<KmlTuple>& out);

// A gx:coord: "lon lat alt" separated by whitespace (commas tolerated); alt may be missing.
std::optional<KmlCoordinate> parse_gx_coord(std::string_view text);

// The recorded channel a gx:SimpleArrayData name stands for (case-insensitive): the names
// Google My Tracks, Garmin and Strava exports use.
enum class ArrayChannel { None, HeartRate, Cadence, Power, Temperature };
ArrayChannel array_channel(std::string_view name);

}  // namespace trailray::track
