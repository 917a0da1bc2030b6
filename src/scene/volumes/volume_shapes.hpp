#pragma once
// A VolumeSet (volumes.hpp) as what is drawn and picked: for each visible volume a wall standing
// on its boundary, a column per boundary point from the floor to the ceiling in ECEF, with the
// terrain under the points that limits above the ground stand on. GL-free: the renderer's volume
// pass uploads these, and the viewer picks the volume under the mouse from them.

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/volumes/volumes.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::scene {

// Samples the terrain under the boundary points of every volume that has no ground yet (or a
// ground of another length), NaN where the source has none; bumps the revision when anything
// changed. `heights` nullptr: nothing to sample, the shapes stand on the neutral ground.
void place_volumes_on_ground(VolumeSet& set, terrain::HeightSource* heights);

// Floors on the ground are drawn this far below it, so that the wall meets the terrain between
// the sampled points too (where it is lower); the terrain hides what is below it.
inline constexpr double kBuriedFloorM = 60.0;
// A wall is at least this tall (a cable whose floor is its ceiling).
inline constexpr double kMinWallM = 20.0;

struct VolumeColumn {
  glm::dvec3 bottom_ecef{}, top_ecef{};
  double bottom_m = 0.0, top_m = 0.0;  // above MSL
};

struct VolumeShape {
  std::size_t volume = 0;             // index in the set
  std::vector<VolumeColumn> columns;  // one per boundary point
  bool closed = true;                 // the last column joins the first
  bool floor_outline = true;          // false for a floor on the ground (it would be buried)
  bool faded_top = false;             // an unlimited or capped ceiling: fades out upwards
  glm::vec3 color_srgb{1.0f};
  float opacity = 0.2f;
};

// The visible volumes' shapes: heights above MSL as they are, above the ground over the volume's
// ground_m at each point (`neutral_ground_m` where it is missing or NaN; NaN counts as 0).
std::vector<VolumeShape> volume_shapes(const VolumeSet& set, double neutral_ground_m);

struct VolumeHit {
  std::size_t volume = 0;  // index in the set
  double distance_m = 0.0;
};
// The nearest wall the ray meets before `max_distance_m` (the terrain's distance under the
// mouse, or infinity), nullopt when none.
std::optional<VolumeHit> pick_volume(const std::vector<VolumeShape>& shapes, const Ray& ray, double max_distance_m);

// The tooltip's lines: the name, then "class: CTR" (or "role: goal"), "floor: GND", "ceiling:
// 12959 ft" with the limits as written in the file, else from the numbers.
std::vector<std::string> volume_tooltip_lines(const Volume& volume);

// Shows or hides every volume of a kind and bumps the set's revision.
void set_volumes_visible(VolumeSet& set, VolumeKind kind, bool visible);

// Where an airspace's name is shown on the picture: over the middle of its boundary, halfway
// between its floor and its ceiling (an unlimited one: 1000 m over the floor), "CTR MEIRINGEN".
struct VolumeLabel {
  std::string text;
  glm::dvec3 anchor_ecef{};
  glm::vec3 color_srgb{1.0f};
};
std::vector<VolumeLabel> airspace_labels(const VolumeSet& set);

// A line for the tooltip: "CTR MEIRINGEN · GND – 6000 ft" (the limits as written in the file,
// else from the numbers).
std::string volume_description(const Volume& volume);

}  // namespace trailray::scene
