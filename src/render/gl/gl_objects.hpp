#pragma once
// Move-only owners of GL object names: each deletes its object exactly once, when it goes out of
// scope, and a moved-from owner holds 0 (which GL ignores on delete), so a move can never delete
// twice. The GL context must be current whenever one is created, reset or destroyed, and must
// outlive them: destroy the objects before the GlContext.

#include <string_view>
#include <utility>

#include "render/gl/gl_api.hpp"

namespace trailray::render {

// `Traits` says how to make and delete one kind of object, and its name for messages.
template <class Traits>
class GlObject {
 public:
  GlObject() = default;                                // owns nothing
  explicit GlObject(GLuint adopted) : id_(adopted) {}  // takes ownership of an existing name

  // Makes a new object; `args` go to the GL creation call (e.g. the shader stage).
  // Throws RenderError when GL returns no name (typically: no current context).
  template <class... Args>
  static GlObject create(Args... args) {
    return GlObject(Traits::create(args...));
  }

  GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) reset(std::exchange(other.id_, 0));
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  ~GlObject() { reset(); }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  // Deletes the object now (if any) and owns `adopted` instead.
  void reset(GLuint adopted = 0) noexcept {
    if (id_ != 0) Traits::destroy(id_);
    id_ = adopted;
  }
  // Gives up ownership without deleting; the caller deletes the returned name.
  [[nodiscard]] GLuint release() noexcept { return std::exchange(id_, 0); }

 private:
  GLuint id_ = 0;
};

namespace gl_traits {
// Each create() throws RenderError("GL created no <kind> ...") when GL hands out name 0.
struct Buffer {
  static GLuint create();
  static void destroy(GLuint id) noexcept;
};
struct Texture {
  static GLuint create();
  static void destroy(GLuint id) noexcept;
};
struct Framebuffer {
  static GLuint create();
  static void destroy(GLuint id) noexcept;
};
struct Renderbuffer {
  static GLuint create();
  static void destroy(GLuint id) noexcept;
};
struct VertexArray {
  static GLuint create();
  static void destroy(GLuint id) noexcept;
};
struct Sampler {
  static GLuint create();
  static void destroy(GLuint id) noexcept;
};
struct Query {
  static GLuint create();
  static void destroy(GLuint id) noexcept;
};
struct Shader {
  static GLuint create(GLenum stage);  // GL_VERTEX_SHADER or GL_FRAGMENT_SHADER
  static void destroy(GLuint id) noexcept;
};
struct Program {
  static GLuint create();
  static void destroy(GLuint id) noexcept;
};
}  // namespace gl_traits

using Buffer = GlObject<gl_traits::Buffer>;
using Texture = GlObject<gl_traits::Texture>;
using Framebuffer = GlObject<gl_traits::Framebuffer>;
using Renderbuffer = GlObject<gl_traits::Renderbuffer>;
using VertexArray = GlObject<gl_traits::VertexArray>;
using Sampler = GlObject<gl_traits::Sampler>;
using Query = GlObject<gl_traits::Query>;
using Shader = GlObject<gl_traits::Shader>;
using Program = GlObject<gl_traits::Program>;

// A 2D texture with immutable storage (glTexStorage2D), nearest filtering and clamp-to-edge:
// the defaults of a render target; set others after. Left bound to GL_TEXTURE_2D. Throws
// RenderError naming the format and size when the size is out of range or GL refuses.
Texture make_texture_2d(GLenum internal_format, int width, int height, int levels = 1);

// A renderbuffer (depth, or colour never sampled); `samples` > 0 for multisampling. Same errors.
Renderbuffer make_renderbuffer(GLenum internal_format, int width, int height, int samples = 0);

// Checks the framebuffer bound to `target` (GL_FRAMEBUFFER, GL_DRAW_FRAMEBUFFER or
// GL_READ_FRAMEBUFFER); throws RenderError("framebuffer 'G-buffer' is incomplete:
// GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (...)") otherwise. `what` names it for the reader.
void check_framebuffer_complete(GLenum target, std::string_view what);

}  // namespace trailray::render
