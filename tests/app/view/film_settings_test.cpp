// The viewer's "record film" settings (app/view/film_settings): the default file name from the
// first track's, what stops a recording before it starts, and which track a follow camera follows.
#include "app/view/film_settings.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "terrain/tile_fixtures.hpp"

namespace trailray::app::view {
namespace {

scene::Track track_named(const std::string& name, bool timed, bool route = false) {
  scene::Track t;
  t.name = name;
  t.is_route = route;
  t.time_unix_s = {timed ? 1718704800.0 : std::nan("")};
  if (timed) t.timed_points = {0};
  return t;
}

TEST(FilmSettings, TheDefaultsAreA720pMinuteAt30FpsBehindTheTrack) {
  const FilmSettings s;
  EXPECT_EQ(s.width, 1280);
  EXPECT_EQ(s.height, 720);
  EXPECT_EQ(s.seconds, 60.0);
  EXPECT_EQ(s.fps, 30.0);
  EXPECT_EQ(s.camera, FilmCamera::follow);
  EXPECT_FALSE(s.replace);
}

TEST(FilmSettings, TheDefaultFileIsNamedAfterTheFirstTrack) {
  scene::TrackSet tracks;
  EXPECT_EQ(default_film_path(tracks), "trailray-film.mp4");
  tracks.add(track_named("Flight 2023-10-02 from Amisbühl", true));
  tracks.add(track_named("Other", true));
  EXPECT_EQ(default_film_path(tracks), "trailray-film-Flight-2023-10-02-from-Amisb-hl.mp4");
  scene::TrackSet odd;
  odd.add(track_named("../../etc/passwd ", true));
  EXPECT_EQ(default_film_path(odd), "trailray-film-etc-passwd.mp4");  // stays in the current folder
  scene::TrackSet nothing_left;
  nothing_left.add(track_named("//", true));
  EXPECT_EQ(default_film_path(nothing_left), "trailray-film.mp4");
}

TEST(FilmSettings, ProblemsAreNamedBeforeTheRecordingStarts) {
  test::TempDir dir;
  FilmSettings s;
  s.path = (dir.path() / "film.mp4").string();
  EXPECT_EQ(film_settings_problem(s), "");
  s.path = (dir.path() / "film.avi").string();
  EXPECT_NE(film_settings_problem(s).find(".mp4 (H.264) or .webm"), std::string::npos);
  s.path = (dir.path() / "film.webm").string();
  std::ofstream(s.path) << "an earlier film";
  EXPECT_NE(film_settings_problem(s).find("already exists"), std::string::npos);
  s.replace = true;
  EXPECT_EQ(film_settings_problem(s), "");
  s.width = 1281;
  EXPECT_NE(film_settings_problem(s).find("1281x720"), std::string::npos);
  s.width = 1280;
  s.seconds = 0.0;
  EXPECT_NE(film_settings_problem(s).find("length"), std::string::npos);
  s.seconds = 10.0;
  s.fps = 0.5;
  EXPECT_NE(film_settings_problem(s).find("frames per second"), std::string::npos);
  s.fps = 30.0;
  s.path.clear();
  EXPECT_NE(film_settings_problem(s), "");
}

TEST(FilmSettings, TheFollowedTrackHasTimes) {
  scene::TrackSet tracks;
  tracks.add(track_named("route", false, true));
  tracks.add(track_named("untimed", false));
  tracks.add(track_named("first timed", true));
  tracks.add(track_named("second timed", true));
  FilmSettings s;
  EXPECT_EQ(film_follow_track(s, tracks, -1), 2u);  // nothing chosen: the first with times
  EXPECT_EQ(film_follow_track(s, tracks, 3), 3u);   // the viewer's (replay or selection)
  EXPECT_EQ(film_follow_track(s, tracks, 1), 2u);   // ... unless it has no times
  s.follow_track = 2;
  EXPECT_EQ(film_follow_track(s, tracks, 3), 2u);  // the film window's own choice first
  s.follow_track = 0;                              // a route: no times
  EXPECT_EQ(film_follow_track(s, tracks, 3), 3u);
}

}  // namespace
}  // namespace trailray::app::view
