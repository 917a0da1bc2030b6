#pragma once
// The cleaning steps behind clean_segment (clean.hpp lists them), internal to it: each works
// on one segment's points, in the order given there.

#include <vector>

#include "track/clean.hpp"
#include "track/model.hpp"

namespace trailray::track::detail {

// Steps 1 and 2 (clean_order.cpp): the kept points of `in`.
std::vector<TrackPoint> drop_invalid_and_unordered(const std::vector<TrackPoint>& in, CleanReport& report);

// Step 3 (clean_min_distance.cpp), in place.
void enforce_min_distance(std::vector<TrackPoint>& pts, double min_distance_m, CleanReport& report);

// Step 4 (clean_smooth.cpp), in place.
void smooth_pieces(std::vector<TrackPoint>& pts, const CleanOptions& o);

}  // namespace trailray::track::detail
