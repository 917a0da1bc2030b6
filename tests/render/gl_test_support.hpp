#pragma once
// What the render tests share: one headless GL context per test suite (llvmpipe in CI), and a
// small RGBA8 render target to draw into and read back.

#include <gtest/gtest.h>

#include <optional>

#include "render/platform/gl_context.hpp"
#include "render/gl/gl_objects.hpp"

namespace trailray::render::test {

// A fixture whose tests run with a current OpenGL ES 3 context.
class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context() = GlContext::create_headless(); }
  static void TearDownTestSuite() { context().reset(); }
  void SetUp() override { context()->make_current(); }
  void TearDown() override {
    // A test that leaves a GL error behind has a bug, even when its checks passed.
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "a GL error was left set";
  }
  static std::optional<GlContext>& context() {
    static std::optional<GlContext> instance;
    return instance;
  }
};

// A framebuffer with one RGBA8 colour texture, bound (draw and read) with the viewport set.
struct RgbaTarget {
  Texture color;
  Framebuffer framebuffer;
  int width, height;

  RgbaTarget(int w, int h)
      : color(make_texture_2d(GL_RGBA8, w, h)), framebuffer(Framebuffer::create()), width(w), height(h) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
    check_framebuffer_complete(GL_FRAMEBUFFER, "test target");
    glViewport(0, 0, w, h);
  }
};

}  // namespace trailray::render::test
