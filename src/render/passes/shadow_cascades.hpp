#pragma once
// Cascaded shadow maps, the CPU half: where the four cascades split the view, and for each a
// sun-aligned orthographic projection (thesis §3.1.1: four cascades; DESIGN.md "The frame",
// shadow pass). No GL here: shadow_maps.hpp renders and samples what this computes.
//
// Why each choice:
// - Splits: the "practical" scheme, a blend of logarithmic splits (constant texel size per
//   metre of view depth, good near the camera) and uniform splits (logarithmic alone spends
//   almost nothing on the distance); far capped at what matters for shadows (60 km: beyond,
//   the atmosphere hides them and a texel is larger than a valley).
// - Each cascade encloses its frustum slice's bounding sphere, not the slice's box: the sphere's
//   radius depends only on the lens and the split depths, so turning the camera never changes
//   the cascade's size (no texel size swimming).
// - The cascade's centre is snapped to whole texels in a light frame fixed in ECEF: moving the
//   camera moves the map by whole texels or not at all, so shadow edges do not shimmer.
// - The projection reaches towards the sun beyond the sphere far enough to include every caster
//   up to the terrain's height range (a peak outside the slice still shades a valley in it).
// - Bias scales with the texel size: a texel of a far cascade covers tens of metres of slope.
//
// Precision (DESIGN.md): centres are ECEF doubles; matrices take "origin minus centre" in double
// and are rounded to float once, like Camera::view_projection_relative_to.

#include <glm/glm.hpp>

#include <array>
#include <cstddef>

#include "scene/camera/camera.hpp"

namespace trailray::render {

inline constexpr std::size_t kShadowCascadeCount = 4;

struct ShadowCascadeSettings {
  double split_lambda = 0.7;              // 0: uniform splits, 1: logarithmic
  double max_distance_m = 60'000.0;       // shadows end here (or at the camera's far plane)
  int map_size_px = 2048;                 // each cascade's square depth map
  double caster_height_span_m = 4'000.0;  // highest caster minus lowest receiver in the view
  double min_sun_elevation_deg = 2.0;     // a lower sun reaches at most this far for casters
  // Receiver bias, in texels of the receiver's cascade. A plane tilted by theta against the sun
  // changes its light depth by tan(theta) per texel, and the 3x3 PCF with bilinear compares
  // reaches up to ~1.5 texels away: the normal offset (scaled by sin(theta), worth
  // tan(theta) texels of depth per texel of offset) plus the slope bias must exceed that, and
  // every texel more detaches shadows from their casters (peter-panning).
  double constant_bias_texels = 0.5;  // depth bias for every receiver
  double slope_bias_texels = 1.0;     // depth bias times tan(angle between normal and sun)
  double normal_offset_texels = 1.0;  // receiver moved along its normal, times sin(angle)
};

// One cascade: an orthographic light projection around `centre`, looking along -sun.
struct ShadowCascade {
  double near_m = 0.0, far_m = 0.0;  // the frustum slice, metres of view depth
  double radius_m = 0.0;             // the slice's bounding sphere + 1 texel: half the map's width
  double depth_extent_m = 0.0;       // light-space depth covered (sphere + reach towards the sun)
  double texel_size_m = 0.0;         // 2 * radius / map size
  double constant_bias_m = 0.0, slope_bias_m = 0.0, normal_offset_m = 0.0;
  glm::dvec3 centre_ecef{0.0};     // snapped to whole texels of the light frame
  glm::dvec3 eye_ecef{0.0};        // where the light's view starts: centre + sun * reach
  glm::dmat3 light_rotation{1.0};  // ECEF directions into the light's view space

  // Light view-projection for vertices given as float offsets from `origin` (clip depth in
  // [-1, 1], column-major, ready for glUniformMatrix4fv).
  std::array<float, 16> view_projection_relative_to(const glm::dvec3& origin) const;
  // The same in double, for tests and for the CPU (point -> clip).
  glm::dmat4 view_projection_relative_to_d(const glm::dvec3& origin_ecef) const;
  // A point's texel coordinates (x, y; continuous, 0..map size) and window depth (0..1).
  glm::dvec3 texel_and_depth(const glm::dvec3& point_ecef, int map_size_px) const;
  // Whether a sphere reaches into the cascade's light box (its square around the centre and its
  // depth range): casters that do not are left out of the cascade's map. Conservative: a sphere
  // near a corner of the box counts as inside.
  bool may_hold(const glm::dvec3& sphere_centre_ecef, double sphere_radius_m) const;
};

class ShadowCascades {
 public:
  // Cascades for `camera` lit from `sun_direction_ecef` (towards the sun; normalized here).
  // Throws std::invalid_argument naming the value for a zero or non-finite sun direction, a map
  // size outside 16..16384, a lambda outside [0, 1], a non-positive distance or negative span.
  ShadowCascades(const scene::Camera& camera, const glm::dvec3& sun_direction_ecef,
                 const ShadowCascadeSettings& settings = {});

  const std::array<ShadowCascade, kShadowCascadeCount>& cascades() const { return cascades_; }
  const ShadowCascade& operator[](std::size_t i) const { return cascades_.at(i); }
  const ShadowCascadeSettings& settings() const { return settings_; }
  const glm::dvec3& sun_direction_ecef() const { return sun_; }
  const glm::dvec3& camera_position() const { return camera_position_; }
  // The far view depth of each cascade: what the lookup compares a pixel's view depth with.
  std::array<float, kShadowCascadeCount> split_far_m() const;
  // Each cascade's view-projection for camera-relative positions (what the compose pass has).
  std::array<float, 16> camera_relative_matrix(std::size_t cascade) const;
  // The same cascades for lookups from another camera position: a frame drawn while the camera
  // moves reuses maps rendered for an earlier camera (their bounds stay where they were).
  ShadowCascades seen_from(const glm::dvec3& camera_position_ecef) const;

 private:
  ShadowCascadeSettings settings_;
  glm::dvec3 sun_;
  glm::dvec3 camera_position_{};
  std::array<ShadowCascade, kShadowCascadeCount> cascades_;
};

// The split depths near = s0 < s1 < ... < s4 = far of the practical scheme:
// s_i = lambda * near * (far / near)^(i / n) + (1 - lambda) * (near + (far - near) * i / n).
std::array<double, kShadowCascadeCount + 1> practical_split_depths(double near_m, double far_m, double lambda);

// The smallest sphere around the frustum slice between view depths near and far: its centre's
// distance along the view axis and its radius. Depends only on the lens, not on the camera's
// orientation or position.
struct SliceSphere {
  double centre_depth_m = 0.0, radius_m = 0.0;
};
SliceSphere frustum_slice_sphere(const scene::Lens& lens, double near_m, double far_m);

// ECEF directions into a light view space looking along -sun: its x and y axes are fixed by the
// sun alone (so texel snapping holds while the camera moves), z points towards the sun.
glm::dmat3 light_rotation_for(const glm::dvec3& sun_unit);

}  // namespace trailray::render
