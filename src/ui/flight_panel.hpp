#pragma once
// The flight analysis in the viewer: in the statistics window, for a track with flights, each
// flight's summary (take-off and landing, duration, circling share, mean and best climb, best
// glide, wind per altitude band) and a table of its thermals (a click flies the camera to the
// thermal's top); in the profile chart, the thermals shaded as translucent bands. The text is
// made by GL-free functions (tested); drawing is ImGui.

#include <imgui.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/tracks/track_set.hpp"
#include "track/flight/flight_analysis.hpp"
#include "ui/viewer_panels.hpp"

namespace trailray::ui {

// The summary of one flight, a line each: "take-off 14:20:53 UTC, 1593 m", "landing ...",
// "duration 1:28:38, 11.4 km", "circling 32 % (left 17 min, right 11 min)", "thermals 10, mean
// climb +3.2 m/s, best +8.7 m/s", "best glide L/D 11.1 over 11.4 km", "wind 2000-2500 m: 5.1 m/s
// from 2°" (one line per band).
std::vector<std::string> flight_summary_lines(const track::flight::Flight& flight);

// A thermal's row: its start (UTC), mean climb, entry→exit altitude, gain, duration.
std::vector<std::string> thermal_row(const track::flight::Thermal& thermal);

// The flat points of `track` whose times lie in [t0, t1] (first, last); nullopt when none does.
std::optional<std::pair<std::size_t, std::size_t>> points_between(const scene::Track& track, double t0, double t1);

// The flights' part of the statistics window (nothing for a track without flights).
void flight_statistics(const scene::Track& track, PanelActions& actions);

// Shades the thermals of `track` in the profile chart: a translucent band from the first to the
// last point of each circling phase, `x_px` the chart's pixel column of a flat point.
void shade_thermals(ImDrawList* draw, const scene::Track& track, const std::function<float(std::size_t)>& x_px,
                    float top, float bottom);

}  // namespace trailray::ui
