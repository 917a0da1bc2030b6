#include "render/passes/shadow_cascades.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace trailray::render {
namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

std::string vector_text(const glm::dvec3& v) {
  std::ostringstream out;
  out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return out.str();
}

void check_settings(const ShadowCascadeSettings& s) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("shadow cascades: " + what); };
  if (!(s.split_lambda >= 0.0 && s.split_lambda <= 1.0))
    fail("split lambda " + std::to_string(s.split_lambda) + " is outside [0, 1]");
  if (!(s.max_distance_m > 0.0) || !std::isfinite(s.max_distance_m))
    fail("max distance " + std::to_string(s.max_distance_m) + " m must be positive");
  if (s.map_size_px < 16 || s.map_size_px > 16384)
    fail("map size " + std::to_string(s.map_size_px) + " px is outside 16..16384");
  if (!(s.caster_height_span_m >= 0.0) || !std::isfinite(s.caster_height_span_m))
    fail("caster height span " + std::to_string(s.caster_height_span_m) + " m must be >= 0");
  if (!(s.min_sun_elevation_deg > 0.0 && s.min_sun_elevation_deg < 90.0))
    fail("minimum sun elevation " + std::to_string(s.min_sun_elevation_deg) + " deg is outside (0, 90)");
}

// Column-major float copy, the layout glUniformMatrix4fv takes.
std::array<float, 16> to_float_array(const glm::dmat4& m) {
  std::array<float, 16> out{};
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row)
      out[static_cast<std::size_t>(column * 4 + row)] = static_cast<float>(m[column][row]);
  }
  return out;
}

}  // namespace

std::array<double, kShadowCascadeCount + 1> practical_split_depths(double near_m, double far_m, double lambda) {
  std::array<double, kShadowCascadeCount + 1> splits{};
  const double n = static_cast<double>(kShadowCascadeCount);
  for (std::size_t i = 0; i <= kShadowCascadeCount; ++i) {
    const double t = static_cast<double>(i) / n;
    const double logarithmic = near_m * std::pow(far_m / near_m, t);
    const double uniform = near_m + (far_m - near_m) * t;
    splits[i] = lambda * logarithmic + (1.0 - lambda) * uniform;
  }
  // Exact ends: pow rounds, and the first and last cascade must meet the frustum's planes.
  splits.front() = near_m;
  splits.back() = far_m;
  return splits;
}

SliceSphere frustum_slice_sphere(const scene::Lens& lens, double near_m, double far_m) {
  // A slice corner at depth d lies at d * sqrt(k) off the axis, k = tan^2(half vertical fov) +
  // tan^2(half horizontal fov). The centre equidistant from the near and far corners is at
  // (near + far) (1 + k) / 2; past `far` (wide lenses, thin slices) the far corners' circle
  // alone decides.
  const double tan_vertical = std::tan(0.5 * lens.vertical_fov_deg * kRadPerDeg);
  const double tan_horizontal = tan_vertical * lens.aspect();
  const double k = tan_vertical * tan_vertical + tan_horizontal * tan_horizontal;
  SliceSphere sphere;
  sphere.centre_depth_m = 0.5 * (near_m + far_m) * (1.0 + k);
  if (sphere.centre_depth_m >= far_m) {
    sphere.centre_depth_m = far_m;
    sphere.radius_m = far_m * std::sqrt(k);
  } else {
    const double along = sphere.centre_depth_m - near_m;
    sphere.radius_m = std::sqrt(along * along + near_m * near_m * k);
  }
  return sphere;
}

glm::dmat3 light_rotation_for(const glm::dvec3& sun_unit) {
  // x perpendicular to the sun and the Earth's axis (east-like), unless the sun stands on the
  // axis; y completes a right-handed frame with z = sun. Rows of the rotation are the axes.
  const glm::dvec3 pole = std::abs(sun_unit.z) < 0.99 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 x = glm::normalize(glm::cross(pole, sun_unit));
  const glm::dvec3 y = glm::cross(sun_unit, x);
  return glm::transpose(glm::dmat3(x, y, sun_unit));
}

glm::dmat4 ShadowCascade::view_projection_relative_to_d(const glm::dvec3& origin_ecef) const {
  glm::dmat4 view(light_rotation);
  view = glm::translate(view, origin_ecef - eye_ecef);
  const glm::dmat4 projection = glm::ortho(-radius_m, radius_m, -radius_m, radius_m, 0.0, depth_extent_m);
  return projection * view;
}

std::array<float, 16> ShadowCascade::view_projection_relative_to(const glm::dvec3& origin) const {
  return to_float_array(view_projection_relative_to_d(origin));
}

