#include "render/gl/gl_objects.hpp"

#include <string>

#include "render/gl/gl_check.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

GLuint require_name(GLuint id, std::string_view kind) {
  if (id == 0) throw RenderError("GL created no " + std::string(kind) + " (is a GL context current on this thread?)");
  return id;
}

std::string size_text(GLenum internal_format, int width, int height) {
  return std::to_string(width) + " x " + std::to_string(height) + " " + gl_format_name(internal_format);
}

void check_size(std::string_view kind, GLenum internal_format, int width, int height, GLenum max_size_query) {
  GLint max_size = 0;
  glGetIntegerv(max_size_query, &max_size);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw RenderError("cannot make a " + size_text(internal_format, width, height) + " " + std::string(kind) +
                      ": each side must be 1.." + std::to_string(max_size) + " pixels on this GL");
}

}  // namespace

namespace gl_traits {

GLuint Buffer::create() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  return require_name(id, "buffer");
}
void Buffer::destroy(GLuint id) noexcept { glDeleteBuffers(1, &id); }

GLuint Texture::create() {
  GLuint id = 0;
  glGenTextures(1, &id);
  return require_name(id, "texture");
}
void Texture::destroy(GLuint id) noexcept { glDeleteTextures(1, &id); }

GLuint Framebuffer::create() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return require_name(id, "framebuffer");
}
void Framebuffer::destroy(GLuint id) noexcept { glDeleteFramebuffers(1, &id); }

GLuint Renderbuffer::create() {
  GLuint id = 0;
  glGenRenderbuffers(1, &id);
  return require_name(id, "renderbuffer");
}
void Renderbuffer::destroy(GLuint id) noexcept { glDeleteRenderbuffers(1, &id); }

GLuint VertexArray::create() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return require_name(id, "vertex array");
}
void VertexArray::destroy(GLuint id) noexcept { glDeleteVertexArrays(1, &id); }

GLuint Sampler::create() {
  GLuint id = 0;
  glGenSamplers(1, &id);
  return require_name(id, "sampler");
}
void Sampler::destroy(GLuint id) noexcept { glDeleteSamplers(1, &id); }

GLuint Query::create() {
  GLuint id = 0;
  glGenQueries(1, &id);
  return require_name(id, "query");
}
void Query::destroy(GLuint id) noexcept { glDeleteQueries(1, &id); }

GLuint Shader::create(GLenum stage) { return require_name(glCreateShader(stage), "shader"); }
void Shader::destroy(GLuint id) noexcept { glDeleteShader(id); }

GLuint Program::create() { return require_name(glCreateProgram(), "program"); }
void Program::destroy(GLuint id) noexcept { glDeleteProgram(id); }

}  // namespace gl_traits

Texture make_texture_2d(GLenum internal_format, int width, int height, int levels) {
  check_size("texture", internal_format, width, height, GL_MAX_TEXTURE_SIZE);
  check_gl_error("an earlier GL call (found before making a texture)");
  Texture texture = Texture::create();
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glTexStorage2D(GL_TEXTURE_2D, levels, internal_format, width, height);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  check_gl_error("allocating a " + size_text(internal_format, width, height) + " texture with " +
                 std::to_string(levels) + " level(s)");
  return texture;
}

Renderbuffer make_renderbuffer(GLenum internal_format, int width, int height, int samples) {
  check_size("renderbuffer", internal_format, width, height, GL_MAX_RENDERBUFFER_SIZE);
  check_gl_error("an earlier GL call (found before making a renderbuffer)");
  Renderbuffer renderbuffer = Renderbuffer::create();
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer.id());
  if (samples > 0)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, internal_format, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, internal_format, width, height);
  check_gl_error("allocating a " + size_text(internal_format, width, height) + " renderbuffer" +
                 (samples > 0 ? " with " + std::to_string(samples) + " samples" : std::string()));
  return renderbuffer;
}

void check_framebuffer_complete(GLenum target, std::string_view what) {
  const GLenum status = glCheckFramebufferStatus(target);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  if (status == 0) check_gl_error("glCheckFramebufferStatus for framebuffer '" + std::string(what) + "'");
  throw RenderError("framebuffer '" + std::string(what) + "' is incomplete: " + framebuffer_status_text(status));
}

}  // namespace trailray::render
