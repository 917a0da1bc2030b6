// A frame's passes run in KHR_debug groups named after them, in the frame's order (what a GL
// debugger shows), when the context has KHR_debug.
#include "render/gl/debug_group.hpp"

#include <EGL/egl.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl_test_support.hpp"
#include "render/gl/gl_api.hpp"
#include "render/renderer.hpp"
#include "scene_test_support.hpp"
#include "track_test_support.hpp"

namespace trailray::render {
namespace {

std::vector<std::string>* g_groups = nullptr;

void GL_APIENTRY collect(GLenum, GLenum type, GLuint, GLenum, GLsizei length, const GLchar* message, const void*) {
  if (type == GL_DEBUG_TYPE_PUSH_GROUP_KHR && g_groups != nullptr) g_groups->emplace_back(message, length);
}

class DebugGroupTest : public test::GlTest {};

TEST_F(DebugGroupTest, EachPassOfAFrameIsAGroupInOrder) {
  if (!query_gl_capabilities().debug_output) GTEST_SKIP() << "no KHR_debug";
  auto callback = reinterpret_cast<PFNGLDEBUGMESSAGECALLBACKKHRPROC>(eglGetProcAddress("glDebugMessageCallbackKHR"));
  ASSERT_NE(callback, nullptr);
  std::vector<std::string> groups;
  g_groups = &groups;
  glEnable(GL_DEBUG_OUTPUT_KHR);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR);
  callback(collect, nullptr);

  constexpr scene::GeoPosition kPlace{46.5, 10.0, 0.0};
  const test::LocalFrame frame(kPlace);
  const scene::TrackSet tracks =
      test::track_set({test::track_of(test::geometry_of({test::polyline(frame, {{-50, 0, 800}, {50, 0, 800}})}))});
  scene::Scene scene = test::lit_scene(test::sun_from(kPlace.lat_deg, kPlace.lon_deg, 180.0, 60.0));
  scene.tracks = &tracks;
  test::SceneDrawer drawer(nullptr, nullptr);
  drawer.draw(test::looking_down({kPlace.lat_deg, kPlace.lon_deg, 1000.0}, scene::Lens{30.0, 64, 48}, 10.0), scene);

  callback(nullptr, nullptr);
  glDisable(GL_DEBUG_OUTPUT_KHR);
  g_groups = nullptr;
  const std::vector<std::string> expected{"shadows", "tiles", "tracks", "ssao", "compose", "overlays", "output"};
  EXPECT_EQ(groups, expected);
}

}  // namespace
}  // namespace trailray::render
