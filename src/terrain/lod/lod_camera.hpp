#pragma once
// The camera as the level-of-detail selection (lod_selection.hpp) sees it: a perspective view in
// Earth-centred, Earth-fixed (ECEF, WGS84) metres, in doubles. ECEF rather than a local frame so
// that one camera works anywhere on the globe (across the antimeridian, over the poles, from
// orbit); doubles because ECEF coordinates are ~6.4e6 m and the selection wants metre accuracy.
// The renderer converts to a camera-relative float frame itself.
//
// Screen conventions: pixel (0, 0) is the top-left corner of the viewport, x grows right, y grows
// down; a pixel's centre is at (i + 0.5, j + 0.5).

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

namespace trailray::terrain {

// Points and directions: glm::dvec3, ECEF metres.

// a / |a|; the zero vector stays zero (callers check for degenerate directions themselves).
inline glm::dvec3 normalized(const glm::dvec3& a) {
  const double len = glm::length(a);
  return len > 0.0 ? a * (1.0 / len) : a;
}

// The local geodetic "up" (the ellipsoid normal) at a latitude and longitude: the direction of
// increasing height.
glm::dvec3 geodetic_up(double lat_deg, double lon_deg);

// A plane with its normal pointing into the frustum: a point p is on the inner side when
// signed_distance(p) >= 0.
struct FrustumPlane {
  glm::dvec3 normal{};  // unit
  double offset = 0.0;  // dot(normal, p) + offset is the signed distance in metres

  double signed_distance(const glm::dvec3& p) const { return glm::dot(normal, p) + offset; }
};

// Order of Frustum::planes.
enum FrustumSide { kFrustumLeft, kFrustumRight, kFrustumBottom, kFrustumTop, kFrustumNear, kFrustumFar };

struct Frustum {
  std::array<FrustumPlane, 6> planes;  // indexed by FrustumSide

  // Whether a point lies inside all six planes (within `tolerance_m` outside any of them).
  bool contains(const glm::dvec3& p, double tolerance_m = 0.0) const;
};

struct LodCamera {
  glm::dvec3 position{};                         // ECEF metres
  glm::dvec3 forward{};                          // unit: the view direction
  glm::dvec3 up{};                               // unit, orthogonal to forward: the screen's up direction
  double vertical_fov_rad = 1.0471975511965976;  // 60 degrees
  std::uint32_t viewport_width_px = 1920, viewport_height_px = 1080;
  double near_m = 1.0, far_m = 1.0e7;

  glm::dvec3 right() const { return glm::cross(forward, up); }
  double aspect() const { return static_cast<double>(viewport_width_px) / static_cast<double>(viewport_height_px); }

  // How many screen pixels one metre spans, seen face-on at `distance_m` along the view axis:
  // viewport_height / (2 * distance * tan(vfov / 2)). The screen-space error of the selection is
  // a tile's geometric error times this.
  double pixels_per_metre_at(double distance_m) const {
    return static_cast<double>(viewport_height_px) / (2.0 * distance_m * std::tan(0.5 * vertical_fov_rad));
  }
};

// Why a camera is unusable (non-finite or zero vectors, a field of view outside (0, pi), an empty
// viewport, near/far out of order); nullopt when it is fine. The selection refuses such a camera
// with this message.
std::optional<const char*> camera_problem(const LodCamera& camera);

// A camera at (lat, lon, height_m) looking at (target_lat, target_lon, target_height_m), heights
// above the WGS84 ellipsoid in metres, vertical field of view in radians. The screen's up is the
// local vertical as seen from the camera; looking straight down (or up) it is north. Near is 1 m;
// far reaches past the horizon of the camera plus that of a 9000 m peak, so that no visible
// terrain is clipped. Throws std::invalid_argument (naming the positions) for non-finite input,
// a target at the camera's position, a field of view outside (0, pi) or an empty viewport.
LodCamera look_at(double lat_deg, double lon_deg, double height_m, double target_lat_deg, double target_lon_deg,
                  double target_height_m, double vertical_fov_rad, std::uint32_t viewport_width_px,
                  std::uint32_t viewport_height_px);

// The six planes bounding what the camera sees, normals inward. `forward` and `up` are
// re-orthonormalised first, so a slightly non-orthogonal camera still gives a proper frustum.
Frustum frustum_planes(const LodCamera& camera);

// A point's place on the screen: pixels from the top-left corner of the viewport (continuous;
// outside [0, width] x [0, height] when the point is off screen) and its depth along the view
// axis in metres.
struct ScreenPoint {
  double x_px = 0.0, y_px = 0.0;
  double depth_m = 0.0;
};

// The perspective projection of an ECEF point; nullopt for points at or behind the camera plane
// (depth <= 0), which have no image.
std::optional<ScreenPoint> project_to_pixels(const LodCamera& camera, const glm::dvec3& point);

// The inverse: the unit direction of the ray from the camera through a (continuous) pixel.
glm::dvec3 ray_through_pixel(const LodCamera& camera, double x_px, double y_px);

}  // namespace trailray::terrain
