#pragma once
// The reference tube of the track benchmark: the explicit-mesh way to draw a
// track in 3D. Every point gets a ring of 8 vertices (position and normal, 24 bytes each), the
// ring lying in the plane of the joint's bisector (widened along the bend, so the tube keeps its
// radius through a turn and consecutive rings join without gaps), its vertices carried from ring
// to ring by parallel transport (no twist); 16 triangles join consecutive rings, indexed with
// GL_UNSIGNED_INT (48 indices, 192 bytes, per segment). The ends are left open. The radius is
// in metres, fixed when the mesh is built (radius_for_pixel_width: the same width as the other
// techniques at the scene's centre). It fills the G-buffer like the capsules' visible pass. It
// exists only in `trailray bench tracks`.

#include <glm/glm.hpp>

#include <cstddef>

#include "scene/camera/camera.hpp"
#include "render/passes/gbuffer.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/gl/shader_program.hpp"
#include "render/passes/track_buffer.hpp"

namespace trailray::render::reference {

inline constexpr int kTubeSides = 8;

class TubeBuffer {
 public:
  // Builds and uploads the mesh (the GL context must be current). A segment of one point has a
  // ring and no triangles. Throws std::invalid_argument for a radius that is not a positive
  // number, RenderError when GL refuses the buffers.
  TubeBuffer(const scene::TrackGeometry& geometry, double radius_m);

  std::size_t point_count() const { return point_count_; }
  std::size_t gpu_bytes() const { return gpu_bytes_; }
  double radius_m() const { return radius_m_; }
  const glm::dvec3& origin() const { return origin_; }
  GLsizei index_count() const { return index_count_; }
  const VertexArray& vertex_array() const { return vertex_array_; }

 private:
  std::size_t point_count_ = 0, gpu_bytes_ = 0;
  double radius_m_;
  glm::dvec3 origin_{};
  GLsizei index_count_ = 0;
  VertexArray vertex_array_;
  Buffer vertices_, indices_;
};

class TubePass {
 public:
  TubePass();  // compiles the program (the GL context must be current); throws ShaderError

  // Into the bound G-buffer (as TerrainPass left it), depth-tested against what is there.
  // Throws RenderError when GL reports an error.
  void draw(const GBuffer& gbuffer, const scene::Camera& camera, const TubeBuffer& tube, const glm::vec3& color_srgb) const;

 private:
  ShaderProgram program_;
};

}  // namespace trailray::render::reference
