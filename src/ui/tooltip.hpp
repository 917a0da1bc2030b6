#pragma once
// The numbers of one track point, as the 3D view's tooltip and `--script print-hover` print them.

#include <cstddef>
#include <string>
#include <vector>

#include "scene/tracks/track_set.hpp"

namespace trailray::ui {

// "time", "altitude", "height above ground", "speed", "vertical speed", "heart rate", one line
// each as "label: value unit" (km/h, m/s, m, bpm; the time as "YYYY-MM-DD hh:mm:ss UTC"); a
// missing value reads "—". A point with a GNSS or pressure altitude (IGC) has "GNSS altitude"
// and "pressure altitude", in that order, after "altitude". Empty for an index out of range.
std::vector<std::string> tooltip_lines(const scene::Track& track, std::size_t point);

// A time as the tooltips show it: "YYYY-MM-DD hh:mm:ss UTC" ("—" when it cannot be shown).
std::string tooltip_time_text(double unix_s);

}  // namespace trailray::ui
