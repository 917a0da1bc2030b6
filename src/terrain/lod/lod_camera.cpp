#include "terrain/lod/lod_camera.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "geo/wgs84.hpp"

namespace trailray::terrain {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// Terrain never rises above this (Everest is 8849 m): the far plane must reach the horizon of
// such a peak, which can stand beyond the camera's own horizon and still be seen.
constexpr double kHighestTerrainM = 9000.0;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Distance from a point at height h to its horizon on a sphere of the equatorial radius.
double horizon_distance_m(double height_m) {
  const double h = std::max(height_m, 0.0);
  return std::sqrt(h * (2.0 * geo::wgs84::kA + h));
}

std::string describe(double lat, double lon, double h) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << lat << ", " << lon << ", " << h << " m)";
  return s.str();
}

// The camera's right and up, made exactly orthonormal to forward.
struct ScreenAxes {
  glm::dvec3 forward, right, up;
};
ScreenAxes screen_axes(const LodCamera& camera) {
  ScreenAxes axes;
  axes.forward = normalized(camera.forward);
  axes.right = normalized(glm::cross(axes.forward, camera.up));
  axes.up = glm::cross(axes.right, axes.forward);
  return axes;
}

}  // namespace

glm::dvec3 geodetic_up(double lat_deg, double lon_deg) {
  const double lat = lat_deg * kRadPerDeg, lon = lon_deg * kRadPerDeg;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

bool Frustum::contains(const glm::dvec3& p, double tolerance_m) const {
  for (const FrustumPlane& plane : planes) {
    if (plane.signed_distance(p) < -tolerance_m) return false;
  }
  return true;
}

std::optional<const char*> camera_problem(const LodCamera& camera) {
  if (!finite(camera.position)) return "camera position is not finite";
  if (!finite(camera.forward) || glm::length(camera.forward) == 0.0)
    return "camera forward is not a finite non-zero vector";
  if (!finite(camera.up) || glm::length(camera.up) == 0.0) return "camera up is not a finite non-zero vector";
  if (glm::length(glm::cross(normalized(camera.forward), normalized(camera.up))) < 1e-9)
    return "camera up is parallel to forward";
  if (!(camera.vertical_fov_rad > 0.0 && camera.vertical_fov_rad < std::numbers::pi)) {
    return "camera vertical field of view is not within (0, pi) radians";
  }
  if (camera.viewport_width_px == 0 || camera.viewport_height_px == 0) return "camera viewport is empty";
  if (!(camera.near_m > 0.0 && camera.far_m > camera.near_m && std::isfinite(camera.far_m))) {
    return "camera near/far distances are not 0 < near < far < infinity";
  }
  return std::nullopt;
}

LodCamera look_at(double lat_deg, double lon_deg, double height_m, double target_lat_deg, double target_lon_deg,
                  double target_height_m, double vertical_fov_rad, std::uint32_t viewport_width_px,
                  std::uint32_t viewport_height_px) {
  const std::string where = "look_at from " + describe(lat_deg, lon_deg, height_m) + " to " +
                            describe(target_lat_deg, target_lon_deg, target_height_m);
  for (double v : {lat_deg, lon_deg, height_m, target_lat_deg, target_lon_deg, target_height_m}) {
    if (!std::isfinite(v)) throw std::invalid_argument(where + ": a coordinate is not finite");
  }
  if (std::abs(lat_deg) > 90.0 || std::abs(target_lat_deg) > 90.0) {
    throw std::invalid_argument(where + ": latitude outside [-90, 90]");
  }
  if (!(vertical_fov_rad > 0.0 && vertical_fov_rad < std::numbers::pi)) {
    throw std::invalid_argument(where + ": vertical field of view " + std::to_string(vertical_fov_rad) +
                                " rad is not within (0, pi)");
  }
  if (viewport_width_px == 0 || viewport_height_px == 0) throw std::invalid_argument(where + ": empty viewport");

  LodCamera camera;
  camera.position = geo::ecef_from_geodetic(lat_deg, lon_deg, height_m);
  const glm::dvec3 to_target =
      geo::ecef_from_geodetic(target_lat_deg, target_lon_deg, target_height_m) - camera.position;
  if (glm::length(to_target) < 1e-6) throw std::invalid_argument(where + ": the target is at the camera's position");
  camera.forward = normalized(to_target);

  // Screen up: the local vertical with its component along the view removed. Looking (almost)
  // straight down or up that vanishes; north is then up, as on a map.
  const double lat = lat_deg * kRadPerDeg, lon = lon_deg * kRadPerDeg;
  const glm::dvec3 vertical = geodetic_up(lat_deg, lon_deg);
  glm::dvec3 up = vertical - camera.forward * glm::dot(vertical, camera.forward);
  if (glm::length(up) < 1e-6) {
    const glm::dvec3 north{-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)};
    up = north - camera.forward * glm::dot(north, camera.forward);
  }
  camera.up = normalized(up);

  camera.vertical_fov_rad = vertical_fov_rad;
  camera.viewport_width_px = viewport_width_px;
  camera.viewport_height_px = viewport_height_px;
  camera.near_m = 1.0;
  camera.far_m = horizon_distance_m(height_m) + horizon_distance_m(kHighestTerrainM) + 1000.0;
  return camera;
}

