// The script commands on the session (ui/script_session.hpp), as both front ends carry them out:
// what they print, the flights they make arrive at once, errors naming the script's line, and
// the front end's own commands left to it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "scene/tracks/track_building.hpp"
#include "ui/script_session.hpp"

namespace trailray::ui {
namespace {

ViewerSession session_with_hike() {
  track::Segment s;
  for (int i = 0; i < 60; ++i) {
    track::TrackPoint p;
    p.lat = 46.70;
    p.lon = 7.85 + 0.0003 * i;
    p.ele = 1000.0 + i;
    p.time = 1718704800.0 + 10.0 * i;
    s.points.push_back(p);
  }
  scene::LoadedTrackFile f;
  f.path = "hike.gpx";
  f.file.tracks.push_back(track::Track{});
  f.file.tracks.back().name = "Hike";
  f.file.tracks.back().segments.push_back(std::move(s));
  scene::TrackBuildOptions options;
  options.inspect = true;
  options.neutral_ground_m = 1000.0;
  scene::CollectedDiagnostics diagnostics;
  ViewerSession session;
  session.model().neutral_ground_m = 1000.0;
  LoadedTracks loaded;
  loaded.tracks = scene::build_tracks({f}, scene::TrackStyle{}, options, diagnostics);
  session.adopt(std::move(loaded));
  scene::Lens lens;
  lens.width_px = 640;
  lens.height_px = 360;
  CameraRequest request;
  request.look_at = scene::LookAt{{46.70, 7.86, 1000.0}, 3000.0, 10.0, -40.0};
  EXPECT_TRUE(session.place_first_camera(request, lens));
  return session;
}

std::optional<std::string> run(ViewerSession& session, const std::string& line) {
  const ViewScript script = parse_view_script(line + "\n", "s.txt");
  return run_session_command(session, script.commands.at(0), script.file);
}

TEST(ScriptSession, PrintsTheCameraAndTheStateAndMovesIt) {
  ViewerSession s = session_with_hike();
  EXPECT_EQ(run(s, "print-camera"),
            "camera: pivot 46.700000,7.860000,1000.0 distance 3000.0 heading 10.00 pitch -40.00\n");
  EXPECT_EQ(run(s, "orbit 40 0"), "");
  EXPECT_EQ(run(s, "print-camera"),
            "camera: pivot 46.700000,7.860000,1000.0 distance 3000.0 heading 0.00 pitch -40.00\n");
  const std::optional<std::string> state = run(s, "print-state");
  ASSERT_TRUE(state.has_value());
  ASSERT_EQ(state->back(), '\n');
  const auto j = nlohmann::json::parse(*state);
  EXPECT_EQ(j["tracks"][0]["name"], "Hike");
  EXPECT_EQ(j["camera"]["heading"], 0.0);
  EXPECT_EQ(run(s, "print-hover"), "hover: none\n");
}

TEST(ScriptSession, SelectFliesThereAtOnceAndNamesTheLineWhenThereIsNoSuchTrack) {
  ViewerSession s = session_with_hike();
  EXPECT_EQ(run(s, "select 0"), "");
  EXPECT_FALSE(s.camera().animating()) << "scripted flights arrive at once";
  EXPECT_NEAR(s.camera().view().target.lat_deg, 46.70, 0.01);
  try {
    run(s, "select 3");
    FAIL() << "no track 3";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), "s.txt:1: select 3: there is 1 track (0..0)");
  }
}

TEST(ScriptSession, TheFrontEndsOwnCommandsAreLeftToIt) {
  ViewerSession s = session_with_hike();
  for (const char* line : {"hover 3 4", "wait 2", "screenshot a.png", "hide-panels", "record-film f.mp4 3"})
    EXPECT_FALSE(run(s, line).has_value()) << line;
  // The replay: played for 5 s at 100 times, then paused.
  EXPECT_EQ(run(s, "speed 100"), "");
  EXPECT_EQ(run(s, "play 5"), "");
  EXPECT_FALSE(s.model().clock.playing());
  EXPECT_NEAR(s.model().clock.time() - 1718704800.0, 500.0, 1e-6);
}

}  // namespace
}  // namespace trailray::ui
