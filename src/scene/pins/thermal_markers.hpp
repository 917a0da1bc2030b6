#pragma once
// Thermal markers (`--thermals`): each thermal of a track's flights as a pin at its top (the
// point where the glider left it, at the exit altitude), named by its mean climb and its entry
// and exit altitudes, "+2.4 m/s · 1650→2380 m", so a pilot reads where the lift was and how good
// it was. The pin stands on the track in the air (its stem's foot is the marker itself: a short
// flag, not a pole from the ground through the valley's air), in the pins' thermal colour; the
// labels pass lays the names out without overlaps, stronger thermals (more height gained) first.
// Glides need no marker: they are the track between two thermals.

#include <string>
#include <vector>

#include "scene/tracks/track_set.hpp"
#include "scene/pins/waypoints.hpp"
#include "track/flight/flight_analysis.hpp"

namespace trailray::scene {

// "+2.4 m/s · 1650→2380 m": the mean climb with its sign (a true minus, U+2212, for a thermal
// that lost height), one decimal; entry and exit altitudes in whole metres.
std::string thermal_label(const track::flight::Thermal& thermal);

// The markers of the thermals of `track`'s flight analysis (none without one) that gained
// height and have altitudes, in flight and time order, kind Thermal, priority the metres gained.
std::vector<Waypoint> thermal_markers(const Track& track);

}  // namespace trailray::scene
