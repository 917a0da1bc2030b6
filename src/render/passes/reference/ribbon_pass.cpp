#include "render/passes/reference/ribbon_pass.hpp"

#include <string>

#include "render/passes/reference/reference_track.hpp"
#include "render/gl/render_error.hpp"

namespace trailray::render::reference {
namespace {

struct RibbonVertex {
  float x, y, z;     // offset from the origin
  float dx, dy, dz;  // unit direction of the track at the point
  float side;        // -1 or +1
};
static_assert(sizeof(RibbonVertex) == 28);

// The direction at point i: the mean of the unit directions of the edges on either side (the
// one edge at the ends). Repeated points take the nearest edge that has a length.
glm::dvec3 direction_at(const std::vector<glm::dvec3>& points, std::size_t i) {
  const auto edge = [&](std::size_t a, std::size_t b) {
    const glm::dvec3 d = points[b] - points[a];
    const double length = glm::length(d);
    return length > 0.0 ? d / length : glm::dvec3(0.0);
  };
  glm::dvec3 sum(0.0);
  if (i > 0) sum += edge(i - 1, i);
  if (i + 1 < points.size()) sum += edge(i, i + 1);
  const double length = glm::length(sum);
  if (length > 1e-9) return sum / length;
  // A reversal (the two edges cancel) or a repeated point: the incoming edge, else any edge.
  for (std::size_t j = i; j > 0; --j)
    if (const glm::dvec3 d = edge(j - 1, j); d != glm::dvec3(0.0)) return d;
  for (std::size_t j = i; j + 1 < points.size(); ++j)
    if (const glm::dvec3 d = edge(j, j + 1); d != glm::dvec3(0.0)) return d;
  return {1.0, 0.0, 0.0};
}

}  // namespace

RibbonBuffer::RibbonBuffer(const scene::TrackGeometry& geometry) : origin_(geometry_origin(geometry)) {
  const glm::dvec3 origin = origin_;
  std::vector<RibbonVertex> vertices;
  vertices.reserve(2 * geometry_point_count(geometry));
  for (const scene::TrackPolyline& segment : geometry.segments) {
    const std::vector<glm::dvec3>& points = segment.points_ecef;
    point_count_ += points.size();
    if (points.size() < 2) continue;
    strips_.push_back({static_cast<GLint>(vertices.size()), static_cast<GLsizei>(2 * points.size())});
    for (std::size_t i = 0; i < points.size(); ++i) {
      const glm::vec3 p(points[i] - origin);
      const glm::vec3 d(direction_at(points, i));
      for (float side : {-1.0f, 1.0f}) vertices.push_back({p.x, p.y, p.z, d.x, d.y, d.z, side});
    }
  }
  gpu_bytes_ = vertices.size() * sizeof(RibbonVertex);
  vertex_array_ = VertexArray::create();
  vertices_ = Buffer::create();
  glBindVertexArray(vertex_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(gpu_bytes_), vertices.data(), GL_STATIC_DRAW);
  constexpr auto stride = static_cast<GLsizei>(sizeof(RibbonVertex));
  const auto attribute = [](GLuint location, GLint size, std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
  };
  attribute(0, 3, offsetof(RibbonVertex, x));
  attribute(1, 3, offsetof(RibbonVertex, dx));
  attribute(2, 1, offsetof(RibbonVertex, side));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
    throw RenderError("uploading a ribbon of " + std::to_string(point_count_) + " points failed (GL error " +
                      std::to_string(error) + ")");
}

RibbonPass::RibbonPass() : program_(ShaderProgram::from_embedded("reference_ribbon.vert", "reference_track.frag")) {}

void RibbonPass::draw(const GBuffer& gbuffer, const scene::Camera& camera, const RibbonBuffer& ribbon,
                      const glm::vec3& color_srgb, double width_px) const {
  begin_reference_draw(program_, gbuffer, camera, ribbon.origin(), color_srgb);
  program_.set_vec2("u_viewport_px", static_cast<float>(gbuffer.width()), static_cast<float>(gbuffer.height()));
  program_.set_float("u_half_width_px", static_cast<float>(0.5 * width_px));
  glBindVertexArray(ribbon.vertex_array().id());
  for (const RibbonBuffer::Range& strip : ribbon.strips()) glDrawArrays(GL_TRIANGLE_STRIP, strip.first, strip.count);
  end_reference_draw("drawing the reference ribbon");
}

}  // namespace trailray::render::reference
