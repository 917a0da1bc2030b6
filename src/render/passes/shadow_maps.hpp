#pragma once
// Cascaded shadow maps, the GL half: one depth texture array (a layer per cascade, 32-bit float
// depth, compare mode on so shaders sample it as sampler2DArrayShadow), filled by rendering the
// casters once per cascade, and the uniforms shadows.glsl needs for the lookup.
//
// The casters are drawn by the caller (terrain tiles, tracks), through a callback that receives
// each cascade's light view-projection for camera-relative positions; a caster with its own
// origin multiplies in its "origin minus camera" offset (or uses
// ShadowCascade::view_projection_relative_to its origin, which is exact in double).

#include <array>
#include <functional>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/shadow_cascades.hpp"

namespace trailray::render {

class ShadowMaps {
 public:
  using DrawCasters = std::function<void(const std::array<float, 16>& light_view_projection_relative)>;

  // Allocates the maps (the GL context must be current). Throws RenderError naming the size
  // when it is outside 16..GL_MAX_TEXTURE_SIZE or GL refuses the storage.
  explicit ShadowMaps(int map_size_px);

  int map_size_px() const { return map_size_px_; }
  GLuint texture() const { return depth_maps_.id(); }
  // A program for casters given as a vec3 position at attribute 0 (float offsets from the
  // camera): shadow_depth.vert + .frag, matrix uniform "u_light_view_projection".
  const ShaderProgram& caster_program() const { return caster_program_; }

  // Renders every cascade: binds its layer, clears depth to far, calls `draw_casters` with its
  // camera-relative matrix, depth test on, no colour, no culling (terrain is open). Called once
  // per cascade, in order 0..3: a caster with its own origin that wants the exact matrix counts
  // the calls and asks cascades[i].view_projection_relative_to(its origin). Restores the
  // framebuffer, viewport, colour mask, depth state and culling it found. Throws RenderError
  // when the cascades were computed for another map size (their texel snapping would not
  // match) or GL reports an error.
  void render(const ShadowCascades& cascades, const DrawCasters& draw_casters) const;

  // Binds the maps to `texture_unit` and sets shadows.glsl's uniforms on `program` (which
  // includes it) for these cascades.
  void bind_for_lookup(const ShaderProgram& program, const ShadowCascades& cascades, GLuint texture_unit) const;

 private:
  int map_size_px_;
  Texture depth_maps_;
  Framebuffer framebuffer_;
  ShaderProgram caster_program_;
};

}  // namespace trailray::render
