#include "render/gl/gl_check.hpp"

#include <cstdio>

#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

std::string hex_code(std::string_view prefix, GLenum code) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04X", code);
  return std::string(prefix) + buffer;
}

}  // namespace

std::string gl_error_name(GLenum error) {
  switch (error) {
    case GL_NO_ERROR:
      return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return hex_code("GL error ", error);
  }
}

std::string framebuffer_status_text(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_COMPLETE:
      return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED:
      return "GL_FRAMEBUFFER_UNDEFINED (the default framebuffer does not exist)";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (an attachment is not renderable or has no storage)";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT (nothing is attached)";
    case GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS:
      return "GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS (attachments differ in size)";
    case GL_FRAMEBUFFER_UNSUPPORTED:
      return "GL_FRAMEBUFFER_UNSUPPORTED (this combination of formats is not supported by the driver)";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
      return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE (attachments differ in sample count)";
    default:
      return hex_code("framebuffer status ", status);
  }
}

std::string gl_format_name(GLenum internal_format) {
  switch (internal_format) {
    case GL_R8:
      return "GL_R8";
    case GL_RG8:
      return "GL_RG8";
    case GL_RGB8:
      return "GL_RGB8";
    case GL_RGBA8:
      return "GL_RGBA8";
    case GL_SRGB8_ALPHA8:
      return "GL_SRGB8_ALPHA8";
    case GL_RGB10_A2:
      return "GL_RGB10_A2";
    case GL_R16F:
      return "GL_R16F";
    case GL_RG16F:
      return "GL_RG16F";
    case GL_RGBA16F:
      return "GL_RGBA16F";
    case GL_R32F:
      return "GL_R32F";
    case GL_RG32F:
      return "GL_RG32F";
    case GL_RGBA32F:
      return "GL_RGBA32F";
    case GL_R11F_G11F_B10F:
      return "GL_R11F_G11F_B10F";
    case GL_R8UI:
      return "GL_R8UI";
    case GL_R32UI:
      return "GL_R32UI";
    case GL_RGBA8UI:
      return "GL_RGBA8UI";
    case GL_DEPTH_COMPONENT16:
      return "GL_DEPTH_COMPONENT16";
    case GL_DEPTH_COMPONENT24:
      return "GL_DEPTH_COMPONENT24";
    case GL_DEPTH_COMPONENT32F:
      return "GL_DEPTH_COMPONENT32F";
    case GL_DEPTH24_STENCIL8:
      return "GL_DEPTH24_STENCIL8";
    case GL_DEPTH32F_STENCIL8:
      return "GL_DEPTH32F_STENCIL8";
    case GL_STENCIL_INDEX8:
      return "GL_STENCIL_INDEX8";
    default:
      return hex_code("format ", internal_format);
  }
}

void check_gl_error(std::string_view what) {
  GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  std::string message = gl_error_name(first);
  // Several flags may be set at once; report them all, and leave none behind for the next check.
  for (int i = 0; i < 8; ++i) {
    const GLenum more = glGetError();
    if (more == GL_NO_ERROR) break;
    message += ", " + gl_error_name(more);
  }
  throw RenderError(message + " after " + std::string(what));
}

}  // namespace trailray::render
