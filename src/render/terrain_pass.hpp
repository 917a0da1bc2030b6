#pragma once
// The terrain pass: draws terrain tiles (terrain_mesh.hpp) into the bound framebuffer with depth,
// each with its own camera-relative matrix (Camera::view_projection_relative_to its origin),
// shaded in one go: albedo from imagery or a hypsometric tint, lit by the sun and the sky.
//
// Next (issue 4, DESIGN.md "The frame"): this pass becomes the G-buffer fill (albedo, normal,
// distance) and the lighting moves to the compose pass with shadows, SSAO and atmosphere; the
// per-tile inputs below stay the same.

#include <glm/glm.hpp>

#include <span>

#include "render/camera.hpp"
#include "render/gl_objects.hpp"
#include "render/shader_program.hpp"
#include "render/terrain_mesh.hpp"

namespace trailray::render {

struct TerrainLighting {
  glm::dvec3 sun_direction_ecef{0.0, 0.0, 1.0};  // unit, towards the sun
  glm::vec3 sun_radiance{1.0f, 0.97f, 0.92f};    // linear, for a surface facing the sun
  glm::vec3 sky_radiance{0.22f, 0.26f, 0.32f};   // linear, for a surface facing the zenith
};

// Linear albedo of the neutral ground (DESIGN.md: where no source covers the view).
inline constexpr glm::vec3 kNeutralGroundAlbedo{0.30f, 0.30f, 0.28f};
// The sky where no terrain is drawn (8-bit sRGB, written as is).
inline constexpr glm::vec3 kSkyColorSrgb{0.64f, 0.77f, 0.91f};

// Imagery for a tile: an sRGB texture and where the tile's square lies in it (uv * scale +
// offset; scale 1, offset 0 for the tile's own imagery, smaller for an ancestor's).
struct TerrainImagery {
  const Texture* texture = nullptr;
  glm::vec2 scale{1.0f, 1.0f}, offset{0.0f, 0.0f};
};

struct TerrainDrawItem {
  const TerrainTileGpu* mesh = nullptr;
  TerrainImagery imagery;  // texture nullptr: the hypsometric tint
};

class TerrainPass {
 public:
  // Compiles the terrain shaders (the GL context must be current). Throws ShaderError.
  TerrainPass();

  // Clears the bound framebuffer's colour to the sky and its depth to far.
  static void clear_to_sky();
  // Draws the tiles with depth testing into the bound framebuffer (its viewport set by the
  // caller). Throws RenderError when GL reports an error.
  void draw(const Camera& camera, std::span<const TerrainDrawItem> tiles, const TerrainLighting& lighting) const;

 private:
  ShaderProgram program_;
};

// An sRGB imagery texture (mipmapped, linear filtering) from RGBA8 pixels. Throws RenderError.
Texture upload_imagery_texture(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba);

// A colour (RGBA8) + depth (24 bit) framebuffer of a size, for the terrain pass and readback.
class FrameTarget {
 public:
  // Throws RenderError naming the size when GL refuses it.
  FrameTarget(int width, int height);
  // Binds it for drawing and reading, and sets the viewport to all of it.
  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  Texture color_;
  Renderbuffer depth_;
  Framebuffer framebuffer_;
};

}  // namespace trailray::render
