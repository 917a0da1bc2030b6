#include "render/volume_gpu.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace trailray::render {
namespace {

// Outlines are drawn nearly opaque and a little lighter than the walls, so a limit reads as a
// line against the tinted wall and the terrain.
constexpr float kOutlineOpacity = 0.9f;
constexpr float kOutlineLift = 0.25f;

void set_position(float (&out)[3], const glm::dvec3& ecef, const glm::dvec3& origin) {
  const glm::vec3 p(ecef - origin);
  out[0] = p.x, out[1] = p.y, out[2] = p.z;
}

void add_outline(VolumeMesh& mesh, const glm::dvec3& a, const glm::dvec3& b, const glm::vec3& color) {
  const glm::vec3 lit = glm::mix(color, glm::vec3(1.0f), kOutlineLift);
  for (const auto& [along, across] :
       {std::pair{0.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {0.f, -1.f}, {1.f, 1.f}, {0.f, 1.f}}) {
    VolumeOutlineVertex v{};
    set_position(v.from, a, mesh.origin);
    set_position(v.to, b, mesh.origin);
    v.color[0] = lit.r, v.color[1] = lit.g, v.color[2] = lit.b, v.color[3] = kOutlineOpacity;
    v.corner[0] = along, v.corner[1] = across;
    mesh.outlines.push_back(v);
  }
}

void attribute(GLuint location, GLint size, GLsizei stride, std::size_t offset) {
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
}

}  // namespace

VolumeMesh volume_mesh(const std::vector<scene::VolumeShape>& shapes) {
  VolumeMesh mesh;
  std::size_t columns = 0;
  for (const scene::VolumeShape& s : shapes)
    for (const scene::VolumeColumn& c : s.columns) {
      mesh.origin += c.bottom_ecef;
      ++columns;
    }
  if (columns == 0) return mesh;
  mesh.origin /= static_cast<double>(columns);
  for (const scene::VolumeShape& s : shapes) {
    const std::size_t n = s.columns.size();
    if (n < 2) continue;
    const std::size_t edges = s.closed ? n : n - 1;
    const auto corner = [&](const scene::VolumeColumn& c, bool top) {
      VolumeWallVertex v{};
      set_position(v.position, top ? c.top_ecef : c.bottom_ecef, mesh.origin);
      v.color[0] = s.color_srgb.r, v.color[1] = s.color_srgb.g, v.color[2] = s.color_srgb.b, v.color[3] = s.opacity;
      v.wall[0] = top ? 1.0f : 0.0f;
      v.wall[1] = s.faded_top ? 1.0f : 0.0f;
      return v;
    };
    for (std::size_t i = 0; i < edges; ++i) {
      const scene::VolumeColumn& a = s.columns[i];
      const scene::VolumeColumn& b = s.columns[(i + 1) % n];
      for (const auto& v :
           {corner(a, false), corner(b, false), corner(b, true), corner(a, false), corner(b, true), corner(a, true)})
        mesh.walls.push_back(v);
      if (!s.faded_top) add_outline(mesh, a.top_ecef, b.top_ecef, s.color_srgb);
      if (s.floor_outline) add_outline(mesh, a.bottom_ecef, b.bottom_ecef, s.color_srgb);
    }
  }
  return mesh;
}

const VolumeDraw* VolumeGpu::draw(const scene::VolumeSet* set, double neutral_ground_m) {
  if (std::isnan(neutral_ground_m)) neutral_ground_m = 0.0;
  const bool same = set == set_ && (set == nullptr || set->revision == revision_) &&
                    std::abs(neutral_ground_m - neutral_ground_m_) < 1.0;
  if (!same) {
    set_ = set;
    revision_ = set != nullptr ? set->revision : 0;
    neutral_ground_m_ = neutral_ground_m;
    draw_.reset();
    const VolumeMesh mesh = set != nullptr ? volume_mesh(scene::volume_shapes(*set, neutral_ground_m)) : VolumeMesh{};
    if (!mesh.walls.empty()) {
      VolumeDraw& d = draw_.emplace();
      d.origin = mesh.origin;
      d.wall_array = VertexArray::create();
      d.wall_buffer = Buffer::create();
      glBindVertexArray(d.wall_array.id());
      glBindBuffer(GL_ARRAY_BUFFER, d.wall_buffer.id());
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.walls.size() * sizeof(VolumeWallVertex)),
                   mesh.walls.data(), GL_STATIC_DRAW);
      constexpr auto wall_stride = static_cast<GLsizei>(sizeof(VolumeWallVertex));
      attribute(0, 3, wall_stride, offsetof(VolumeWallVertex, position));
      attribute(1, 4, wall_stride, offsetof(VolumeWallVertex, color));
      attribute(2, 2, wall_stride, offsetof(VolumeWallVertex, wall));
      d.wall_vertices = static_cast<int>(mesh.walls.size());
      d.outline_array = VertexArray::create();
      d.outline_buffer = Buffer::create();
      glBindVertexArray(d.outline_array.id());
      glBindBuffer(GL_ARRAY_BUFFER, d.outline_buffer.id());
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.outlines.size() * sizeof(VolumeOutlineVertex)),
                   mesh.outlines.data(), GL_STATIC_DRAW);
      constexpr auto outline_stride = static_cast<GLsizei>(sizeof(VolumeOutlineVertex));
      attribute(0, 3, outline_stride, offsetof(VolumeOutlineVertex, from));
      attribute(1, 3, outline_stride, offsetof(VolumeOutlineVertex, to));
      attribute(2, 4, outline_stride, offsetof(VolumeOutlineVertex, color));
      attribute(3, 2, outline_stride, offsetof(VolumeOutlineVertex, corner));
      d.outline_vertices = static_cast<int>(mesh.outlines.size());
      glBindVertexArray(0);
      glBindBuffer(GL_ARRAY_BUFFER, 0);
    }
  }
  return draw_ ? &*draw_ : nullptr;
}

}  // namespace trailray::render
