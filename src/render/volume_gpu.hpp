#pragma once
// The scene's volumes (airspaces, task cylinders: scene/volumes/volumes.hpp) on the GPU: one vertex
// buffer of wall triangles and one of outline quads for the whole set, float offsets from one
// origin (the set's centre: a few hundred kilometres at most once culled, centimetres of float
// precision), made again only when the set, its revision or the neutral ground changes.

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <vector>

#include "render/gl/gl_objects.hpp"
#include "scene/volumes/volume_shapes.hpp"
#include "scene/volumes/volumes.hpp"

namespace trailray::render {

// A wall vertex: position from the origin, colour (sRGB) and opacity, and where it sits on its
// wall (0 at the floor, 1 at the ceiling) and whether the wall fades out at the top.
struct VolumeWallVertex {
  float position[3];
  float color[4];
  float wall[2];
};
// An outline vertex: the segment's two ends, its colour, and which corner of the quad the
// vertex is (0 or 1 along it, -1 or 1 across it); the vertex shader widens it in screen space.
struct VolumeOutlineVertex {
  float from[3];
  float to[3];
  float color[4];
  float corner[2];
};

// What the buffers are made from (GL-free; tests read it): six wall vertices per wall (two
// triangles between neighbouring columns), six outline vertices per ceiling edge and per floor
// edge above the ground (never for a faded top: the cap is no limit).
struct VolumeMesh {
  glm::dvec3 origin{};
  std::vector<VolumeWallVertex> walls;
  std::vector<VolumeOutlineVertex> outlines;
};
VolumeMesh volume_mesh(const std::vector<scene::VolumeShape>& shapes);

// The uploaded mesh the volume pass draws.
struct VolumeDraw {
  glm::dvec3 origin{};
  VertexArray wall_array, outline_array;
  Buffer wall_buffer, outline_buffer;
  int wall_vertices = 0, outline_vertices = 0;
};

class VolumeGpu {
 public:
  // The draw of the set's visible volumes (nullptr: none to draw), uploading when the set, its
  // revision or the neutral ground changed. Valid until the next call.
  const VolumeDraw* draw(const scene::VolumeSet* set, double neutral_ground_m);

 private:
  const scene::VolumeSet* set_ = nullptr;
  std::uint64_t revision_ = 0;
  double neutral_ground_m_ = 0.0;
  std::optional<VolumeDraw> draw_;
};

}  // namespace trailray::render
