#pragma once
// The colour values of `--color-by phase`: per point of a drawn (cleaned) track, the climb rate
// where the glider was circling, the category value (track::kCategoryValue) where it was
// gliding, NaN on the ground, in gaps and before or after the flights.
//
// Which track the analysis sees: the raw track, as read (what `trailray flight` analyses, so the
// figures and the colours agree). Cleaning drops points (repeats, backward times, points closer
// than a few metres while standing) and smooths positions, so raw and cleaned points are not
// parallel; time is what both share (cleaning keeps times, only spreading same-second runs
// forward within that second). A cleaned point takes the phase whose span holds its time; a
// point without a time has no phase (NaN).
//
// The climb of a circling point is measured over a centred window of `climb_window_s` (about one
// circle, so the climb of the circle rather than of its better half), clipped to its circling
// span so the glide before or after does not leak into the thermal's colour.

#include <vector>

#include "track/flight/flight_analysis.hpp"
#include "track/model.hpp"

namespace trailray::track::flight {

// The phase at time `t` (seconds since 1970): the phase span of a flight holding it, Ground
// outside the flights, Unknown for NaN.
Phase phase_at_time(const FlightAnalysis& analysis, double t);

// One value per point of each segment of `drawn` (parallel to drawn.segments[i].points), from
// the analysis of the track it was cleaned from.
std::vector<std::vector<float>> phase_color_values(const Track& drawn, const FlightAnalysis& analysis,
                                                   double climb_window_s = 20.0);

}  // namespace trailray::track::flight
