// The first camera every front end makes (scene/camera/first_camera): a requested camera stands
// on the ground's height there, a request the camera cannot take names its option, nothing to
// frame is an error without one, and waypoints alone are framed.
#include "scene/camera/first_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "geo/wgs84.hpp"

namespace trailray::scene {
namespace {

Lens lens() {
  Lens l;
  l.width_px = 640;
  l.height_px = 360;
  return l;
}

double height_of(const Camera& camera) {
  const geo::Geodetic g = geo::geodetic_from_ecef(camera.position());
  return g.height_m;
}

TEST(FirstCamera, ARequestedCameraIsPlacedAsAskedWithTheGroundThereForItsDepthRange) {
  CameraRequest request;
  CameraPlacement placement;
  placement.position = {46.7, 7.85, 1600.0};
  placement.pitch_deg = -10.0;
  request.placement = placement;
  const TrackSet none;
  std::vector<std::pair<double, double>> asked;
  const GroundHeight hill = [&](double lat, double lon) {
    asked.emplace_back(lat, lon);
    return 1500.0;
  };
  const Camera on_plain = first_camera(request, lens(), none, nullptr, 500.0, {});
  const Camera on_hill = first_camera(request, lens(), none, nullptr, 500.0, hill);
  // The ground is asked for under the camera, once.
  ASSERT_EQ(asked.size(), 1u);
  EXPECT_DOUBLE_EQ(asked[0].first, 46.7);
  EXPECT_DOUBLE_EQ(asked[0].second, 7.85);
  // The camera stands where it was asked either way; 100 m over a hill it needs a nearer near
  // plane than 1100 m over the plain.
  EXPECT_NEAR(height_of(on_hill), 1600.0, 0.01);
  EXPECT_NEAR(height_of(on_plain), 1600.0, 0.01);
  EXPECT_LT(on_hill.depth_range().near_m, on_plain.depth_range().near_m);
  // Unknown ground (NaN) is the neutral ground.
  const Camera unknown =
      first_camera(request, lens(), none, nullptr, 500.0, [](double, double) { return std::nan(""); });
  EXPECT_DOUBLE_EQ(unknown.depth_range().near_m, on_plain.depth_range().near_m);
}

TEST(FirstCamera, AnImpossibleRequestNamesItsOption) {
  CameraRequest request;
  LookAt look;
  look.target = {46.7, 7.85, 0.0};
  look.distance_m = -5.0;  // no camera stands at a negative distance
  request.look_at = look;
  try {
    first_camera(request, lens(), TrackSet{}, nullptr, 0.0, {});
    FAIL() << "a negative distance made a camera";
  } catch (const FirstCameraError& e) {
    EXPECT_EQ(e.option(), "--look-at");
    EXPECT_FALSE(e.why().empty());
    EXPECT_EQ(std::string(e.what()), "--look-at: " + e.why());
  }
}

TEST(FirstCamera, NothingToFrameIsAnErrorWithoutAnOption) {
  try {
    first_camera({}, lens(), TrackSet{}, nullptr, 0.0, {});
    FAIL() << "framed nothing";
  } catch (const FirstCameraError& e) {
    EXPECT_TRUE(e.option().empty());
    EXPECT_NE(std::string(e.what()).find("cannot frame"), std::string::npos) << e.what();
  }
}

TEST(FirstCamera, WaypointsAloneAreFramed) {
  WaypointSet waypoints;
  for (const auto& [lat, lon] : {std::pair{46.70, 7.80}, std::pair{46.72, 7.90}}) {
    Waypoint w;
    w.lat_deg = lat;
    w.lon_deg = lon;
    w.ele_m = 1000.0;
    waypoints.points.push_back(w);
  }
  const Camera camera = first_camera({}, lens(), TrackSet{}, &waypoints, 0.0, {});
  // Both waypoints in the picture.
  for (const Waypoint& w : waypoints.points) {
    const auto seen = camera.project(ecef_from({w.lat_deg, w.lon_deg, w.ele_m}));
    ASSERT_TRUE(seen.has_value());
    EXPECT_GE(seen->x_px, 0.0);
    EXPECT_LE(seen->x_px, 640.0);
    EXPECT_GE(seen->y_px, 0.0);
    EXPECT_LE(seen->y_px, 360.0);
  }
}

}  // namespace
}  // namespace trailray::scene
