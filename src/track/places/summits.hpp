#pragma once
// The summits a track reached and the huts it passed ("peak bagging"), from the places of an
// OpenStreetMap file. Pure: the track's points and the places in, the visits out.
//
// The rule, per place, over the track's legs (the straight line between two fixes, so a place
// between sparse fixes is not missed; its elevation and time interpolated along the leg):
//  - a summit (natural=peak or volcano) is reached where the track passes within `reach_m`
//    (50 m) horizontally and no more than `below_m` (30 m) below the summit's `ele`; where the
//    summit or the track has no elevation there, within 50 m of its position alone;
//  - a hut (tourism=alpine_hut or wilderness_hut) is passed where the track passes within 50 m,
//    at any height.
// The visit is the nearest approach among the places of the leg that qualify: its time (NaN when
// the track has no times), the distance, the track's elevation there. A leg longer than
// `longest_leg_m` (1 km: a gap in the recording, not a walk) only counts at its two fixes.
// Places are found through a grid of about a kilometre, so the work follows the points and the
// places near them, not points × places.

#include <cstddef>
#include <limits>
#include <vector>

#include "track/model.hpp"
#include "track/places/place.hpp"

namespace trailray::track::places {

struct VisitRules {
  double reach_m = 50.0;          // horizontal distance to a summit or hut
  double below_m = 30.0;          // how far below a summit's ele the track may pass
  double longest_leg_m = 1000.0;  // legs longer than this: only their fixes
};

struct PlaceVisit {
  Place place;
  double distance_m = 0.0;  // horizontal, at the nearest approach
  double time_unix_s = std::numeric_limits<double>::quiet_NaN();
  double track_ele_m = std::numeric_limits<double>::quiet_NaN();  // the track's elevation there
  std::size_t segment = 0;  // where along the track: the leg from point `point` of `segment`
  std::size_t point = 0;
  double fraction = 0.0;    // how far along that leg, 0..1
};

struct PlacesVisited {
  std::vector<PlaceVisit> summits;  // in the order the track reached them
  std::vector<PlaceVisit> huts;
};

PlacesVisited places_visited(const Track& track, const std::vector<Place>& places, const VisitRules& rules = {});

}  // namespace trailray::track::places