glm::dvec3 ShadowCascade::texel_and_depth(const glm::dvec3& point_ecef, int map_size_px) const {
  // Relative to the point itself, so the matrix's translation is (point - eye) in double.
  const glm::dvec4 clip = view_projection_relative_to_d(point_ecef) * glm::dvec4(0.0, 0.0, 0.0, 1.0);
  const double size = static_cast<double>(map_size_px);
  return {(0.5 * clip.x + 0.5) * size, (0.5 * clip.y + 0.5) * size, 0.5 * clip.z + 0.5};
}

bool ShadowCascade::may_hold(const glm::dvec3& sphere_centre_ecef, double sphere_radius_m) const {
  // In the light's view space the box is |x|, |y| <= radius and depth (-z) in 0..depth_extent.
  const glm::dvec3 p = light_rotation * (sphere_centre_ecef - eye_ecef);
  const double r = sphere_radius_m;
  return std::abs(p.x) <= radius_m + r && std::abs(p.y) <= radius_m + r && -p.z + r >= 0.0 &&
         -p.z - r <= depth_extent_m;
}

ShadowCascades::ShadowCascades(const scene::Camera& camera, const glm::dvec3& sun_direction_ecef,
                               const ShadowCascadeSettings& settings)
    : settings_(settings), camera_position_(camera.position()) {
  check_settings(settings_);
  const double sun_length = glm::length(sun_direction_ecef);
  if (!std::isfinite(sun_length) || !(sun_length > 0.0))
    throw std::invalid_argument("shadow cascades: the sun direction " + vector_text(sun_direction_ecef) +
                                " is not a direction");
  sun_ = sun_direction_ecef / sun_length;

  const scene::DepthRange& depth = camera.depth_range();
  const double near_m = depth.near_m;
  const double far_m = std::max(std::min(depth.far_m, settings_.max_distance_m), near_m * 1.0001);
  const auto splits = practical_split_depths(near_m, far_m, settings_.split_lambda);

  // How far beyond the sphere casters can stand: a caster `span` above the receiver shades it
  // from span / sin(elevation) away along the sun ray; a low sun is limited by the minimum.
  const scene::EnuAxes enu = scene::enu_axes_at(camera.geodetic().lat_deg, camera.geodetic().lon_deg);
  const double sin_elevation = std::max(glm::dot(sun_, enu.up), std::sin(settings_.min_sun_elevation_deg * kRadPerDeg));
  const double caster_reach_m = settings_.caster_height_span_m / sin_elevation;

  const glm::dmat3 rotation = light_rotation_for(sun_);
  const glm::dvec3 camera_ecef = camera.position();
  const double map_size = static_cast<double>(settings_.map_size_px);
  for (std::size_t i = 0; i < kShadowCascadeCount; ++i) {
    ShadowCascade& c = cascades_[i];
    c.near_m = splits[i];
    c.far_m = splits[i + 1];
    const SliceSphere sphere = frustum_slice_sphere(camera.lens(), c.near_m, c.far_m);
    // One texel of margin: snapping moves the centre by up to half a texel.
    c.radius_m = sphere.radius_m * map_size / (map_size - 2.0);
    c.texel_size_m = 2.0 * c.radius_m / map_size;
    c.light_rotation = rotation;

    // Snap the centre's light-frame x and y (absolute ECEF, in double) to whole texels; its
    // depth along the sun stays, it only moves the depth range, never the texel grid.
    const glm::dvec3 centre = camera_ecef + camera.axes().forward * sphere.centre_depth_m;
    glm::dvec3 in_light = rotation * centre;
    in_light.x = std::round(in_light.x / c.texel_size_m) * c.texel_size_m;
    in_light.y = std::round(in_light.y / c.texel_size_m) * c.texel_size_m;
    c.centre_ecef = glm::transpose(rotation) * in_light;

    // Depth: from the eye (towards the sun) through the sphere; one radius of slack so that
    // receivers grazing the sphere's back and casters on its sun side both fit.
    const double reach_m = c.radius_m + caster_reach_m;
    c.eye_ecef = c.centre_ecef + sun_ * reach_m;
    c.depth_extent_m = reach_m + c.radius_m;

    c.constant_bias_m = settings_.constant_bias_texels * c.texel_size_m;
    c.slope_bias_m = settings_.slope_bias_texels * c.texel_size_m;
    c.normal_offset_m = settings_.normal_offset_texels * c.texel_size_m;
  }
}

std::array<float, kShadowCascadeCount> ShadowCascades::split_far_m() const {
  std::array<float, kShadowCascadeCount> out{};
  for (std::size_t i = 0; i < kShadowCascadeCount; ++i) out[i] = static_cast<float>(cascades_[i].far_m);
  return out;
}

ShadowCascades ShadowCascades::seen_from(const glm::dvec3& camera_position_ecef) const {
  ShadowCascades moved = *this;
  moved.camera_position_ = camera_position_ecef;
  return moved;
}

std::array<float, 16> ShadowCascades::camera_relative_matrix(std::size_t cascade) const {
  return cascades_.at(cascade).view_projection_relative_to(camera_position_);
}

}  // namespace trailray::render
