#include "scene/camera/camera_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geo/wgs84.hpp"

namespace trailray::scene {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRad = kPi / 180.0;

scene::GeoPosition geodetic(const glm::dvec3& p) {
  const geo::Geodetic g = geo::geodetic_from_ecef(p);
  return scene::GeoPosition{g.lat_deg, g.lon_deg, g.height_m};
}

glm::dvec3 ecef(const scene::GeoPosition& g) { return scene::ecef_from(g); }

// Heading and pitch (degrees) of a unit direction in the east-north-up frame at `at`.
void angles_of(const glm::dvec3& direction, const scene::GeoPosition& at, double& heading_deg, double& pitch_deg) {
  const scene::EnuAxes enu = scene::enu_axes_at(at.lat_deg, at.lon_deg);
  const double east = glm::dot(direction, enu.east), north = glm::dot(direction, enu.north);
  pitch_deg = std::asin(std::clamp(glm::dot(direction, enu.up), -1.0, 1.0)) / kRad;
  if (std::hypot(east, north) > 1e-12) heading_deg = std::atan2(east, north) / kRad;
  if (heading_deg < 0.0) heading_deg += 360.0;
}

double smoothstep(double t) { return t * t * (3.0 - 2.0 * t); }

// The shortest turn from heading a to heading b, degrees in (-180, 180].
double heading_delta(double a, double b) {
  double d = std::fmod(b - a, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

}  // namespace

CameraController::CameraController(const scene::LookAt& view, const scene::Lens& lens, GroundFunction ground,
                                   const CameraControls& controls)
    : view_(view), lens_(lens), ground_(std::move(ground)), controls_(controls) {
  view_.distance_m = std::clamp(view_.distance_m, controls_.min_distance_m, controls_.max_distance_m);
  view_.pitch_deg = std::clamp(view_.pitch_deg, controls_.min_pitch_deg, controls_.max_pitch_deg);
  keep_above_ground();
}

scene::LookAt CameraController::look_at_from_camera(const scene::Camera& camera, double ground_height_m,
                                                    double fallback_distance_m) {
  const glm::dvec3 c = camera.position();
  const glm::dvec3 f = camera.axes().forward;
  // The ellipsoid raised by the ground height: x^2/A^2 + y^2/A^2 + z^2/B^2 = 1.
  const double h = std::isfinite(ground_height_m) ? ground_height_m : 0.0;
  const double a = geo::wgs84::kA + h;
  const double b = geo::wgs84::kA * (1.0 - geo::wgs84::kF) + h;
  const glm::dvec3 scale(1.0 / (a * a), 1.0 / (a * a), 1.0 / (b * b));
  const double qa = glm::dot(f * f, scale), qb = 2.0 * glm::dot(c * f, scale), qc = glm::dot(c * c, scale) - 1.0;
  const double disc = qb * qb - 4.0 * qa * qc;
  double t = fallback_distance_m;
  if (disc >= 0.0) {
    const double near = (-qb - std::sqrt(disc)) / (2.0 * qa);
    if (near > 0.0) t = near;
  }
  scene::LookAt look;
  look.target = geodetic(c + t * f);
  look.distance_m = t;
  angles_of(f, look.target, look.heading_deg, look.pitch_deg);
  return look;
}

void CameraController::set_image_size(std::uint32_t width_px, std::uint32_t height_px) {
  lens_.width_px = std::max(1u, width_px);
  lens_.height_px = std::max(1u, height_px);
}

double CameraController::ground_at(double lat_deg, double lon_deg) const {
  if (!ground_) return std::numeric_limits<double>::quiet_NaN();
  return ground_(lat_deg, lon_deg);
}

scene::Camera CameraController::camera() const {
  double ground = ground_at(view_.target.lat_deg, view_.target.lon_deg);
  if (std::isnan(ground)) ground = view_.target.height_m;
  auto made = scene::camera_looking_at(view_, lens_, ground);
  if (!made.ok()) throw std::logic_error("viewer camera: " + made.error);
  return std::move(*made.value);
}

std::optional<scene::GeoPosition> CameraController::ground_point_at(double x_px, double y_px) const {
  const scene::Camera cam = camera();
  const scene::Ray ray = cam.ray_through_pixel(x_px, y_px);
  const glm::dvec3 o = ray.origin;
  // Height above the ground along the ray (the pivot's height where the ground is unknown).
  const auto above = [&](double t, scene::GeoPosition& at) {
    at = geodetic(o + t * ray.direction);
    double g = ground_at(at.lat_deg, at.lon_deg);
    if (std::isnan(g)) g = view_.target.height_m;
    return at.height_m - g;
  };
  scene::GeoPosition at;
  if (above(0.0, at) <= 0.0) return std::nullopt;  // the camera is in the ground
  // March out in growing steps until the ray is below the ground, then bisect.
  const double limit = 20.0 * view_.distance_m + 2.0 * scene::horizon_distance_m(cam.geodetic().height_m) + 1000.0;
  double previous = 0.0;
  for (double t = std::max(0.5, view_.distance_m * 0.002); t < limit; t *= 1.08) {
    if (above(t, at) <= 0.0) {
      double lo = previous, hi = t;
      for (int i = 0; i < 50; ++i) {
        const double mid = 0.5 * (lo + hi);
        (above(mid, at) > 0.0 ? lo : hi) = mid;
      }
      above(hi, at);
      return at;
    }
    previous = t;
  }
  return std::nullopt;
}

void CameraController::orbit(double dx_px, double dy_px) {
  flight_.reset();
  // Dragging right turns the ground to the right (the camera goes round to the left).
  view_.heading_deg = std::fmod(view_.heading_deg - dx_px * controls_.orbit_deg_per_px + 360.0, 360.0);
  if (view_.heading_deg < 0.0) view_.heading_deg += 360.0;
  // Dragging down lifts the camera over the pivot (looks more steeply down).
  view_.pitch_deg = std::clamp(view_.pitch_deg - dy_px * controls_.orbit_deg_per_px, controls_.min_pitch_deg,
                               controls_.max_pitch_deg);
  keep_above_ground();
}

void CameraController::pan(double from_x_px, double from_y_px, double to_x_px, double to_y_px) {
  flight_.reset();
  const auto from = ground_point_at(from_x_px, from_y_px);
  if (!from) return;
  // The point under `to` on the height of the point grabbed: a horizontal plane through it.
  const scene::Camera cam = camera();
  const scene::Ray ray = cam.ray_through_pixel(to_x_px, to_y_px);
  const glm::dvec3 a = ecef(*from);
  const glm::dvec3 up = scene::enu_axes_at(from->lat_deg, from->lon_deg).up;
  const double along = glm::dot(ray.direction, up);
  if (along > -1e-6) return;  // the cursor is above the horizon of that plane
  const double t = glm::dot(a - ray.origin, up) / along;
  const glm::dvec3 b = ray.origin + t * ray.direction;
  // Move everything by a - b: the grabbed point is then seen where b was, under the cursor.
  const double height = view_.target.height_m;
  view_.target = geodetic(ecef(view_.target) + (a - b));
  view_.target.height_m = height;
  keep_above_ground();
}

void CameraController::zoom(double steps, double x_px, double y_px) {
  flight_.reset();
  const double d = view_.distance_m;
  const double wanted = std::clamp(d * std::pow(controls_.zoom_factor_per_step, steps), controls_.min_distance_m,
                                   controls_.max_distance_m);
  const double s = wanted / d;
  const auto under_cursor = ground_point_at(x_px, y_px);
  if (under_cursor) {
    // Scaling the camera and the pivot about the point under the cursor keeps that point on
    // the same ray from the camera, so under the same pixel.
    const glm::dvec3 p = ecef(*under_cursor);
    view_.target = geodetic(p + s * (ecef(view_.target) - p));
  }
  view_.distance_m = wanted;
  keep_above_ground();
}

void CameraController::tilt(double degrees) {
  flight_.reset();
  view_.pitch_deg = std::clamp(view_.pitch_deg + degrees, controls_.min_pitch_deg, controls_.max_pitch_deg);
  keep_above_ground();
}

void CameraController::move(double right, double forward) {
  flight_.reset();
  const scene::EnuAxes enu = scene::enu_axes_at(view_.target.lat_deg, view_.target.lon_deg);
  const double h = view_.heading_deg * kRad;
  const glm::dvec3 ahead = std::cos(h) * enu.north + std::sin(h) * enu.east;
  const glm::dvec3 side = std::cos(h) * enu.east - std::sin(h) * enu.north;
  const double height = view_.target.height_m;
  view_.target = geodetic(ecef(view_.target) + view_.distance_m * (right * side + forward * ahead));
  view_.target.height_m = height;
  set_target_on_ground();
  keep_above_ground();
}

void CameraController::follow(const scene::GeoPosition& pivot, std::optional<double> heading_deg) {
  flight_.reset();
  view_.target = pivot;
  if (heading_deg && std::isfinite(*heading_deg)) view_.heading_deg = std::fmod(*heading_deg + 360.0, 360.0);
  keep_above_ground();
}

void CameraController::reset_north() {
  scene::LookAt north = view_;
  north.heading_deg = 0.0;
  fly_to(north);
}

void CameraController::fly_to(const scene::LookAt& target) {
  scene::LookAt to = target;
  to.distance_m = std::clamp(to.distance_m, controls_.min_distance_m, controls_.max_distance_m);
  to.pitch_deg = std::clamp(to.pitch_deg, controls_.min_pitch_deg, controls_.max_pitch_deg);
  flight_ = Flight{view_, to, 0.0};
  if (!(controls_.fly_seconds > 0.0)) update(0.0);
}

void CameraController::update(double seconds) {
  if (!flight_) return;
  flight_->elapsed_s += std::max(0.0, seconds);
  const double t = controls_.fly_seconds > 0.0 ? std::min(1.0, flight_->elapsed_s / controls_.fly_seconds) : 1.0;
  const double e = smoothstep(t);
  const scene::LookAt& a = flight_->from;
  const scene::LookAt& b = flight_->to;
  view_.target.lat_deg = a.target.lat_deg + e * (b.target.lat_deg - a.target.lat_deg);
  view_.target.lon_deg = a.target.lon_deg + e * heading_delta(a.target.lon_deg, b.target.lon_deg);
  if (view_.target.lon_deg > 180.0) view_.target.lon_deg -= 360.0;
  if (view_.target.lon_deg < -180.0) view_.target.lon_deg += 360.0;
  view_.target.height_m = a.target.height_m + e * (b.target.height_m - a.target.height_m);
  // Distance on a log scale: a flight from 100 km to 1 km does not rush through the last km.
  view_.distance_m = std::exp(std::log(a.distance_m) + e * (std::log(b.distance_m) - std::log(a.distance_m)));
  view_.heading_deg = std::fmod(a.heading_deg + e * heading_delta(a.heading_deg, b.heading_deg) + 360.0, 360.0);
  view_.pitch_deg = a.pitch_deg + e * (b.pitch_deg - a.pitch_deg);
  if (t >= 1.0) flight_.reset();
  keep_above_ground();
}

void CameraController::set_target_on_ground() {
  const double g = ground_at(view_.target.lat_deg, view_.target.lon_deg);
  if (!std::isnan(g)) view_.target.height_m = g;
}

void CameraController::keep_above_ground() {
  // Lift the camera: first look more steeply down (the camera rises on its sphere round the
  // pivot), then step back. Bounded: the clamps end it.
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 target = ecef(view_.target);
    const scene::EnuAxes enu = scene::enu_axes_at(view_.target.lat_deg, view_.target.lon_deg);
    const double h = view_.heading_deg * kRad, p = view_.pitch_deg * kRad;
    const glm::dvec3 forward = std::cos(p) * (std::cos(h) * enu.north + std::sin(h) * enu.east) + std::sin(p) * enu.up;
    const scene::GeoPosition at = geodetic(target - view_.distance_m * forward);
    double g = ground_at(at.lat_deg, at.lon_deg);
    if (std::isnan(g)) g = view_.target.height_m;  // unknown ground: the pivot's height
    if (at.height_m >= g + controls_.clearance_m) return;
    if (view_.pitch_deg > controls_.min_pitch_deg)
      view_.pitch_deg = std::max(controls_.min_pitch_deg, view_.pitch_deg - 1.0);
    else if (view_.distance_m < controls_.max_distance_m)
      view_.distance_m = std::min(controls_.max_distance_m, view_.distance_m * 1.1);
    else
      return;
  }
}

}  // namespace trailray::scene
