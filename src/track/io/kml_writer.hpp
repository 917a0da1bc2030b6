#pragma once
// Writes a TrackFile as KML 2.2 with Google's gx extensions, as Google Earth and GDAL read it:
//   a track    -> Placemark (name, description) holding one gx:Track per segment (a
//                 gx:MultiTrack when there are several): <when> and <gx:coord> per point, and
//                 ExtendedData/SchemaData with gx:SimpleArrayData arrays heartrate, cadence,
//                 power, temperature, speed (the channels some point has; an empty gx:value where
//                 a point has none), declared in the document's Schema "trailray_channels".
//                 A segment without any time is a LineString instead (gx:Track needs times).
//   a route    -> Placemark with a LineString, ExtendedData Data "type" = "route".
//   a waypoint -> Placemark with a Point: name, description, TimeStamp, sym as ExtendedData.
// altitudeMode is absolute wherever heights are written (clampToGround otherwise, KML's
// default), so heights are not taken relative to the terrain.

#include <ostream>

#include "track/model.hpp"

namespace trailray::track {

void write_kml(const TrackFile& file, std::ostream& out);

}  // namespace trailray::track
