#pragma once
// The tracks as one frame of a film draws them (`trailray video`): each track cut to its trail
// at the frame's time (the whole of it with the future ghosted, only the past, or a tail of the
// last minutes) and a marker at its current position carrying its name, as a pin among the
// files' waypoints. The cut tracks get a new revision each frame, so the renderer uploads them
// again (and frees the old ones); the source tracks are never changed.

#include <string_view>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/tracks/replay_position.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/pins/waypoints.hpp"

namespace trailray::scene {

enum class TrailKind { all, past, tail };
struct TrailMode {
  TrailKind kind = TrailKind::all;
  double tail_s = 0.0;  // TrailKind::tail: how far back
};
// `--trail all|past|DURATION` ("10m", "90s"); errors name --trail.
Result<TrailMode> parse_trail_mode(std::string_view text);

// The part of a track between two positions on it (from <= to in the track's order), as drawn:
// per segment the points between, ends interpolated; segments with fewer than two points left out.
TrackGeometry slice_geometry(const Track& track, const TrackPosition& from, const TrackPosition& to);

// The colour of the ghosted future: the track's own, paler and greyer.
glm::vec3 ghost_color(const glm::vec3& srgb);

class FilmTracks {
 public:
  // `source` and `waypoints` must outlive this. `neutral_ground_m`: where a marker's stem ends
  // when the ground under a point is unknown.
  FilmTracks(const TrackSet& source, const WaypointSet& waypoints, TrailMode mode, double neutral_ground_m);

  // Per source track, seconds added to the film's clock to get that track's time (--align start);
  // empty: none.
  void set_clock_offsets(std::vector<double> offsets) { offsets_ = std::move(offsets); }
  double track_time(std::size_t source_index, double film_time) const;

  // Cuts every track at `film_time` and moves the markers there.
  void set_time(double film_time);

  const TrackSet& tracks() const { return drawn_; }
  const WaypointSet& waypoints() const { return waypoints_; }
  // Where source track i is at the last set_time (invalid for a track without times).
  const std::vector<TrackPosition>& positions() const { return positions_; }

 private:
  const TrackSet& source_;
  const WaypointSet& file_waypoints_;
  TrailMode mode_;
  double neutral_ground_m_;
  std::vector<double> offsets_;
  TrackSet drawn_;  // per source track: the trail, then (TrailKind::all) the ghosted future
  std::vector<std::size_t> trail_of_, future_of_;  // indices into drawn_ (future: npos when none)
  WaypointSet waypoints_;
  std::vector<TrackPosition> positions_;
};

}  // namespace trailray::scene
