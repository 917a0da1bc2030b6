#include "render/passes/reference/tube_pass.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/passes/reference/reference_track.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render::reference {
namespace {

struct TubeVertex {
  float x, y, z;     // offset from the origin
  float nx, ny, nz;  // unit normal
};
static_assert(sizeof(TubeVertex) == 24);

// A ring's widening along the bend is 1 / cos(half the turn); capped, so a near reversal does
// not throw a spike across the screen (the reference accepts a pinch there).
constexpr double kMaxMiterScale = 4.0;

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
  const double length = glm::length(v);
  return length > 0.0 ? v / length : glm::dvec3(0.0);
}

// Any unit vector perpendicular to `t` (unit).
glm::dvec3 perpendicular_to(const glm::dvec3& t) {
  const glm::dvec3 axis = std::abs(t.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  return glm::normalize(glm::cross(t, axis));
}

// Appends one segment's rings to `vertices` and its triangles to `indices`.
class SegmentMesher {
 public:
  SegmentMesher(const std::vector<glm::dvec3>& points, const glm::dvec3& origin, double radius_m)
      : points_(points), origin_(origin), radius_m_(radius_m) {}

  void append(std::vector<TubeVertex>& vertices, std::vector<std::uint32_t>& indices) {
    const auto first_ring = static_cast<std::uint32_t>(vertices.size());
    glm::dvec3 reference(0.0);  // the ring's first vertex direction, transported along
    glm::dvec3 last_edge(0.0);  // the last edge with a length, for repeated points
    for (std::size_t i = 0; i < points_.size(); ++i) {
      glm::dvec3 in = i > 0 ? unit_or_zero(points_[i] - points_[i - 1]) : glm::dvec3(0.0);
      glm::dvec3 out = i + 1 < points_.size() ? unit_or_zero(points_[i + 1] - points_[i]) : glm::dvec3(0.0);
      if (in == glm::dvec3(0.0)) in = last_edge != glm::dvec3(0.0) ? last_edge : out;
      if (out == glm::dvec3(0.0)) out = in;
      if (in == glm::dvec3(0.0)) in = out = glm::dvec3(0.0, 0.0, 1.0);  // every point the same
      last_edge = in;
      glm::dvec3 tangent = unit_or_zero(in + out);
      if (tangent == glm::dvec3(0.0)) tangent = in;  // a reversal: the ring faces the incoming edge
      // Parallel transport: the previous ring's reference direction, made perpendicular again.
      glm::dvec3 u = reference - glm::dot(reference, tangent) * tangent;
      u = glm::length(u) > 1e-6 ? glm::normalize(u) : perpendicular_to(tangent);
      reference = u;
      const glm::dvec3 v = glm::cross(tangent, u);
      // The bend's direction in the ring's plane and the widening along it.
      const glm::dvec3 bend = unit_or_zero(in - glm::dot(in, tangent) * tangent);
      const double cos_half_turn = std::abs(glm::dot(in, tangent));
      const double widen = std::min(1.0 / std::max(cos_half_turn, 1e-9), kMaxMiterScale) - 1.0;
      const glm::dvec3 centre = points_[i] - origin_;
      for (int k = 0; k < kTubeSides; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / kTubeSides;
        const glm::dvec3 radial = std::cos(angle) * u + std::sin(angle) * v;
        const glm::dvec3 p = centre + radius_m_ * (radial + widen * glm::dot(radial, bend) * bend);
        const glm::vec3 pf(p), nf(radial);
        vertices.push_back({pf.x, pf.y, pf.z, nf.x, nf.y, nf.z});
      }
    }
    for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
      const auto ring = first_ring + static_cast<std::uint32_t>(i * kTubeSides);
      for (std::uint32_t k = 0; k < kTubeSides; ++k) {
        const std::uint32_t a = ring + k, b = ring + (k + 1) % kTubeSides;
        const std::uint32_t c = a + kTubeSides, d = b + kTubeSides;
        indices.insert(indices.end(), {a, b, c, b, d, c});
      }
    }
  }

 private:
  const std::vector<glm::dvec3>& points_;
  glm::dvec3 origin_;
  double radius_m_;
};

}  // namespace

TubeBuffer::TubeBuffer(const scene::TrackGeometry& geometry, double radius_m)
    : radius_m_(radius_m), origin_(geometry_origin(geometry)) {
  if (!(radius_m > 0.0) || !std::isfinite(radius_m))
    throw std::invalid_argument("tube radius " + std::to_string(radius_m) + " m is not a positive number");
  point_count_ = geometry_point_count(geometry);
  if (point_count_ * kTubeSides > std::numeric_limits<std::uint32_t>::max())
    throw RenderError("a tube of " + std::to_string(point_count_) + " points needs more than 32-bit indices");
  std::vector<TubeVertex> vertices;
  std::vector<std::uint32_t> indices;
  vertices.reserve(point_count_ * kTubeSides);
  indices.reserve(point_count_ * kTubeSides * 6);
  const glm::dvec3 origin = origin_;
  for (const scene::TrackPolyline& segment : geometry.segments)
    SegmentMesher(segment.points_ecef, origin, radius_m).append(vertices, indices);
  index_count_ = static_cast<GLsizei>(indices.size());
  gpu_bytes_ = vertices.size() * sizeof(TubeVertex) + indices.size() * sizeof(std::uint32_t);

  vertex_array_ = VertexArray::create();
  vertices_ = Buffer::create();
  indices_ = Buffer::create();
  glBindVertexArray(vertex_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(TubeVertex)), vertices.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
               indices.data(), GL_STATIC_DRAW);
  constexpr auto stride = static_cast<GLsizei>(sizeof(TubeVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(TubeVertex, x)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(TubeVertex, nx)));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
    throw RenderError("uploading a tube of " + std::to_string(point_count_) + " points failed (GL error " +
                      std::to_string(error) + ")");
}

TubePass::TubePass() : program_(ShaderProgram::from_embedded("reference_tube.vert", "reference_track.frag")) {}

void TubePass::draw(const GBuffer& gbuffer, const scene::Camera& camera, const TubeBuffer& tube,
                    const glm::vec3& color_srgb) const {
  begin_reference_draw(program_, gbuffer, camera, tube.origin(), color_srgb);
  glBindVertexArray(tube.vertex_array().id());
  if (tube.index_count() > 0) glDrawElements(GL_TRIANGLES, tube.index_count(), GL_UNSIGNED_INT, nullptr);
  end_reference_draw("drawing the reference tube");
}

}  // namespace trailray::render::reference
