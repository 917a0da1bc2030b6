// Cascaded shadow maps on the GL (llvmpipe in CI): walls standing on a plane cast their shadows
// away from the sun, measured at known points through shadows.glsl (shadow_probe.frag), in the
// first cascade and in a far one; the plane does not shadow itself (no acne).

#include "render/passes/shadow_maps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gl_test_support.hpp"
#include "render/gl/gl_check.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

using test::GlTest;

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr int kMapSize = 1024;

const scene::GeoPosition kCameraPosition{46.69, 7.86, 600.0};

// A scene in the tangent plane at the camera's foot: east, north, up axes and the foot itself.
struct Scene {
  scene::Camera camera{scene::ecef_from(kCameraPosition), 0.0, -20.0, scene::Lens{45.0, 320, 180}, scene::DepthRange{50.0, 100'000.0}};
  scene::EnuAxes enu = scene::enu_axes_at(kCameraPosition.lat_deg, kCameraPosition.lon_deg);
  glm::dvec3 foot = scene::ecef_from(scene::GeoPosition{kCameraPosition.lat_deg, kCameraPosition.lon_deg, 0.0});
  // The sun due east, 30 degrees high: a wall of height h casts a shadow h / tan(30) long, westwards.
  glm::dvec3 sun = std::cos(30.0 * kRadPerDeg) * enu.east + std::sin(30.0 * kRadPerDeg) * enu.up;

  // A point on the plane, `east_m` and `north_m` from the foot.
  glm::dvec3 ground(double east_m, double north_m) const { return foot + east_m * enu.east + north_m * enu.north; }
  glm::vec3 relative(const glm::dvec3& p) const { return glm::vec3(p - camera.position()); }
};

// Triangles (camera-relative float positions) in a buffer, drawn with the shadow caster program.
class Casters {
 public:
  explicit Casters(const std::vector<glm::vec3>& triangles)
      : vertex_array_(VertexArray::create()),
        buffer_(Buffer::create()),
        count_(static_cast<GLsizei>(triangles.size())) {
    glBindVertexArray(vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size() * sizeof(glm::vec3)), triangles.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  }
  void draw(const ShaderProgram& program, const std::array<float, 16>& matrix) const {
    program.set_mat4("u_light_view_projection", matrix);
    glBindVertexArray(vertex_array_.id());
    glDrawArrays(GL_TRIANGLES, 0, count_);
    glBindVertexArray(0);
  }

 private:
  VertexArray vertex_array_;
  Buffer buffer_;
  GLsizei count_;
};

void add_quad(std::vector<glm::vec3>& out, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
              const glm::vec3& d) {
  for (const glm::vec3& v : {a, b, c, a, c, d}) out.push_back(v);
}

// The ground plane, 10 km wide and 20 km deep, and optionally two north-south walls: one 100 m
// high 2 km ahead (first cascade), one 400 m high 12 km ahead (a far cascade).
std::vector<glm::vec3> scene_triangles(const Scene& s, bool with_walls) {
  std::vector<glm::vec3> triangles;
  add_quad(triangles, s.relative(s.ground(-5'000, -5'000)), s.relative(s.ground(5'000, -5'000)),
           s.relative(s.ground(5'000, 15'000)), s.relative(s.ground(-5'000, 15'000)));
  if (with_walls) {
    auto wall = [&](double north_m, double half_length_m, double height_m) {
      const glm::dvec3 up = s.enu.up * height_m;
      const glm::dvec3 south = s.ground(0.0, north_m - half_length_m), north = s.ground(0.0, north_m + half_length_m);
      add_quad(triangles, s.relative(south), s.relative(north), s.relative(north + up), s.relative(south + up));
    };
    wall(2'000.0, 300.0, 100.0);
    wall(12'000.0, 1'500.0, 400.0);
  }
  return triangles;
}

struct Probe {
  std::string name;
  glm::dvec3 position;
};

struct ProbeResult {
  double visibility;
  int cascade;
};

// Renders the shadow maps of the scene and reads the sun's visibility at each probe (at most 8).
std::vector<ProbeResult> measure(const Scene& s, bool with_walls, const std::vector<Probe>& probes) {
  ShadowCascadeSettings settings;
  settings.map_size_px = kMapSize;
  settings.caster_height_span_m = 500.0;
  const ShadowCascades cascades(s.camera, s.sun, settings);
  const ShadowMaps maps(kMapSize);
  const Casters casters(scene_triangles(s, with_walls));
  maps.render(cascades, [&](const std::array<float, 16>& matrix) { casters.draw(maps.caster_program(), matrix); });

  const test::RgbaTarget target(8, 1);
  const ShaderProgram probe = ShaderProgram::from_embedded("fullscreen_triangle.vert", "shadow_probe.frag");
  maps.bind_for_lookup(probe, cascades, 1);
  for (std::size_t i = 0; i < 8; ++i) {
    const glm::dvec3 p = probes[std::min(i, probes.size() - 1)].position;
    const glm::vec3 rel = s.relative(p);
    probe.set_vec3("u_probe_positions[" + std::to_string(i) + "]", rel.x, rel.y, rel.z);
    const double depth = glm::dot(p - s.camera.position(), s.camera.axes().forward);
    probe.set_float("u_probe_view_depths_m[" + std::to_string(i) + "]", static_cast<float>(depth));
  }
  const glm::vec3 up(s.enu.up), sun(s.sun);
  probe.set_vec3("u_probe_normal", up.x, up.y, up.z);
  probe.set_vec3("u_sun_direction", sun.x, sun.y, sun.z);
  const VertexArray empty = VertexArray::create();
  glBindVertexArray(empty.id());
  glDisable(GL_DEPTH_TEST);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  std::array<std::uint8_t, 8 * 4> pixels{};
  glReadPixels(0, 0, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  check_gl_error("probing the shadows");
  std::vector<ProbeResult> results;
  for (std::size_t i = 0; i < probes.size(); ++i)
    results.push_back({pixels[i * 4] / 255.0, static_cast<int>(std::lround(pixels[i * 4 + 1] / 255.0 * 4.0))});
  return results;
}

class ShadowMapsTest : public GlTest {};

TEST_F(ShadowMapsTest, WallsShadowTheGroundAwayFromTheSunAndNothingElse) {
  const Scene s;
  const std::vector<Probe> probes = {
      {"50 m west of the near wall (in its 173 m shadow: no gap at the wall's foot)", s.ground(-50.0, 2'000.0)},
      {"120 m west of the near wall (in its shadow)", s.ground(-120.0, 2'100.0)},
      {"80 m east of the near wall (sun side)", s.ground(80.0, 2'000.0)},
      {"300 m west of the near wall (beyond its shadow)", s.ground(-300.0, 2'000.0)},
      {"80 m west, north of the near wall's end", s.ground(-80.0, 2'500.0)},
      {"300 m west of the far wall (in its 693 m shadow)", s.ground(-300.0, 12'000.0)},
      {"300 m east of the far wall (sun side)", s.ground(300.0, 12'000.0)},
      {"1200 m west of the far wall (beyond its shadow)", s.ground(-1'200.0, 12'000.0)},
  };
  const std::vector<bool> expect_shadow = {true, true, false, false, false, true, false, false};
  const auto with_walls = measure(s, true, probes);
  const auto plane_only = measure(s, false, probes);
  for (std::size_t i = 0; i < probes.size(); ++i) {
    if (expect_shadow[i])
      EXPECT_LT(with_walls[i].visibility, 0.1) << probes[i].name;
    else
      EXPECT_GT(with_walls[i].visibility, 0.9) << probes[i].name;
    // Without the walls the plane is lit everywhere: it does not shadow itself (no acne).
    EXPECT_GT(plane_only[i].visibility, 0.9) << probes[i].name << ", plane only";
  }
  // The near wall's probes are in the first cascade, the far wall's in a later one.
  EXPECT_EQ(with_walls[0].cascade, 0);
  EXPECT_GE(with_walls[5].cascade, 2);
  EXPECT_LT(with_walls[5].cascade, 4);
}

TEST_F(ShadowMapsTest, RenderingLeavesTheCallersFramebufferAndViewportAsFound) {
  const Scene s;
  ShadowCascadeSettings settings;
  settings.map_size_px = 64;
  const ShadowCascades cascades(s.camera, s.sun, settings);
  const ShadowMaps maps(64);
  const test::RgbaTarget target(5, 3);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_DEPTH_TEST);
  int calls = 0;
  maps.render(cascades, [&](const std::array<float, 16>& matrix) {
    // Each cascade's own matrix, drawing into the shadow map's framebuffer at the map's size.
    EXPECT_EQ(matrix, cascades.camera_relative_matrix(static_cast<std::size_t>(calls)));
    std::array<GLint, 4> viewport{};
    glGetIntegerv(GL_VIEWPORT, viewport.data());
    EXPECT_EQ(viewport[2], 64);
    ++calls;
  });
  EXPECT_EQ(calls, static_cast<int>(kShadowCascadeCount));
  GLint framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  EXPECT_EQ(static_cast<GLuint>(framebuffer), target.framebuffer.id());
  std::array<GLint, 4> viewport{};
  glGetIntegerv(GL_VIEWPORT, viewport.data());
  EXPECT_EQ(viewport, (std::array<GLint, 4>{0, 0, 5, 3}));
  GLint depth_func = 0;
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func);
  EXPECT_EQ(depth_func, GL_LEQUAL);
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
  glDepthFunc(GL_LESS);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(ShadowMapsTest, MismatchedSizesAreClearErrors) {
  const Scene s;
  const ShadowMaps maps(128);
  const ShadowCascades cascades(s.camera, s.sun);  // 2048 px by default
  try {
    maps.render(cascades, [](const std::array<float, 16>&) {});
    FAIL() << "cascades for 2048 px maps were rendered into 128 px maps";
  } catch (const RenderError& error) {
    EXPECT_STREQ(error.what(), "shadow cascades computed for 2048 px maps cannot be rendered into 128 px shadow maps");
  }
  try {
    const ShadowMaps tiny(4);
    FAIL() << "4 px shadow maps were made";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("cannot make 4 x 4 shadow maps: each side must be 16.."),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace trailray::render
