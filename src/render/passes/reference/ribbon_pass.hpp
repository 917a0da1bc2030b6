#pragma once
// The reference ribbon of the track benchmark: the usual way to draw a
// polyline, a flat camera-facing strip of constant width in pixels. Two vertices per point in a
// vertex buffer (28 bytes each: the offset from the track's origin, the track's direction at
// the point, the side), one GL_TRIANGLE_STRIP per segment, no joint handling beyond the
// averaged direction (sharp turns pinch, reversals fold). It fills the G-buffer like the
// capsules' visible pass (albedo, normal facing the camera, distance, depth-tested), so the
// bench compares like with like. It exists only in `trailray bench tracks`.

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

#include "scene/camera/camera.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/track_buffer.hpp"

namespace trailray::render::reference {

class RibbonBuffer {
 public:
  struct Range {
    GLint first = 0;     // first vertex of the segment's strip
    GLsizei count = 0;   // its vertices (2 per point)
  };

  // Uploads (the GL context must be current). A segment of fewer than two points is left out
  // (a strip needs a direction). Throws RenderError when GL refuses the buffer.
  explicit RibbonBuffer(const scene::TrackGeometry& geometry);

  std::size_t point_count() const { return point_count_; }
  std::size_t gpu_bytes() const { return gpu_bytes_; }
  const glm::dvec3& origin() const { return origin_; }
  const std::vector<Range>& strips() const { return strips_; }
  const VertexArray& vertex_array() const { return vertex_array_; }

 private:
  std::size_t point_count_ = 0, gpu_bytes_ = 0;
  glm::dvec3 origin_{};
  std::vector<Range> strips_;
  VertexArray vertex_array_;
  Buffer vertices_;
};

class RibbonPass {
 public:
  RibbonPass();  // compiles the program (the GL context must be current); throws ShaderError

  // Into the bound G-buffer (as TerrainPass left it), depth-tested against what is there.
  // Throws RenderError when GL reports an error.
  void draw(const GBuffer& gbuffer, const scene::Camera& camera, const RibbonBuffer& ribbon, const glm::vec3& color_srgb,
            double width_px) const;

 private:
  ShaderProgram program_;
};

}  // namespace trailray::render::reference
