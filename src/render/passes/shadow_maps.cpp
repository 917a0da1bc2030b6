#include "render/passes/shadow_maps.hpp"

#include <string>

#include "render/gl/gl_check.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render {
namespace {

Texture make_depth_array(int size) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (size < 16 || size > max_size)
    throw RenderError("cannot make " + std::to_string(size) + " x " + std::to_string(size) +
                      " shadow maps: each side must be 16.." + std::to_string(max_size));
  Texture texture = Texture::create();
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture.id());
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH_COMPONENT32F, size, size, static_cast<GLsizei>(kShadowCascadeCount));
  // Linear filtering with compare mode: the hardware's 2x2 PCF where it has one, under the
  // shader's 3x3 taps. Outside the map nothing is in shadow: the shader returns 1 there anyway.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  check_gl_error("allocating " + std::to_string(size) + " x " + std::to_string(size) + " x " +
                 std::to_string(kShadowCascadeCount) + " GL_DEPTH_COMPONENT32F shadow maps");
  return texture;
}

// The GL state render() changes, put back as found so the caller's pass is not disturbed.
class SavedState {
 public:
  SavedState() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
    glGetBooleanv(GL_COLOR_WRITEMASK, color_mask_.data());
    cull_face_ = glIsEnabled(GL_CULL_FACE);
    depth_test_ = glIsEnabled(GL_DEPTH_TEST);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
    glGetIntegerv(GL_DEPTH_FUNC, &depth_func_);
  }
  SavedState(const SavedState&) = delete;
  SavedState& operator=(const SavedState&) = delete;
  ~SavedState() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(framebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glColorMask(color_mask_[0], color_mask_[1], color_mask_[2], color_mask_[3]);
    if (cull_face_) glEnable(GL_CULL_FACE);
    if (!depth_test_) glDisable(GL_DEPTH_TEST);
    glDepthMask(depth_mask_);
    glDepthFunc(static_cast<GLenum>(depth_func_));
  }

 private:
  GLint framebuffer_ = 0, depth_func_ = GL_LESS;
  std::array<GLint, 4> viewport_{};
  std::array<GLboolean, 4> color_mask_{};
  GLboolean cull_face_ = GL_FALSE, depth_test_ = GL_FALSE, depth_mask_ = GL_TRUE;
};

std::array<float, 4> per_cascade(const ShadowCascades& cascades, double ShadowCascade::*member) {
  std::array<float, 4> out{};
  for (std::size_t i = 0; i < kShadowCascadeCount; ++i) out[i] = static_cast<float>(cascades[i].*member);
  return out;
}

}  // namespace

ShadowMaps::ShadowMaps(int map_size_px)
    : map_size_px_(map_size_px),
      depth_maps_(make_depth_array(map_size_px)),
      framebuffer_(Framebuffer::create()),
      caster_program_(ShaderProgram::from_embedded("shadow_depth.vert", "shadow_depth.frag")) {}

void ShadowMaps::render(const ShadowCascades& cascades, const DrawCasters& draw_casters) const {
  if (cascades.settings().map_size_px != map_size_px_)
    throw RenderError("shadow cascades computed for " + std::to_string(cascades.settings().map_size_px) +
                      " px maps cannot be rendered into " + std::to_string(map_size_px_) + " px shadow maps");
  {
    const SavedState saved;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, map_size_px_, map_size_px_);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    const GLenum no_colour = GL_NONE;
    glDrawBuffers(1, &no_colour);
    for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
      glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_maps_.id(), 0, static_cast<GLint>(i));
      if (i == 0) check_framebuffer_complete(GL_DRAW_FRAMEBUFFER, "shadow maps");
      glClearDepthf(1.0f);
      glClear(GL_DEPTH_BUFFER_BIT);
      draw_casters(cascades.camera_relative_matrix(i));
    }
  }
  check_gl_error("rendering the shadow cascades");
}

void ShadowMaps::bind_for_lookup(const ShaderProgram& program, const ShadowCascades& cascades,
                                 GLuint texture_unit) const {
  glActiveTexture(GL_TEXTURE0 + texture_unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, depth_maps_.id());
  glActiveTexture(GL_TEXTURE0);
  program.set_int("u_shadow_maps", static_cast<int>(texture_unit));
  for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
    const auto matrix = cascades.camera_relative_matrix(i);
    program.set_mat4("u_shadow_matrices[" + std::to_string(i) + "]", matrix);
  }
  auto set = [&](std::string_view name, const std::array<float, 4>& v) {
    program.set_vec4(name, v[0], v[1], v[2], v[3]);
  };
  set("u_shadow_split_far_m", cascades.split_far_m());
  set("u_shadow_depth_extent_m", per_cascade(cascades, &ShadowCascade::depth_extent_m));
  set("u_shadow_constant_bias_m", per_cascade(cascades, &ShadowCascade::constant_bias_m));
  set("u_shadow_slope_bias_m", per_cascade(cascades, &ShadowCascade::slope_bias_m));
  set("u_shadow_normal_offset_m", per_cascade(cascades, &ShadowCascade::normal_offset_m));
  program.set_float("u_shadow_texel_uv", 1.0f / static_cast<float>(map_size_px_));
}

}  // namespace trailray::render
