// Cleaning a segment: the steps of clean.hpp in order (clean_steps.hpp), and a track segment by
// segment.

#include "track/clean.hpp"

#include "track/clean_steps.hpp"

namespace trailray::track {

Segment clean_segment(const Segment& segment, const CleanOptions& options, CleanReport& report) {
  Segment out;
  out.points = detail::drop_invalid_and_unordered(segment.points, report);
  detail::enforce_min_distance(out.points, options.min_distance_m, report);
  if (options.smooth) detail::smooth_pieces(out.points, options);
  return out;
}

Track clean_track(const Track& track, const CleanOptions& options, CleanReport& report) {
  Track out;
  out.name = track.name;
  out.description = track.description;
  out.type = track.type;
  out.segments.reserve(track.segments.size());
  for (const Segment& s : track.segments) out.segments.push_back(clean_segment(s, options, report));
  return out;
}

}  // namespace trailray::track
