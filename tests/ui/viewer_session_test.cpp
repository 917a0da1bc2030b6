// The viewer's session driven through a script of inputs, as a front end drives it: tracks
// adopted (their warnings kept), the first camera, hover at a pixel over a track, a pin and an
// airspace wall, key F flying to the selected track, a click on a photo's pin enlarging it, a
// drag and the wheel, and the state every front end shows (session_state_json).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "scene/pins/photo_image.hpp"
#include "scene/tracks/track_building.hpp"
#include "ui/session_state.hpp"
#include "ui/track_picking.hpp"
#include "ui/viewer_session.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::ui {
namespace {

constexpr double kLat = 46.70, kLon = 7.85, kEle = 1000.0;
constexpr double kT0 = 1718704800.0;  // 2024-06-18T10:00:00Z

scene::Lens lens() {
  scene::Lens l;
  l.width_px = 640;
  l.height_px = 360;
  return l;
}

// A hike of `count` points heading east from (kLat, kLon + lon0), about 20 m and 10 s apart,
// climbing 2 m a point.
scene::LoadedTrackFile hike(const std::string& name, int count, double lon0 = 0.0) {
  track::Segment s;
  const double step_deg = 20.0 / (111320.0 * std::cos(kLat * 3.14159265358979323846 / 180.0));
  for (int i = 0; i < count; ++i) {
    track::TrackPoint p;
    p.lat = kLat;
    p.lon = kLon + lon0 + i * step_deg;
    p.ele = kEle + 2.0 * i;
    p.time = kT0 + 10.0 * i;
    s.points.push_back(p);
  }
  track::Track t;
  t.name = name;
  t.segments.push_back(std::move(s));
  scene::LoadedTrackFile f;
  f.path = name + ".gpx";
  f.file.tracks.push_back(std::move(t));
  return f;
}

// The files as the viewer builds them (inspected: summaries), with a warning of their own.
LoadedTracks loaded(std::vector<scene::LoadedTrackFile> files, std::vector<std::string> warnings = {}) {
  scene::TrackBuildOptions options;
  options.inspect = true;
  options.neutral_ground_m = kEle;
  scene::CollectedDiagnostics diagnostics;
  LoadedTracks out;
  out.tracks = scene::build_tracks(files, scene::TrackStyle{}, options, diagnostics);
  out.warnings = std::move(warnings);
  for (std::string& w : diagnostics.warnings) out.warnings.push_back(std::move(w));
  return out;
}

scene::Waypoint pin_at(const std::string& name, double lat, double lon, double ele, scene::WaypointKind kind) {
  scene::Waypoint w;
  w.name = name;
  w.kind = kind;
  w.lat_deg = lat;
  w.lon_deg = lon;
  w.ele_m = ele;
  w.ground_m = kEle;
  w.marker_ecef = scene::ecef_from({lat, lon, ele});
  w.ground_ecef = scene::ecef_from({lat, lon, kEle});
  if (kind == scene::WaypointKind::Photo) {
    scene::RgbaImage thumbnail;
    thumbnail.width = 64;
    thumbnail.height = 48;
    thumbnail.rgba.assign(64 * 48 * 4, 200);
    w.thumbnail = scene::make_photo_image(std::move(thumbnail));
  }
  return w;
}

// A session with one hike of 100 points, framed by the first camera.
ViewerSession framed_session() {
  ViewerSession s;
  s.model().neutral_ground_m = kEle;
  s.adopt(loaded({hike("Hike", 100)}));
  EXPECT_TRUE(s.place_first_camera({}, lens()));
  return s;
}

// How many of the track's points lie inside the picture.
std::size_t points_in_view(const ViewerSession& s, int track) {
  const scene::Track& t = s.model().tracks[static_cast<std::size_t>(track)];
  const scene::Camera camera = s.camera().camera();
  std::size_t in = 0;
  for (std::size_t i = 0; i < t.point_count(); ++i)
    if (const auto p = screen_position(camera, t.ecef(i)))
      in += p->x >= 0 && p->y >= 0 && p->x < lens().width_px && p->y < lens().height_px ? 1 : 0;
  return in;
}

TEST(ViewerSession, AdoptKeepsWarningsAndErrorsAndSelectsTheFirstTrack) {
  ViewerSession s;
  LoadedTracks first = loaded({hike("Hike", 30)}, {"hike.gpx: line 7: a point without a time"});
  first.errors.push_back("broken.igc: not a track file");
  s.adopt(std::move(first));
  ASSERT_EQ(s.model().tracks.size(), 1u);
  EXPECT_EQ(s.model().selected_track, 0);
  ASSERT_EQ(s.warnings().size(), 1u);
  EXPECT_EQ(s.warnings()[0], "hike.gpx: line 7: a point without a time");
  ASSERT_EQ(s.model().errors.size(), 1u);
  EXPECT_EQ(s.model().errors[0], "broken.igc: not a track file");
  // A second load adds its tracks and warnings to those open.
  s.adopt(loaded({hike("Second", 20, 0.01)}, {"second.gpx: cut short at line 3"}));
  ASSERT_EQ(s.model().tracks.size(), 2u);
  EXPECT_EQ(s.model().selected_track, 0);
  ASSERT_EQ(s.warnings().size(), 2u);
  EXPECT_EQ(s.warnings()[1], "second.gpx: cut short at line 3");
  // The state says so.
  const auto state = nlohmann::json::parse(session_state_json(s));
  EXPECT_EQ(state["warnings"].size(), 2u);
  EXPECT_EQ(state["errors"][0], "broken.igc: not a track file");
  EXPECT_EQ(state["tracks"][1]["name"], "Second");
  EXPECT_EQ(state["tracks"][0]["points"], 30);
  EXPECT_TRUE(state["camera"].is_null()) << "no camera placed yet";
  // replace_tracks (the page builds every track again): its warnings replace the others.
  s.replace_tracks(loaded({hike("Hike", 30)}, {"only this"}));
  EXPECT_EQ(s.model().tracks.size(), 1u);
  ASSERT_EQ(s.warnings().size(), 1u);
  EXPECT_EQ(s.warnings()[0], "only this");
}

TEST(ViewerSession, TheFirstCameraFramesTheTracksOrTakesTheRequest) {
  ViewerSession s = framed_session();
  ASSERT_TRUE(s.has_camera());
  EXPECT_EQ(points_in_view(s, 0), 100u) << "the whole hike in the picture";
  // The pivot on the neutral ground, near the hike's middle (about 1 km east of its start).
  EXPECT_NEAR(s.camera().view().target.height_m, kEle, 1.0);
  EXPECT_NEAR(s.camera().view().target.lat_deg, kLat, 0.01);
  // A look-at asked for is the view, as it is.
  ViewerSession asked;
  CameraRequest request;
  request.look_at = scene::LookAt{{46.6, 8.0, 500.0}, 2500.0, 30.0, -20.0};
  ASSERT_TRUE(asked.place_first_camera(request, lens()));
  EXPECT_DOUBLE_EQ(asked.camera().view().target.lat_deg, 46.6);
  EXPECT_DOUBLE_EQ(asked.camera().view().distance_m, 2500.0);
  EXPECT_DOUBLE_EQ(asked.camera().view().heading_deg, 30.0);
  // Nothing to frame and nothing asked for: no camera.
  ViewerSession empty;
  EXPECT_FALSE(empty.place_first_camera({}, lens()));
  EXPECT_FALSE(empty.has_camera());
}

TEST(ViewerSession, TracksFarApartFrameTheLargestGroupAndSaySo) {
  ViewerSession s;
  s.model().neutral_ground_m = kEle;
  // Two hikes side by side, one 40 degrees of longitude away (far beyond one view).
  s.adopt(loaded({hike("A", 20), hike("B", 20, 0.02), hike("Far", 20, 40.0)}));
  scene::CollectedDiagnostics diagnostics;
  ASSERT_TRUE(s.place_first_camera({}, lens(), &diagnostics));
  ASSERT_EQ(diagnostics.warnings.size(), 1u);
  EXPECT_NE(diagnostics.warnings[0].find("the 2 of 3"), std::string::npos) << diagnostics.warnings[0];
  EXPECT_EQ(points_in_view(s, 0), 20u);
  EXPECT_EQ(points_in_view(s, 2), 0u);
}

TEST(ViewerSession, HoverAtAPixelOverTheTrackGivesThatPoint) {
  ViewerSession s = framed_session();
  const scene::Track& t = s.model().tracks[0];
  for (const std::size_t target : {10u, 50u, 87u}) {
    const auto at = screen_position(s.camera().camera(), t.ecef(target));
    ASSERT_TRUE(at.has_value());
    s.hover_at(at->x, at->y);
    EXPECT_EQ(s.model().hover.track, 0);
    EXPECT_LE(s.model().hover.point > target ? s.model().hover.point - target : target - s.model().hover.point, 1u);
  }
  const auto state = nlohmann::json::parse(session_state_json(s));
  EXPECT_EQ(state["hover"]["track"], 0);
  EXPECT_EQ(state["hover"]["name"], "Hike");
  ASSERT_FALSE(state["hover"]["lines"].empty());
  EXPECT_EQ(state["hover"]["lines"][0].get<std::string>().substr(0, 6), "time: ");
  // A corner far from the track: nothing.
  s.hover_at(2.0, 2.0);
  EXPECT_EQ(s.model().hover.track, -1);
  EXPECT_EQ(nlohmann::json::parse(session_state_json(s))["hover"]["track"], -1);
}

TEST(ViewerSession, APinUnderTheCursorWinsOverTheTrack) {
  ViewerSession s = framed_session();
  const scene::Track& t = s.model().tracks[0];
  const geo::Geodetic g = geo::geodetic_from_ecef(t.ecef(40));
  s.model().waypoints.points.push_back(pin_at("Hut", g.lat_deg, g.lon_deg, g.height_m, scene::WaypointKind::Waypoint));
  const auto ball = pin_screen_position(s.camera().camera(), s.model().waypoints.points[0], s.model().settings.style.pins);
  ASSERT_TRUE(ball.has_value());
  s.hover_at(ball->x, ball->y);
  EXPECT_EQ(s.model().hover.waypoint, 0);
  EXPECT_EQ(s.model().hover.track, -1);
  EXPECT_EQ(nlohmann::json::parse(session_state_json(s))["hover"]["name"], "Hut");
}

TEST(ViewerSession, HoverOverAnAirspaceWallAwayFromTheTrack) {
  ViewerSession s = framed_session();
  // A square airspace south of the hike, 500 m on a side, from the ground to 3000 m.
  scene::Volume v;
  v.name = "CTR Test";
  v.category = "CTR";
  const double lat0 = kLat - 0.012, lon0 = kLon + 0.005, d = 0.0045;
  v.boundary = {{lat0, lon0}, {lat0, lon0 + d}, {lat0 + d, lon0 + d}, {lat0 + d, lon0}};
  v.floor.metres = 0.0;
  v.ceiling.metres = 3000.0;
  s.model().volumes.volumes.push_back(v);
  ++s.model().volumes.revision;
  // The middle of its northern wall (the side facing the camera or not: a wall either way).
  const auto at = screen_position(s.camera().camera(), scene::ecef_from({lat0 + d, lon0 + d / 2, 2000.0}));
  ASSERT_TRUE(at.has_value());
  s.hover_at(at->x, at->y);
  EXPECT_EQ(s.model().hover.track, -1);
  EXPECT_EQ(s.model().hover.volume, 0);
  const auto state = nlohmann::json::parse(session_state_json(s));
  EXPECT_EQ(state["hover"]["airspace"], 0);
  EXPECT_EQ(state["hover"]["name"], "CTR Test");
}

TEST(ViewerSession, KeyFFliesToTheSelectedTrack) {
  ViewerSession s = framed_session();
  // Far in, turned away: only a few points of the hike are in the picture.
  s.zoom(12.0, 20.0, 20.0);
  s.orbit(300.0, 0.0);
  ASSERT_LT(points_in_view(s, 0), 50u);
  const std::uint64_t moves = s.camera_moves();
  KeyInput keys;
  keys.press(ViewerKey::fly_to_selected);
  EXPECT_FALSE(s.keys(keys, 1.0 / 60.0)) << "F holds no move";
  EXPECT_TRUE(s.camera().animating());
  EXPECT_GT(s.camera_moves(), moves);
  s.update(1e9);
  EXPECT_EQ(points_in_view(s, 0), 100u) << "the whole hike in view again";
}

TEST(ViewerSession, KeysMoveTheCameraAndSpacePlays) {
  ViewerSession s = framed_session();
  const scene::LookAt before = s.camera().view();
  KeyInput forward;
  forward.hold(ViewerKey::forward);
  EXPECT_TRUE(s.keys(forward, 0.1));
  const scene::LookAt after = s.camera().view();
  EXPECT_GT(std::abs(after.target.lat_deg - before.target.lat_deg) + std::abs(after.target.lon_deg - before.target.lon_deg),
            1e-5);
  KeyInput orbit;
  orbit.hold(ViewerKey::orbit_right);
  s.keys(orbit, 0.1);  // 200 px a second, 0.25 degrees a pixel (a drag to the right turns it left)
  EXPECT_NEAR(std::remainder(after.heading_deg - s.camera().view().heading_deg, 360.0), 5.0, 0.01);
  KeyInput space;
  space.press(ViewerKey::play_pause);
  EXPECT_FALSE(s.model().clock.playing());
  s.keys(space, 0.1);
  EXPECT_TRUE(s.model().clock.playing());
  EXPECT_TRUE(nlohmann::json::parse(session_state_json(s))["replay"]["playing"].get<bool>());
}

TEST(ViewerSession, ClickOnAPhotoPinEnlargesItAndFliesThere) {
  ViewerSession s = framed_session();
  const scene::Track& t = s.model().tracks[0];
  const geo::Geodetic g = geo::geodetic_from_ecef(t.ecef(70));
  s.model().waypoints.points.push_back(pin_at("Hut", kLat + 0.003, kLon, kEle, scene::WaypointKind::Waypoint));
  s.model().waypoints.points.push_back(pin_at("IMG_1.jpg", g.lat_deg, g.lon_deg, g.height_m, scene::WaypointKind::Photo));
  int asked_px = 0;
  s.set_larger_photo([&](scene::Waypoint& w, int long_side_px) {
    asked_px = long_side_px;
    scene::RgbaImage larger;
    larger.width = static_cast<std::uint32_t>(long_side_px);
    larger.height = static_cast<std::uint32_t>(long_side_px * 3 / 4);
    larger.rgba.assign(std::size_t{larger.width} * larger.height * 4, 100);
    w.thumbnail = scene::make_photo_image(std::move(larger));
  });
  const std::uint64_t revision = s.model().waypoints.revision;
  // A click beside every pin does nothing.
  s.pointer({{5.0, 5.0}, {0.0, 0.0}, false, false, true, false, 0.0});
  EXPECT_EQ(s.enlarged_photo(), -1);
  EXPECT_FALSE(s.camera().animating());
  const auto ball = pin_screen_position(s.camera().camera(), s.model().waypoints.points[1], s.model().settings.style.pins);
  ASSERT_TRUE(ball.has_value());
  PointerInput click;
  click.position = *ball;
  click.left_clicked = true;
  s.pointer(click);
  EXPECT_EQ(s.enlarged_photo(), 1);
  EXPECT_GT(s.model().waypoints.revision, revision);
  EXPECT_EQ(asked_px, static_cast<int>(s.model().settings.style.pins.photo_px * scene::kEnlargedPhotoScale * 2.0));
  EXPECT_EQ(s.model().waypoints.points[1].thumbnail->pixels.width, static_cast<std::uint32_t>(asked_px));
  EXPECT_TRUE(s.camera().animating()) << "flying to the photo";
  s.update(1e9);
  const scene::LookAt& v = s.camera().view();
  EXPECT_NEAR(v.target.lat_deg, g.lat_deg, 1e-6);
  EXPECT_NEAR(v.target.lon_deg, g.lon_deg, 1e-6);
  const auto state = nlohmann::json::parse(session_state_json(s));
  EXPECT_EQ(state["enlarged_photo"]["name"], "IMG_1.jpg");
  // A click on a pin that is no photo's enlarges nothing else.
  const auto hut = pin_screen_position(s.camera().camera(), s.model().waypoints.points[0], s.model().settings.style.pins);
  if (hut && hut->x >= 0 && hut->y >= 0 && hut->x < 640 && hut->y < 360) {
    s.click(hut->x, hut->y);
    EXPECT_EQ(s.enlarged_photo(), 1);
  }
}

TEST(ViewerSession, DragOrbitsWheelZoomsDoubleClickFliesToTheGround) {
  ViewerSession s = framed_session();
  const scene::LookAt start = s.camera().view();
  PointerInput drag;
  drag.position = {320.0, 180.0};
  drag.delta = {40.0, 0.0};
  drag.left_down = true;
  s.pointer(drag);
  EXPECT_NEAR(std::remainder(start.heading_deg - s.camera().view().heading_deg, 360.0), 10.0, 0.01);
  PointerInput wheel;
  wheel.position = {320.0, 180.0};
  wheel.wheel = 2.0;
  const double far = s.camera().view().distance_m;
  s.pointer(wheel);
  EXPECT_LT(s.camera().view().distance_m, far);
  PointerInput twice;
  twice.position = {320.0, 180.0};
  twice.left_clicked = twice.left_double_clicked = true;
  const double before = s.camera().view().distance_m;
  s.pointer(twice);
  s.update(1e9);
  EXPECT_NEAR(s.camera().view().distance_m, before / 2.0, before * 1e-6);
  EXPECT_NEAR(s.camera().view().target.height_m, kEle, 1.0) << "on the ground under the pointer";
}

TEST(ViewerSession, PanelActionsFlyToATrack) {
  ViewerSession s;
  s.model().neutral_ground_m = kEle;
  s.adopt(loaded({hike("A", 40), hike("B", 40, 0.05)}));
  ASSERT_TRUE(s.place_first_camera({}, lens()));
  PanelActions actions;
  actions.fly_to_track = 1;
  s.apply(actions);
  s.update(1e9);
  EXPECT_EQ(points_in_view(s, 1), 40u);
}

}  // namespace
}  // namespace trailray::ui
