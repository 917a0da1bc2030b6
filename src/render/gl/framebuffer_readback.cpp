#include "render/gl/framebuffer_readback.hpp"

#include <string>

#include "render/gl/gl_check.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render {

scene::RgbaImage read_rgba8(int x, int y, int width, int height) {
  if (width < 1 || height < 1)
    throw RenderError("cannot read " + std::to_string(width) + " x " + std::to_string(height) +
                      " pixels from a framebuffer: the rectangle is empty");
  check_framebuffer_complete(GL_READ_FRAMEBUFFER, "read back");
  check_gl_error("an earlier GL call (found before reading pixels back)");
  scene::RgbaImage image;
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  image.rgba.resize(std::size_t{image.width} * image.height * 4);
  // With a pixel-pack buffer bound, glReadPixels would write into it at offset `data`.
  GLint pack_buffer = 0;
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack_buffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);  // RGBA8 rows are whole multiples of 4 bytes
  glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer));
  check_gl_error("glReadPixels of " + std::to_string(width) + " x " + std::to_string(height) + " RGBA8 pixels at (" +
                 std::to_string(x) + ", " + std::to_string(y) + ")");
  scene::flip_rows(image.rgba, std::size_t{image.width} * 4);
  return image;
}

}  // namespace trailray::render