Frustum frustum_planes(const LodCamera& camera) {
  const ScreenAxes axes = screen_axes(camera);
  const double tan_v = std::tan(0.5 * camera.vertical_fov_rad);
  const double tan_h = tan_v * camera.aspect();
  // A side plane contains the camera and the frustum's edge directions forward +- tan * axis;
  // its inward normal is forward * tan -+ axis (normalised): orthogonal to those edges and with
  // a positive component along forward.
  auto through_camera = [&](const glm::dvec3& normal) {
    const glm::dvec3 n = normalized(normal);
    return FrustumPlane{n, -glm::dot(n, camera.position)};
  };
  Frustum f;
  f.planes[kFrustumLeft] = through_camera(axes.forward * tan_h + axes.right);
  f.planes[kFrustumRight] = through_camera(axes.forward * tan_h - axes.right);
  f.planes[kFrustumBottom] = through_camera(axes.forward * tan_v + axes.up);
  f.planes[kFrustumTop] = through_camera(axes.forward * tan_v - axes.up);
  f.planes[kFrustumNear] = FrustumPlane{axes.forward, -glm::dot(axes.forward, camera.position) - camera.near_m};
  f.planes[kFrustumFar] = FrustumPlane{axes.forward * -1.0, glm::dot(axes.forward, camera.position) + camera.far_m};
  return f;
}

std::optional<ScreenPoint> project_to_pixels(const LodCamera& camera, const glm::dvec3& point) {
  const ScreenAxes axes = screen_axes(camera);
  const glm::dvec3 v = point - camera.position;
  const double depth = glm::dot(v, axes.forward);
  if (!(depth > 0.0)) return std::nullopt;
  const double tan_v = std::tan(0.5 * camera.vertical_fov_rad);
  const double tan_h = tan_v * camera.aspect();
  // Normalised device coordinates in [-1, 1] across the viewport, y up.
  const double ndc_x = glm::dot(v, axes.right) / (depth * tan_h);
  const double ndc_y = glm::dot(v, axes.up) / (depth * tan_v);
  ScreenPoint s;
  s.x_px = 0.5 * (ndc_x + 1.0) * camera.viewport_width_px;
  s.y_px = 0.5 * (1.0 - ndc_y) * camera.viewport_height_px;
  s.depth_m = depth;
  return s;
}

glm::dvec3 ray_through_pixel(const LodCamera& camera, double x_px, double y_px) {
  const ScreenAxes axes = screen_axes(camera);
  const double tan_v = std::tan(0.5 * camera.vertical_fov_rad);
  const double tan_h = tan_v * camera.aspect();
  const double ndc_x = 2.0 * x_px / camera.viewport_width_px - 1.0;
  const double ndc_y = 1.0 - 2.0 * y_px / camera.viewport_height_px;
  return normalized(axes.forward + axes.right * (ndc_x * tan_h) + axes.up * (ndc_y * tan_v));
}

}  // namespace trailray::terrain
