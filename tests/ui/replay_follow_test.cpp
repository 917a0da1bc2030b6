// The replay's camera follow (both viewers): the pivot goes to the followed track's marker; a
// chase camera looks along the track; off, or a clock outside the track's times, leaves the camera.
#include "ui/replay_follow.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "track/flight/synthetic_flight.hpp"
#include "scene/tracks/replay_position.hpp"
#include "scene/tracks/track_building.hpp"

namespace trailray::ui {
namespace {

// A straight glide to the east (heading 90), built as the viewers build tracks.
ViewerModel gliding_east() {
  track::test::SyntheticFlight sim(0.0, 0.0);
  sim.glide(300, 90.0);
  scene::LoadedTrackFile loaded;
  loaded.path = "glide.igc";
  loaded.file.tracks.push_back(sim.track());
  scene::CollectedDiagnostics diagnostics;
  ViewerModel model;
  for (scene::Track& t : scene::build_tracks({loaded}, {}, {}, diagnostics)) model.tracks.add(std::move(t));
  model.clock.set_span(*common_time_span(model.tracks));
  return model;
}

scene::CameraController camera_far_away() {
  scene::LookAt view;
  view.target = {10.0, 10.0, 0.0};
  view.distance_m = 5000.0;
  view.heading_deg = 200.0;
  view.pitch_deg = -30.0;
  scene::Lens lens;
  lens.width_px = 640;
  lens.height_px = 400;
  return scene::CameraController(view, lens);
}

TEST(ReplayFollow, OffLeavesTheCamera) {
  ViewerModel model = gliding_east();
  scene::CameraController camera = camera_far_away();
  model.clock.follow = FollowMode::off;
  EXPECT_FALSE(follow_replay(model, camera));
  EXPECT_EQ(camera.view().target.lat_deg, 10.0);
}

TEST(ReplayFollow, ThePivotGoesToTheMarkerAndChaseLooksAlongTheTrack) {
  ViewerModel model = gliding_east();
  model.clock.seek_fraction(0.5);
  const scene::TrackPosition p = scene::position_at(model.tracks[0], model.clock.time());
  ASSERT_TRUE(p.valid);
  const geo::Geodetic marker = geo::geodetic_from_ecef(p.ecef);

  scene::CameraController orbit = camera_far_away();
  model.clock.follow = FollowMode::orbit;
  model.clock.follow_track = 0;
  ASSERT_TRUE(follow_replay(model, orbit));
  EXPECT_NEAR(orbit.view().target.lat_deg, marker.lat_deg, 1e-9);
  EXPECT_NEAR(orbit.view().target.lon_deg, marker.lon_deg, 1e-9);
  EXPECT_EQ(orbit.view().heading_deg, 200.0);  // an orbit keeps its heading

  scene::CameraController chase = camera_far_away();
  model.clock.follow = FollowMode::chase;
  ASSERT_TRUE(follow_replay(model, chase));
  EXPECT_NEAR(chase.view().target.lon_deg, marker.lon_deg, 1e-9);
  EXPECT_NEAR(std::remainder(chase.view().heading_deg - 90.0, 360.0), 0.0, 2.0);  // looking east, the way it glides
}

TEST(ReplayFollow, ATrackThatIsNotThereLeavesTheCamera) {
  ViewerModel model = gliding_east();
  scene::CameraController camera = camera_far_away();
  model.clock.follow = FollowMode::chase;
  model.clock.follow_track = 3;
  EXPECT_FALSE(follow_replay(model, camera));
  EXPECT_EQ(camera.view().heading_deg, 200.0);
}

}  // namespace
}  // namespace trailray::ui
