#pragma once
// Pixels out of GL: read an RGBA8 framebuffer (GL's rows run bottom-up, images' top-down) into a
// scene::RgbaImage, which encodes and writes it (scene/pictures/rgba_image.hpp).

#include "render/gl/gl_api.hpp"
#include "scene/pictures/rgba_image.hpp"

namespace trailray::render {

// Reads the rectangle (x, y, width, height) of colour attachment 0 of the framebuffer bound
// to GL_READ_FRAMEBUFFER (x, y: GL's window coordinates, from the bottom-left), as RGBA8 with the
// rows flipped to top-down. The attachment must be a normalized fixed-point format (RGBA8,
// RGB10_A2, ...: ES 3.0 reads all of them as RGBA8). Throws RenderError for an incomplete
// framebuffer, a rectangle of no pixels, or a GL error.
scene::RgbaImage read_rgba8(int x, int y, int width, int height);

}  // namespace trailray::render
