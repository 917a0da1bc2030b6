#pragma once
// Vertical volumes drawn translucent over the terrain: airspaces (--airspace FILE) and the
// cylinders of a competition task (--task FILE). A volume is a closed ring on the ground
// extruded between a floor and a ceiling; each limit is above mean sea level or above the
// terrain below each boundary point (a floor "1000 ft AGL" follows the ground). Built by the
// scene from the files; the renderer draws walls and the outlines of floor and ceiling; nothing
// here touches GL.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "geo/web_mercator.hpp"

namespace trailray::scene {

enum class VolumeHeightReference {
  Msl,     // metres above mean sea level
  Ground,  // metres above the terrain below each boundary point (0: on the ground)
};

struct VolumeLimit {
  VolumeHeightReference reference = VolumeHeightReference::Msl;
  double metres = 0.0;
  // No upper limit (UNL): drawn up to a height the scene chooses, faded out at the top.
  // For an unlimited (or capped) ceiling `metres` holds the height the scene chose to draw it at.
  bool unlimited = false;
};

enum class VolumeKind {
  Airspace,      // from an OpenAir file
  TaskCylinder,  // a task's turnpoint, start, ESS or goal cylinder
};

struct Volume {
  VolumeKind kind = VolumeKind::Airspace;
  std::string name;       // shown on hover and in labels
  std::string category;   // the airspace class ("CTR", "R", "D", ...) or the turnpoint's role
                          // ("takeoff", "SSS", "turnpoint", "ESS", "goal")
  std::string source;     // the file it came from
  std::int64_t line = 0;  // where in it (0: unknown)

  std::vector<geo::LatLon> boundary;  // closed ring, first point not repeated
  VolumeLimit floor;
  VolumeLimit ceiling;

  // The limits as written in the file ("FL 95", "2000 ft AGL", "GND"), shown on hover; empty:
  // the limits are printed from the numbers.
  std::string floor_text;
  std::string ceiling_text;
  // The terrain under each boundary point (metres above MSL), which limits above the ground stand
  // on: filled by place_volumes_on_ground (volume_shapes.hpp); empty until then.
  std::vector<double> ground_m;
  // A line (2 points: a cable) is drawn as one wall, not closed back to its start.
  bool closed = true;

  glm::vec3 color_srgb{0.8f, 0.2f, 0.2f};
  float opacity = 0.25f;  // of the walls; outlines are drawn opaque
  bool visible = true;
};

// The volumes of a scene; `revision` changes whenever what is drawn of them changes, so the
// renderer can keep their GPU buffers until then.
struct VolumeSet {
  std::vector<Volume> volumes;
  std::uint64_t revision = 0;
};

}  // namespace trailray::scene
