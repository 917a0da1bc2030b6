// The headless context: creation on whatever EGL offers (llvmpipe here), capabilities, errors.

#include "render/platform/gl_context.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "render/gl/gl_api.hpp"

namespace trailray::render {
namespace {

bool contains(const std::string& text, std::string_view part) { return text.find(part) != std::string::npos; }

TEST(GlContext, CreatesACurrentEs3ContextAndQueriesItsCapabilities) {
  const GlContext context = GlContext::create_headless();
  EXPECT_TRUE(context.is_current());
  const GlCapabilities& caps = context.capabilities();
  EXPECT_GE(caps.major_version, 3);
  EXPECT_FALSE(caps.renderer.empty());
  EXPECT_TRUE(caps.version.starts_with("OpenGL ES 3.")) << caps.version;
  // What the capability struct says is what GL answers now.
  EXPECT_EQ(caps.renderer, reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  EXPECT_EQ(caps.extensions.size(), static_cast<std::size_t>(count));
  EXPECT_TRUE(std::is_sorted(caps.extensions.begin(), caps.extensions.end()));
  EXPECT_GE(caps.max_texture_size, 2048);  // the ES 3.0 minimum
  EXPECT_GE(caps.max_draw_buffers, 4);
  EXPECT_GE(caps.max_color_attachments, 4);
  // Flags agree with the extension list, with or without the GL_ prefix.
  EXPECT_EQ(caps.color_buffer_float, caps.has_extension("GL_EXT_color_buffer_float"));
  EXPECT_EQ(caps.color_buffer_float, caps.has_extension("EXT_color_buffer_float"));
  EXPECT_EQ(caps.disjoint_timer_query, caps.has_extension("EXT_disjoint_timer_query"));
  EXPECT_EQ(caps.texture_float_linear, caps.has_extension("OES_texture_float_linear"));
  EXPECT_FALSE(caps.has_extension("GL_TRAILRAY_no_such_extension"));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(GlContext, DescribeGivesTheLinesVerboseLogs) {
  const GlContext context = GlContext::create_headless();
  const std::vector<std::string> lines = context.describe();
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_TRUE(lines[0].starts_with("EGL 1.")) << lines[0];
  EXPECT_TRUE(contains(lines[0], std::string(to_string(context.platform())) + " platform")) << lines[0];
  EXPECT_TRUE(contains(lines[1], context.capabilities().renderer)) << lines[1];
  EXPECT_TRUE(contains(lines[2], context.capabilities().version)) << lines[2];
  const std::string expected_float =
      std::string("EXT_color_buffer_float ") + (context.capabilities().color_buffer_float ? "yes" : "no");
  EXPECT_TRUE(contains(lines[3], expected_float)) << lines[3];
  EXPECT_TRUE(contains(lines[3], "EXT_disjoint_timer_query")) << lines[3];
  EXPECT_TRUE(contains(lines[4], "texture " + std::to_string(context.capabilities().max_texture_size))) << lines[4];
}

TEST(GlContext, MesaSurfacelessIsUsedWhenAskedFor) {
  // CI renders with Mesa (DESIGN.md); its surfaceless platform is the fallback everywhere.
  HeadlessContextOptions options;
  options.platform = EglPlatform::surfaceless;
  const GlContext context = GlContext::create_headless(options);
  EXPECT_EQ(context.platform(), EglPlatform::surfaceless);
  EXPECT_TRUE(contains(context.egl_description(), "surfaceless platform")) << context.egl_description();
  EXPECT_GE(context.capabilities().major_version, 3);
}

TEST(GlContext, AContextNoDriverCanMakeNamesEveryAttempt) {
  try {
    GlContext::create_headless({.platform = std::nullopt, .gles_major = 9, .gles_minor = 1});
    FAIL() << "an OpenGL ES 9.1 context was created";
  } catch (const RenderError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.starts_with("no OpenGL ES 9.1 context through EGL: tried ")) << message;
    // Each display EGL offered is named with the call that failed on it.
    EXPECT_TRUE(contains(message, "Mesa surfaceless: ")) << message;
    EXPECT_TRUE(contains(message, "eglCreateContext failed (EGL_")) << message;
    EXPECT_TRUE(contains(message, "libegl-mesa0")) << message;
  }
  // A failed attempt leaves EGL usable.
  EXPECT_NO_THROW(GlContext::create_headless());
}

TEST(GlContext, TwoContextsShareADisplayAndOutliveEachOther) {
  GlContext first = GlContext::create_headless();
  {
    const GlContext second = GlContext::create_headless();
    EXPECT_TRUE(second.is_current());
    EXPECT_FALSE(first.is_current());
  }
  // Destroying the second must not have terminated the display the first one lives on.
  first.make_current();
  EXPECT_TRUE(first.is_current());
  ASSERT_NE(glGetString(GL_RENDERER), nullptr);
  EXPECT_EQ(first.capabilities().renderer, reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
}

TEST(GlContext, MovingKeepsTheContextAndEmptiesTheSource) {
  GlContext original = GlContext::create_headless();
  const std::string renderer = original.capabilities().renderer;
  GlContext moved = std::move(original);
  EXPECT_TRUE(moved.is_current());
  EXPECT_FALSE(original.is_current());                 // NOLINT(bugprone-use-after-move): a moved-from context is empty
  EXPECT_THROW(original.make_current(), RenderError);  // NOLINT(bugprone-use-after-move): an error, not a crash
  EXPECT_THROW(original.capabilities(), RenderError);  // NOLINT(bugprone-use-after-move)
  EXPECT_EQ(moved.capabilities().renderer, renderer);
  GlContext assigned = GlContext::create_headless();
  assigned = std::move(moved);  // releases the context `assigned` held
  assigned.make_current();
  EXPECT_EQ(assigned.capabilities().renderer, reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
}

TEST(GlCapabilities, ParsesTheEsVersionString) {
  EXPECT_EQ(parse_gles_version("OpenGL ES 3.2 Mesa 22.3.6"), std::make_pair(3, 2));
  EXPECT_EQ(parse_gles_version("OpenGL ES 3.0 (ANGLE 2.1)"), std::make_pair(3, 0));
  EXPECT_EQ(parse_gles_version("OpenGL ES 3.2 NVIDIA 535.104.05"), std::make_pair(3, 2));
  EXPECT_EQ(parse_gles_version("OpenGL ES 10.15"), std::make_pair(10, 15));
  EXPECT_EQ(parse_gles_version("4.6.0 NVIDIA 535.104.05"), std::nullopt);  // desktop GL
  EXPECT_EQ(parse_gles_version("OpenGL ES-CM 1.1"), std::nullopt);         // ES 1 profile
  EXPECT_EQ(parse_gles_version("OpenGL ES 3"), std::nullopt);
  EXPECT_EQ(parse_gles_version(""), std::nullopt);
}

TEST(GlCapabilities, TellsSoftwareRenderers) {
  GlCapabilities caps;
  caps.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
  EXPECT_TRUE(caps.is_software());
  caps.renderer = "NVIDIA H200/PCIe/SSE2";
  EXPECT_FALSE(caps.is_software());
}

}  // namespace
}  // namespace trailray::render
