// Camera paths from files (scene/film/camera_path): keyframes read with comments and both forms,
// errors naming FILE:LINE, the interpolation through every keyframe and smooth between them.

#include <gtest/gtest.h>

#include <cmath>

#include "geo/wgs84.hpp"
#include "scene/film/camera_path.hpp"

namespace trailray::scene {
namespace {

const char* kPath =
    "# a turn around Interlaken\n"
    "0s   look-at 46.68,7.86,600 3000 350 -30\n"
    "\n"
    "5s   look-at 46.68,7.86,600 2000 20 -40   # closer, turning through north\n"
    "10s  camera 46.70,7.80,2500,90,-20\n";

TEST(CameraPath, ReadsKeyframesAndPassesThroughThem) {
  const auto keys = parse_camera_path(kPath, "path.txt");
  ASSERT_TRUE(keys.ok()) << keys.error;
  ASSERT_EQ(keys.value->size(), 3u);
  EXPECT_DOUBLE_EQ((*keys.value)[1].film_s, 5.0);
  const FilmLook at5 = camera_path_look(*keys.value, 5.0);
  EXPECT_NEAR(at5.distance_m, 2000.0, 1e-6);
  EXPECT_NEAR(at5.heading_deg, 20.0, 1e-6);
  // The camera keyframe puts the camera where it says.
  const FilmLook at10 = camera_path_look(*keys.value, 10.0);
  const geo::Geodetic c = geo::geodetic_from_ecef(camera_position(at10));
  EXPECT_NEAR(c.lat_deg, 46.70, 1e-4);
  EXPECT_NEAR(c.lon_deg, 7.80, 1e-4);
  EXPECT_NEAR(c.height_m, 2500.0, 1.0);
  // Between 0 s and 5 s the heading turns the short way through north (350 -> 20), never
  // swinging through south.
  for (double t = 0.0; t <= 5.0; t += 0.25) {
    const double h = camera_path_look(*keys.value, t).heading_deg;
    EXPECT_TRUE(h >= 340.0 || h <= 30.0) << t << " s: " << h;
  }
  // Before the first and after the last keyframe: held.
  EXPECT_NEAR(camera_path_look(*keys.value, -1.0).heading_deg, 350.0, 1e-9);
  EXPECT_NEAR(camera_path_look(*keys.value, 60.0).heading_deg, 90.0, 1e-6);
}

TEST(CameraPath, ErrorsNameTheFileAndLine) {
  struct Case {
    const char* text;
    const char* where;
  };
  const Case cases[] = {
      {"0s look-at 46.68,7.86,600 3000 350 -30\nsoon camera 46.70,7.80,2500,90,-20\n", "path.txt:2:"},
      {"0s look-at 46.68,7.86,600 3000 350 -30\n\n5s look-at 46.68,7.86,600 -3 350 -30\n", "path.txt:3:"},
      {"0s look-at 46.68,7.86,600 3000 350 -100\n", "path.txt:1:"},
      {"5s camera 46.70,7.80,2500,90,-20\n2s camera 46.70,7.80,2500,90,-20\n", "path.txt:2:"},
      {"0s camera 46.70,7.80,2500\n", "path.txt:1:"},
      {"0s fly 46.70,7.80,2500\n", "path.txt:1:"},
      {"# nothing\n", "path.txt:1:"},
  };
  for (const Case& c : cases) {
    const auto keys = parse_camera_path(c.text, "path.txt");
    EXPECT_FALSE(keys.ok()) << c.text;
    EXPECT_EQ(keys.error.rfind(c.where, 0), 0u) << c.text << " -> " << keys.error;
  }
}

}  // namespace
}  // namespace trailray::scene
