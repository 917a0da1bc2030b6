// Drawing with the embedded shaders and reading the pixels back: exact values, which way is up.

#include "render/gl/framebuffer_readback.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "gl_test_support.hpp"
#include "render/gl/render_error.hpp"
#include "render/gl/shader_program.hpp"

namespace trailray::render {
namespace {

using test::GlTest;
using test::RgbaTarget;
using Pixel = std::array<std::uint8_t, 4>;

void draw_fullscreen_triangle(const ShaderProgram& program) {
  const VertexArray no_attributes = VertexArray::create();  // positions come from gl_VertexID
  program.use();
  glBindVertexArray(no_attributes.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

// The 8-bit value GL stores for a normalized float (ES 3.0 §2.3.4.1: round to nearest).
std::uint8_t unorm8(float value) { return static_cast<std::uint8_t>(std::lround(value * 255.0f)); }

class FramebufferReadback : public GlTest {};

TEST_F(FramebufferReadback, AClearColourReadsBackExactly) {
  const RgbaTarget target(13, 7);  // odd sizes: no row padding hides a mistake
  glClearColor(10 / 255.0f, 128 / 255.0f, 250 / 255.0f, 77 / 255.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const scene::RgbaImage image = read_rgba8(0, 0, target.width, target.height);
  ASSERT_EQ(image.width, 13u);
  ASSERT_EQ(image.height, 7u);
  ASSERT_EQ(image.rgba.size(), 13u * 7u * 4u);
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x)
      ASSERT_EQ(image.pixel(x, y), (Pixel{10, 128, 250, 77})) << x << "," << y;
}

TEST_F(FramebufferReadback, RowsComeBackTopDown) {
  const RgbaTarget target(6, 4);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  // GL's row 0 is the bottom: paint it red; in the image it must be the last row.
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 6, 1);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  const scene::RgbaImage image = read_rgba8(0, 0, 6, 4);
  EXPECT_EQ(image.pixel(0, 3), (Pixel{255, 0, 0, 255}));
  EXPECT_EQ(image.pixel(5, 3), (Pixel{255, 0, 0, 255}));
  EXPECT_EQ(image.pixel(0, 0), (Pixel{0, 0, 255, 255}));
  EXPECT_EQ(image.pixel(0, 2), (Pixel{0, 0, 255, 255}));
  // A sub-rectangle: GL's x 2..4, rows 0..1 -> an image whose bottom row is the red one.
  const scene::RgbaImage part = read_rgba8(2, 0, 3, 2);
  ASSERT_EQ(part.width, 3u);
  ASSERT_EQ(part.height, 2u);
  EXPECT_EQ(part.pixel(0, 1), (Pixel{255, 0, 0, 255}));
  EXPECT_EQ(part.pixel(2, 0), (Pixel{0, 0, 255, 255}));
}

TEST_F(FramebufferReadback, TheFullscreenTriangleCoversEveryPixel) {
  const RgbaTarget target(31, 17);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  const ShaderProgram program = ShaderProgram::from_embedded("fullscreen_triangle.vert", "solid_color.frag");
  program.set_vec4("u_color", 0.2f, 0.4f, 0.6f, 0.8f);
  draw_fullscreen_triangle(program);
  const scene::RgbaImage image = read_rgba8(0, 0, target.width, target.height);
  const Pixel expected{unorm8(0.2f), unorm8(0.4f), unorm8(0.6f), unorm8(0.8f)};
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) ASSERT_EQ(image.pixel(x, y), expected) << x << "," << y;
}

TEST_F(FramebufferReadback, TheGradientPutsEachPixelCentreWhereItBelongs) {
  const RgbaTarget target(16, 8);
  const ShaderProgram program = ShaderProgram::from_embedded("fullscreen_triangle.vert", "uv_gradient.frag");
  draw_fullscreen_triangle(program);
  const scene::RgbaImage image = read_rgba8(0, 0, target.width, target.height);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      // Pixel centres in GL's window coordinates; image row y is GL row height - 1 - y.
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(image.width);
      const float v = (static_cast<float>(image.height - 1 - y) + 0.5f) / static_cast<float>(image.height);
      const Pixel pixel = image.pixel(x, y);
      // Interpolation in float, then rounding: one step of 8 bits either way.
      ASSERT_LE(std::abs(pixel[0] - unorm8(u)), 1) << x << "," << y;
      ASSERT_LE(std::abs(pixel[1] - unorm8(v)), 1) << x << "," << y;
      ASSERT_EQ(pixel[2], 0);
      ASSERT_EQ(pixel[3], 255);
    }
  }
  // The top-left of the picture is near u = 0, v = 1: little red, much green.
  EXPECT_LT(image.pixel(0, 0)[0], 16);
  EXPECT_GT(image.pixel(0, 0)[1], 224);
}

TEST_F(FramebufferReadback, TheShadersSrgbCurveMatchesTheCpus) {
  const RgbaTarget target(1, 1);
  const ShaderProgram program = ShaderProgram::from_embedded("fullscreen_triangle.vert", "encode_srgb.frag");
  for (float linear : {0.0f, 0.001f, 0.0031308f, 0.01f, 0.05f, 0.18f, 0.214f, 0.5f, 0.8f, 1.0f, 1.5f}) {
    program.set_vec4("u_linear_color", linear, linear * 0.5f, 1.0f - linear, 1.0f);
    draw_fullscreen_triangle(program);
    const Pixel pixel = read_rgba8(0, 0, 1, 1).pixel(0, 0);
    // The GPU's pow is not correctly rounded; one 8-bit step is what that can cost.
    EXPECT_LE(std::abs(pixel[0] - scene::linear_to_srgb8(linear)), 1) << linear;
    EXPECT_LE(std::abs(pixel[1] - scene::linear_to_srgb8(linear * 0.5f)), 1) << linear;
    EXPECT_LE(std::abs(pixel[2] - scene::linear_to_srgb8(1.0f - linear)), 1) << linear;
  }
}

TEST_F(FramebufferReadback, ReadingWithoutAFramebufferOrPixelsIsAClearError) {
  const RgbaTarget target(4, 4);
  EXPECT_THROW(read_rgba8(0, 0, 0, 4), RenderError);
  const Framebuffer empty = Framebuffer::create();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, empty.id());
  try {
    read_rgba8(0, 0, 4, 4);
    FAIL() << "read from a framebuffer without attachments";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("framebuffer 'read back' is incomplete"), std::string::npos)
        << error.what();
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer.id());
}

TEST_F(FramebufferReadback, APixelPackBufferDoesNotCatchThePixels) {
  const RgbaTarget target(2, 2);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const Buffer pack = Buffer::create();
  glBindBuffer(GL_PIXEL_PACK_BUFFER, pack.id());
  glBufferData(GL_PIXEL_PACK_BUFFER, 64, nullptr, GL_STREAM_READ);
  EXPECT_EQ(read_rgba8(0, 0, 2, 2).pixel(1, 1), (Pixel{0, 255, 0, 255}));
  GLint bound = 0;
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &bound);
  EXPECT_EQ(static_cast<GLuint>(bound), pack.id());  // restored
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
}

}  // namespace
}  // namespace trailray::render
