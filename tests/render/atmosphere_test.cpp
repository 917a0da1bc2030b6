// The CPU side of the light model: the sun reddens and dims as it sinks, is gone below the
// horizon, and the sky light fades with it.
#include "render/passes/atmosphere.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace trailray::render {
namespace {

TEST(Atmosphere, AHighSunIsTheRenderersWhiteSun) {
  const glm::vec3 zenith = sun_radiance(90.0);
  EXPECT_NEAR(zenith.r, 1.0f, 1e-4f);
  EXPECT_NEAR(zenith.g, 0.97f, 1e-4f);
  EXPECT_NEAR(zenith.b, 0.92f, 1e-4f);
}

TEST(Atmosphere, TheSunReddensAndDimsAsItSinks) {
  double previous_ratio = 0.0, previous_green = 2.0;
  for (const double elevation : {90.0, 60.0, 30.0, 10.0, 3.0, 0.5}) {
    const glm::vec3 sun = sun_radiance(elevation);
    const double ratio = sun.r / sun.b;
    EXPECT_GT(ratio, previous_ratio) << elevation << " degrees";
    EXPECT_LT(sun.g, previous_green) << elevation << " degrees";
    previous_ratio = ratio;
    previous_green = sun.g;
  }
  // Near the horizon the blue is mostly gone (air mass ~27 at 0.5 degrees).
  EXPECT_LT(sun_radiance(0.5).b, 0.2f * sun_radiance(0.5).r);
}

TEST(Atmosphere, NoSunBelowTheHorizon) {
  const glm::vec3 set = sun_radiance(-1.0);
  EXPECT_EQ(set, glm::vec3(0.0f));
  EXPECT_GT(sun_radiance(0.1).r, 0.0f);  // half the disc still up
}

TEST(Atmosphere, TheSkyLightFadesWithTheSunButNotToBlack) {
  EXPECT_GT(sky_radiance(45.0).b, sky_radiance(10.0).b);
  EXPECT_GT(sky_radiance(10.0).b, sky_radiance(-3.0).b);
  EXPECT_GT(sky_radiance(-20.0).b, 0.0f);
  EXPECT_GT(sky_radiance(60.0).b, sky_radiance(60.0).r);  // bluish
}

TEST(Atmosphere, ElevationFromDirections) {
  EXPECT_NEAR(elevation_deg({0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}), 90.0, 1e-9);
  EXPECT_NEAR(elevation_deg({1.0, 0.0, 1.0}, {0.0, 0.0, 2.0}), 45.0, 1e-9);
  EXPECT_NEAR(elevation_deg({0.0, 1.0, -0.0}, {0.0, 0.0, 1.0}), 0.0, 1e-9);
}

}  // namespace
}  // namespace trailray::render
