#pragma once
// The density view (`--color-by density`) and the thermal map (`--color-by thermals`) on a
// scene's tracks: each point of each recorded track coloured by how many tracks passed within a
// radius of it, or how many flights climbed in a thermal within that radius. Unlike the other
// metrics a point's value depends on every track, so this runs once the tracks are built
// together (track_building.hpp's finish_tracks; the viewer again when the metric, the radius or
// the tracks change). The geometry is track/density.hpp's.
//
// What counts: every recorded track of the set, shown or not (routes are plans, not passages: they
// neither count nor are coloured). density: each track is one source, its cleaned segments its
// lines, and a point's own track counts (every point at least 1). thermals: each flight of a
// track's flight analysis is one source, its lines the cleaned points during its thermals that
// gained height (the circling `--thermals` marks), so a point counts the flights that climbed near
// it, its own flight among them when it climbed there; a point where no flight climbed is 0.

#include <cstddef>
#include <string>
#include <vector>

#include "scene/tracks/track_set.hpp"
#include "track/density.hpp"

namespace trailray::scene {

// Sets the colour values of every recorded track to `metric`'s counts within `radius_m` and bumps
// its revision (routes keep theirs). Returns the number of sources: the tracks (density), or the
// flights that climbed in a thermal (thermals: 0 means every point is 0). Throws
// std::invalid_argument for another metric, a radius outside track::kMinNeighbourRadiusM to
// kMaxNeighbourRadiusM, and for thermals a recorded track without its flight analysis.
std::size_t apply_neighbour_counts(std::vector<Track>& tracks, track::ColorMetric metric, double radius_m,
                                   const track::ParallelFor& parallel = {});

// The legend's title, saying what a number means: "Tracks within 100 m (own included)",
// "Flights climbing within 200 m (own included)"; from 1 km on the radius in km ("1.5 km").
std::string neighbour_legend_title(track::ColorMetric metric, double radius_m);

// "100 m", "2.5 km".
std::string radius_text(double radius_m);

}  // namespace trailray::scene
