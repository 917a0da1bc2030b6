#pragma once
// Writes a TrackFile as CSV (RFC 4180, UTF-8, "\n" line ends), one row per point, for
// spreadsheets and scripts. The header row:
//   kind,track,segment,name,lat,lon,ele,time,hr,cad,power,temp,speed
// kind is "track", "route" or "waypoint"; track is the 1-based number of the track (of the
// route, of the waypoint) within its kind; segment the 1-based segment of a track point (empty
// for routes and waypoints); name the track's, route's or waypoint's name. time is ISO 8601 UTC;
// hr, cad, power (W), temp (degrees C) and speed (m/s) are as recorded. A value the point does
// not have is an empty field. Rows come as tracks, then routes, then waypoints.

#include <ostream>

#include "track/model.hpp"

namespace trailray::track {

void write_csv(const TrackFile& file, std::ostream& out);

}  // namespace trailray::track
