// RAII owners of GL names: each object deleted exactly once; framebuffer and allocation errors.

#include "render/gl/gl_objects.hpp"

#include <gtest/gtest.h>

#include "gl_test_support.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

using test::GlTest;

// GL only counts a texture as existing once it has been bound.
Texture bound_texture() {
  Texture texture = Texture::create();
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

bool contains(const std::string& text, std::string_view part) { return text.find(part) != std::string::npos; }

class GlObjects : public GlTest {};

TEST_F(GlObjects, DeletesItsObjectAtScopeEnd) {
  GLuint name = 0;
  {
    const Texture texture = bound_texture();
    name = texture.id();
    ASSERT_NE(name, 0u);
    EXPECT_TRUE(glIsTexture(name));
  }
  EXPECT_FALSE(glIsTexture(name));
}

TEST_F(GlObjects, AMovedFromOwnerDeletesNothing) {
  Texture first = bound_texture();
  const GLuint name = first.id();
  Texture second = std::move(first);
  EXPECT_EQ(first.id(), 0u);  // NOLINT(bugprone-use-after-move): moved-from owners hold 0
  EXPECT_FALSE(first);        // NOLINT(bugprone-use-after-move)
  EXPECT_EQ(second.id(), name);
  second.reset();
  EXPECT_FALSE(glIsTexture(name));
  // GL hands the freed name out again; had `first` kept it, its destructor would now delete the
  // new texture: the double delete that moving must not cause.
  const Texture reused = bound_texture();
  first = Texture();  // destroys whatever `first` still owns
  EXPECT_TRUE(glIsTexture(reused.id()));
}

TEST_F(GlObjects, MoveAssignmentDeletesTheTargetsOldObject) {
  Buffer target = Buffer::create();
  glBindBuffer(GL_ARRAY_BUFFER, target.id());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  const GLuint old_name = target.id();
  Buffer source = Buffer::create();
  glBindBuffer(GL_ARRAY_BUFFER, source.id());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  const GLuint new_name = source.id();
  target = std::move(source);
  EXPECT_EQ(target.id(), new_name);
  EXPECT_FALSE(glIsBuffer(old_name));
  EXPECT_TRUE(glIsBuffer(new_name));
  // A self-move keeps the object: on purpose, so clang's warning about it is off here.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wself-move"
#endif
  target = std::move(target);  // NOLINT
#if defined(__clang__)
#pragma clang diagnostic pop
#endif
  EXPECT_TRUE(glIsBuffer(new_name));
}

TEST_F(GlObjects, ReleaseGivesUpOwnership) {
  GLuint name = 0;
  {
    Framebuffer framebuffer = Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    name = framebuffer.release();
    EXPECT_FALSE(framebuffer);
  }
  EXPECT_TRUE(glIsFramebuffer(name));
  const Framebuffer adopted(name);  // deletes it again, once
}

TEST_F(GlObjects, EveryKindCanBeMadeAndDeleted) {
  const Buffer buffer = Buffer::create();
  const Texture texture = Texture::create();
  const Framebuffer framebuffer = Framebuffer::create();
  const Renderbuffer renderbuffer = Renderbuffer::create();
  const VertexArray vertex_array = VertexArray::create();
  const Sampler sampler = Sampler::create();
  const Query query = Query::create();
  const Shader shader = Shader::create(GL_FRAGMENT_SHADER);
  const Program program = Program::create();
  for (GLuint id : {buffer.id(), texture.id(), framebuffer.id(), renderbuffer.id(), vertex_array.id(), sampler.id(),
                    query.id(), shader.id(), program.id()})
    EXPECT_NE(id, 0u);
  EXPECT_TRUE(glIsShader(shader.id()));
  EXPECT_TRUE(glIsProgram(program.id()));
}

TEST_F(GlObjects, AnIncompleteFramebufferIsAClearError) {
  const Framebuffer empty = Framebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, empty.id());
  try {
    check_framebuffer_complete(GL_FRAMEBUFFER, "G-buffer");
    FAIL() << "a framebuffer without attachments passed";
  } catch (const RenderError& error) {
    EXPECT_STREQ(error.what(),
                 "framebuffer 'G-buffer' is incomplete: GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT (nothing is "
                 "attached)");
  }
  // A depth texture is not colour-renderable: attached as colour, the attachment is incomplete.
  const Texture depth = make_texture_2d(GL_DEPTH_COMPONENT24, 8, 8);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, depth.id(), 0);
  try {
    check_framebuffer_complete(GL_FRAMEBUFFER, "shadow map");
    FAIL() << "a depth texture as colour attachment passed";
  } catch (const RenderError& error) {
    EXPECT_TRUE(contains(error.what(), "framebuffer 'shadow map' is incomplete: GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"))
        << error.what();
  }
  // Attached where it belongs, with a colour texture, the framebuffer is complete.
  const Texture color = make_texture_2d(GL_RGBA8, 8, 8);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0);
  EXPECT_NO_THROW(check_framebuffer_complete(GL_FRAMEBUFFER, "shadow map"));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GlObjects, TexturesAndRenderbuffersOfImpossibleSizesAreRefusedByName) {
  try {
    make_texture_2d(GL_RGBA16F, 0, 4);
    FAIL() << "a 0 x 4 texture was made";
  } catch (const RenderError& error) {
    EXPECT_TRUE(contains(error.what(), "cannot make a 0 x 4 GL_RGBA16F texture: each side must be 1.."))
        << error.what();
  }
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  EXPECT_THROW(make_renderbuffer(GL_DEPTH_COMPONENT24, max_size + 1, 4), RenderError);
  // More mip levels than the size has: GL refuses, and the message names the call.
  try {
    make_texture_2d(GL_RGBA8, 4, 4, 8);
    FAIL() << "a 4 x 4 texture with 8 levels was made";
  } catch (const RenderError& error) {
    EXPECT_TRUE(contains(error.what(), "GL_INVALID_OPERATION after allocating a 4 x 4 GL_RGBA8 texture with 8 level"))
        << error.what();
  }
}

TEST_F(GlObjects, MadeTexturesHaveTheirSizeAndFormat) {
  const Texture texture = make_texture_2d(GL_RGBA8, 5, 3);
  const Renderbuffer depth = make_renderbuffer(GL_DEPTH_COMPONENT24, 5, 3);
  GLint width = 0, height = 0, format = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &width);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &height);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &format);
  EXPECT_EQ(width, 5);
  EXPECT_EQ(height, 3);
  EXPECT_EQ(format, GL_DEPTH_COMPONENT24);
  GLint immutable = 0;
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
  EXPECT_EQ(immutable, GL_TRUE);
}

}  // namespace
}  // namespace trailray::render
