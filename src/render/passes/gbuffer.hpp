#pragma once
// The G-buffer (DESIGN.md "The frame", step 3): what the terrain pass leaves for the lighting
// passes, one texel per pixel:
//   albedo    SRGB8_ALPHA8  linear albedo (stored sRGB-encoded for precision in the darks);
//                           alpha 1 for terrain, 0 for a track (it gets less haze)
//   normal    RGB10_A2      view-space unit normal as n * 0.5 + 0.5
//   distance  R32F          metres from the camera, 0 where no terrain was drawn (the sky);
//             RGBA8         the same packed as 24-bit fixed point when float targets are missing
//   depth     DEPTH24       for the depth test only
// The encodings are in shaders/gbuffer.glsl. Distances, not depths: they come straight from
// camera-relative positions, so they keep their precision at any distance from the origin.

#include "render/gl/gl_capabilities.hpp"
#include "render/gl/gl_objects.hpp"

namespace trailray::render {

enum class DistanceEncoding {
  float32,       // R32F (EXT_color_buffer_float)
  packed_rgba8,  // 24-bit fixed point in RGBA8, 1/16 m steps up to 1048 km
};

// The encoding a context allows: float32 with EXT_color_buffer_float, else packed_rgba8.
DistanceEncoding distance_encoding_for(const GlCapabilities& capabilities);

class GBuffer {
 public:
  // Throws RenderError naming the size when GL refuses it.
  GBuffer(int width, int height, DistanceEncoding encoding);

  // Binds it for drawing with all three colour attachments, sets the viewport, and clears
  // everything to 0 (distance 0: the sky) and depth to far.
  void bind_and_clear() const;
  // Binds it for drawing with all three attachments and sets the viewport; keeps the contents
  // (the track pass draws over the terrain).
  void bind() const;

  int width() const { return width_; }
  int height() const { return height_; }
  DistanceEncoding distance_encoding() const { return encoding_; }
  bool packed_distance() const { return encoding_ == DistanceEncoding::packed_rgba8; }
  const Texture& albedo() const { return albedo_; }
  const Texture& normal() const { return normal_; }
  const Texture& distance() const { return distance_; }
  // Its framebuffer (for blitting its depth elsewhere).
  GLuint framebuffer_id() const { return framebuffer_.id(); }

 private:
  int width_, height_;
  DistanceEncoding encoding_;
  Texture albedo_, normal_, distance_;
  Renderbuffer depth_;
  Framebuffer framebuffer_;
};

}  // namespace trailray::render
