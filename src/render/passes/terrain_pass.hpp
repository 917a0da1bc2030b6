#pragma once
// The terrain pass: the G-buffer fill (DESIGN.md "The frame", step 3). Draws terrain tiles
// (terrain_mesh.hpp) into a GBuffer with depth, each with its own camera-relative matrix
// (Camera::view_projection_relative_to its origin): albedo from imagery or a hypsometric tint,
// the view-space normal and the distance from the camera. Lighting is the compose pass's.

#include <glm/glm.hpp>

#include <span>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/passes/terrain_mesh.hpp"
#include "scene/camera/camera.hpp"
#include "scene/style.hpp"

namespace trailray::render {

// Linear albedo of the neutral ground (DESIGN.md: where no source covers the view).
inline constexpr glm::vec3 kNeutralGroundAlbedo{0.30f, 0.30f, 0.28f};

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

  // Clears the G-buffer and draws the tiles into it with depth testing; snow: white from about
  // `snowline_m` up (fading in over the 300 m below it), on slopes under about 40-50 degrees.
  // Throws RenderError when GL reports an error.
  void draw(const GBuffer& gbuffer, const scene::Camera& camera, std::span<const TerrainDrawItem> tiles,
            const scene::SnowCover& snow = {}) const;

 private:
  ShaderProgram program_;
};

// An sRGB imagery texture (mipmapped, linear filtering) from RGBA8 pixels. Throws RenderError.
Texture upload_imagery_texture(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba);

// A colour (RGBA8) + depth (24 bit) framebuffer of a size: the composed frame, before it goes to
// its FrameTarget (frame_target.hpp), and the track overlay.
class ColorDepthTarget {
 public:
  // Throws RenderError naming the size when GL refuses it.
  ColorDepthTarget(int width, int height);
  // Binds it for drawing and reading, and sets the viewport to all of it.
  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }
  const Texture& color() const { return color_; }
  GLuint framebuffer_id() const { return framebuffer_.id(); }

 private:
  int width_, height_;
  Texture color_;
  Renderbuffer depth_;
  Framebuffer framebuffer_;
};

}  // namespace trailray::render
