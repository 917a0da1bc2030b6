#pragma once
// Writes a TrackFile as GPX 1.1: metadata name/description/time, waypoints, routes, tracks with
// their segments (waypoints with name, desc and sym), and per point ele, time and the recorded channels (heart rate,
// cadence, temperature and speed in a Garmin TrackPointExtension v2, power as <power>, as Strava and Garmin tools read
// it). What the model does not keep (links, names of points, unknown extensions) is not written.

#include <ostream>

#include "track/model.hpp"

namespace trailray::track {

void write_gpx(const TrackFile& file, std::ostream& out);

}  // namespace trailray::track
