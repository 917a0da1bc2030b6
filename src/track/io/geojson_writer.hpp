#pragma once
// Writes a TrackFile as a GeoJSON FeatureCollection in togeojson's conventions, so that
// togeojson users, our reader and GDAL read it alike:
//   a track  -> Feature, LineString (one segment) or MultiLineString (one line per segment),
//               properties: name, desc, type, "_gpxType": "trk", and coordinateProperties with
//               one value per position (an array per line for a MultiLineString), null where a
//               point has none: times (ISO 8601), heart, cads, powers, atemps, speeds (only the
//               channels some point has);
//   a route  -> Feature, LineString, "_gpxType": "rte" (name, and times when it has any);
//   a waypoint -> Feature, Point: name, desc, sym, time.
// The file's metadata name, description and time are foreign members of the FeatureCollection.
// Positions are [lon, lat] or [lon, lat, ele] (ele only where known). Empty segments are left
// out. Features come in file order: tracks, then routes, then waypoints.

#include <ostream>

#include "track/model.hpp"

namespace trailray::track {

void write_geojson(const TrackFile& file, std::ostream& out);

}  // namespace trailray::track
