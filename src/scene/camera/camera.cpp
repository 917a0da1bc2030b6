#include "scene/camera/camera.hpp"

#include <fast_float/fast_float.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "geo/wgs84.hpp"

namespace trailray::scene {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// Peaks (Everest 8849 m) and high flights (sailplanes in wave, 10-12 km) stay below this: the
// far plane reaches their horizon too.
constexpr double kHighestContentM = 12000.0;
constexpr double kSmallestNearM = 0.5;

std::string number(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

double wrapped_heading(double heading_deg) {
  double h = std::fmod(heading_deg, 360.0);
  if (h < 0.0) h += 360.0;
  return h == 0.0 ? 0.0 : h;  // no -0
}

// Forward, right and up of a view with this heading and pitch in an east-north-up frame.
CameraAxes axes_from_angles(const EnuAxes& enu, double heading_deg, double pitch_deg) {
  const double h = heading_deg * kRadPerDeg, p = pitch_deg * kRadPerDeg;
  const glm::dvec3 level = std::sin(h) * enu.east + std::cos(h) * enu.north;  // horizontal view direction
  CameraAxes axes;
  axes.forward = std::cos(p) * level + std::sin(p) * enu.up;
  axes.up = -std::sin(p) * level + std::cos(p) * enu.up;
  axes.right = std::cos(h) * enu.east - std::sin(h) * enu.north;  // = forward x up, horizontal: roll 0
  return axes;
}

// --- option text ---------------------------------------------------------------------------

std::string_view trimmed(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

std::optional<double> parse_number(std::string_view s) {
  s = trimmed(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = fast_float::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// The comma-separated numbers of `text`, one per name, or what is wrong with them.
Result<std::vector<double>> parse_numbers(std::string_view text, const std::vector<std::string_view>& names) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    fields.push_back(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (fields.size() != names.size()) {
    return {std::nullopt, std::to_string(fields.size()) + " value" + (fields.size() == 1 ? "" : "s") + " instead of " +
                              std::to_string(names.size())};
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::optional<double> v = parse_number(fields[i]);
    if (!v) return {std::nullopt, std::string(names[i]) + " '" + std::string(trimmed(fields[i])) + "' is not a number"};
    values.push_back(*v);
  }
  return {values, {}};
}

std::optional<std::string> position_problem(const GeoPosition& p) {
  if (!(std::abs(p.lat_deg) <= 90.0)) return "latitude " + number(p.lat_deg) + " is outside -90..90";
  if (!(std::abs(p.lon_deg) <= 180.0)) return "longitude " + number(p.lon_deg) + " is outside -180..180";
  if (!std::isfinite(p.height_m)) return "altitude is not a finite number";
  return std::nullopt;
}

std::optional<std::string> pitch_problem(double pitch_deg) {
  if (!(std::abs(pitch_deg) <= 90.0)) return "pitch " + number(pitch_deg) + " is outside -90..90";
  return std::nullopt;
}

constexpr std::string_view kCameraForm =
    "--camera expects LAT,LON,ALT,HEADING,PITCH: latitude -90..90 and longitude -180..180 in degrees, altitude in "
    "metres, heading in degrees clockwise from north (0 looks north), pitch -90..90 degrees (0 is level, negative "
    "looks down), e.g. --camera 46.68,7.86,3000,135,-25";
constexpr std::string_view kLookAtForm =
    "--look-at expects LAT,LON,ALT: latitude -90..90 and longitude -180..180 in degrees, altitude in metres, e.g. "
    "--look-at 46.70,7.88,1200 --distance 8000 --heading 135 --pitch -35";

std::string option_error(std::string_view form, std::string_view text, const std::string& problem) {
  return std::string(form) + "; got '" + std::string(text) + "': " + problem;
}

}  // namespace

double horizon_distance_m(double height_m) {
  const double h = std::max(height_m, 0.0);
  return std::sqrt(h * (2.0 * geo::wgs84::kA + h));
}

DepthRange depth_range_for(double camera_height_m, double clearance_m) {
  DepthRange d;
  d.near_m = std::max(kSmallestNearM, 0.25 * (std::isfinite(clearance_m) ? clearance_m : 0.0));
  d.far_m = horizon_distance_m(camera_height_m) + horizon_distance_m(kHighestContentM) + 1000.0;
  d.far_m = std::max(d.far_m, 4.0 * d.near_m);
  return d;
}

EnuAxes enu_axes_at(double lat_deg, double lon_deg) {
  const double lat = lat_deg * kRadPerDeg, lon = lon_deg * kRadPerDeg;
  const double slat = std::sin(lat), clat = std::cos(lat), slon = std::sin(lon), clon = std::cos(lon);
  return EnuAxes{{-slon, clon, 0.0}, {-slat * clon, -slat * slon, clat}, {clat * clon, clat * slon, slat}};
}

std::optional<std::string> lens_problem(const Lens& lens) {
  if (!(lens.vertical_fov_deg > 0.0 && lens.vertical_fov_deg < 180.0)) {
    return "--fov " + number(lens.vertical_fov_deg) + ": the vertical field of view must be within (0, 180) degrees";
  }
  if (lens.width_px == 0 || lens.height_px == 0) {
    return "--size " + std::to_string(lens.width_px) + "x" + std::to_string(lens.height_px) +
           ": width and height must be at least 1 pixel";
  }
  return std::nullopt;
}

// --- Camera --------------------------------------------------------------------------------

Camera::Camera(const glm::dvec3& position, double heading_deg, double pitch_deg, const Lens& lens,
               const DepthRange& depth)
    : position_(position), heading_deg_(wrapped_heading(heading_deg)), pitch_deg_(pitch_deg), lens_(lens) {
  const std::string where = "camera at ECEF (" + number(position.x) + ", " + number(position.y) + ", " +
                            number(position.z) + ") heading " + number(heading_deg) + " pitch " + number(pitch_deg);
  if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z)) {
    throw std::invalid_argument(where + ": the position is not finite");
  }
  if (!std::isfinite(heading_deg)) throw std::invalid_argument(where + ": the heading is not finite");
  if (const auto problem = pitch_problem(pitch_deg)) throw std::invalid_argument(where + ": " + *problem);
  if (const auto problem = lens_problem(lens)) throw std::invalid_argument(where + ": " + *problem);
  set_depth_range(depth);
  const geo::Geodetic g = geo::geodetic_from_ecef(position);
  geodetic_ = GeoPosition{g.lat_deg, g.lon_deg, g.height_m};
  axes_ = axes_from_angles(enu_axes_at(geodetic_.lat_deg, geodetic_.lon_deg), heading_deg_, pitch_deg_);
}

void Camera::set_image_size(std::uint32_t width_px, std::uint32_t height_px) {
  Lens lens = lens_;
  lens.width_px = width_px;
  lens.height_px = height_px;
  if (const auto problem = lens_problem(lens)) throw std::invalid_argument("camera: " + *problem);
  lens_ = lens;
}

void Camera::set_depth_range(const DepthRange& depth) {
  if (!(depth.near_m > 0.0 && depth.far_m > depth.near_m && std::isfinite(depth.far_m))) {
    throw std::invalid_argument("camera depth range near " + number(depth.near_m) + " m, far " + number(depth.far_m) +
                                " m: needs 0 < near < far < infinity");
  }
  depth_ = depth;
}

glm::dmat3 Camera::view_rotation() const {
  // The rows are the view axes (x right, y up, z backwards): a column-major matrix built from
  // them as columns, transposed.
  return glm::transpose(glm::dmat3(axes_.right, axes_.up, -axes_.forward));
}

glm::dmat4 Camera::projection() const {
  return glm::perspective(lens_.vertical_fov_deg * kRadPerDeg, lens_.aspect(), depth_.near_m, depth_.far_m);
}

std::array<float, 16> Camera::view_projection_relative_to(const glm::dvec3& origin) const {
  glm::dmat4 view(view_rotation());
  view = glm::translate(view, origin - position_);
  const glm::dmat4 m = projection() * view;
  std::array<float, 16> out{};
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row)
      out[static_cast<std::size_t>(column * 4 + row)] = static_cast<float>(m[column][row]);
  }
  return out;
}

glm::vec3 Camera::origin_minus_camera(const glm::dvec3& origin) const { return glm::vec3(origin - position_); }

std::optional<terrain::ScreenPoint> Camera::project(const glm::dvec3& point) const {
  const glm::dvec3 in_view = view_rotation() * (point - position_);
  const glm::dvec4 clip = projection() * glm::dvec4(in_view, 1.0);
  if (!(clip.w > 0.0)) return std::nullopt;
  terrain::ScreenPoint s;
  s.x_px = 0.5 * (clip.x / clip.w + 1.0) * lens_.width_px;
  s.y_px = 0.5 * (1.0 - clip.y / clip.w) * lens_.height_px;
  s.depth_m = -in_view.z;
  return s;
}

Ray Camera::ray_through_pixel(double x_px, double y_px) const {
  const double tan_v = std::tan(0.5 * lens_.vertical_fov_deg * kRadPerDeg);
  const double tan_h = tan_v * lens_.aspect();
  const double ndc_x = 2.0 * x_px / lens_.width_px - 1.0;
  const double ndc_y = 1.0 - 2.0 * y_px / lens_.height_px;
  return Ray{position_, glm::normalize(axes_.forward + (ndc_x * tan_h) * axes_.right + (ndc_y * tan_v) * axes_.up)};
}

std::optional<double> Camera::horizon_row_px(double x_px) const {
  // Scaling x and y by 1/a and z by 1/b turns the ellipsoid into the unit sphere and keeps
  // tangency: the horizon (the points P where the line of sight from C touches the ellipsoid)
  // becomes the circle of unit vectors Q with Q . C' = 1, C' the scaled camera. The column's rays
  // span a plane through C with normal n; scaled, it is m . Q = k. The two planes meet in a line
  // whose intersections with the unit sphere are the horizon points of this column.
  const double a = geo::wgs84::kA, b = a * (1.0 - geo::wgs84::kF);
  const glm::dvec3 camera = position_;
  const glm::dvec3 scaled_camera{camera.x / a, camera.y / a, camera.z / b};
  const double c2 = glm::dot(scaled_camera, scaled_camera);
  if (!(c2 > 1.0)) return std::nullopt;

  const double tan_h = std::tan(0.5 * lens_.vertical_fov_deg * kRadPerDeg) * lens_.aspect();
  const glm::dvec3 column_direction = axes_.forward + ((2.0 * x_px / lens_.width_px - 1.0) * tan_h) * axes_.right;
  const glm::dvec3 n = glm::normalize(glm::cross(column_direction, axes_.up));
  const glm::dvec3 m{n.x, n.y, n.z * (b / a)};  // (S^-1 n) / a
  const double k = glm::dot(n, camera) / a;

  // The line: Q0 + t u with Q0 = alpha C' + beta m in both planes, u orthogonal to both.
  const glm::dvec3 u = glm::cross(scaled_camera, m);
  const double cm = glm::dot(scaled_camera, m), m2 = glm::dot(m, m);
  const double det = c2 * m2 - cm * cm;
  if (!(det > 0.0)) return std::nullopt;
  const double alpha = (m2 - cm * k) / det, beta = (c2 * k - cm) / det;
  const glm::dvec3 q0 = alpha * scaled_camera + beta * m;
  const double remaining = 1.0 - glm::dot(q0, q0);
  if (!(remaining >= 0.0)) return std::nullopt;  // the column's plane misses the Earth
  const double t = std::sqrt(remaining / glm::dot(u, u));

  std::optional<double> row;
  for (const double sign : {-1.0, 1.0}) {
    const glm::dvec3 q = q0 + (sign * t) * u;
    const std::optional<terrain::ScreenPoint> s = project(glm::dvec3{q.x * a, q.y * a, q.z * b});
    if (s && (!row || s->y_px < *row)) row = s->y_px;
  }
  return row;
}

terrain::LodCamera to_lod_camera(const Camera& camera) {
  terrain::LodCamera lod;
  lod.position = camera.position();
  lod.forward = camera.axes().forward;
  lod.up = camera.axes().up;
  lod.vertical_fov_rad = camera.lens().vertical_fov_deg * kRadPerDeg;
  lod.viewport_width_px = camera.lens().width_px;
  lod.viewport_height_px = camera.lens().height_px;
  lod.near_m = camera.depth_range().near_m;
  lod.far_m = camera.depth_range().far_m;
  return lod;
}

// --- options -------------------------------------------------------------------------------

Result<CameraPlacement> parse_camera_option(std::string_view text) {
  const Result<std::vector<double>> numbers = parse_numbers(text, {"LAT", "LON", "ALT", "HEADING", "PITCH"});
  if (!numbers.ok()) return {std::nullopt, option_error(kCameraForm, text, numbers.error)};
  const std::vector<double>& v = *numbers.value;
  CameraPlacement placement{{v[0], v[1], v[2]}, v[3], v[4]};
  if (auto problem = position_problem(placement.position)) {
    return {std::nullopt, option_error(kCameraForm, text, *problem)};
  }
  if (auto problem = pitch_problem(placement.pitch_deg))
    return {std::nullopt, option_error(kCameraForm, text, *problem)};
  placement.heading_deg = wrapped_heading(placement.heading_deg);
  return {placement, {}};
}

Result<GeoPosition> parse_look_at_option(std::string_view text) {
  const Result<std::vector<double>> numbers = parse_numbers(text, {"LAT", "LON", "ALT"});
  if (!numbers.ok()) return {std::nullopt, option_error(kLookAtForm, text, numbers.error)};
  const std::vector<double>& v = *numbers.value;
  const GeoPosition target{v[0], v[1], v[2]};
  if (auto problem = position_problem(target)) return {std::nullopt, option_error(kLookAtForm, text, *problem)};
  return {target, {}};
}

Result<Camera> camera_at(const CameraPlacement& placement, const Lens& lens, double ground_height_m) {
  if (auto problem = position_problem(placement.position)) return {std::nullopt, "--camera: " + *problem};
  if (!std::isfinite(placement.heading_deg)) return {std::nullopt, "--camera: the heading is not a finite number"};
  if (auto problem = pitch_problem(placement.pitch_deg)) return {std::nullopt, "--camera: " + *problem};
  if (auto problem = lens_problem(lens)) return {std::nullopt, *problem};
  if (!std::isfinite(ground_height_m)) return {std::nullopt, "--camera: the ground height under the camera is unknown"};
  const double height = placement.position.height_m;
  return {Camera(ecef_from(placement.position), placement.heading_deg, placement.pitch_deg, lens,
                 depth_range_for(height, height - ground_height_m)),
          {}};
}

Result<Camera> camera_looking_at(const LookAt& look_at, const Lens& lens, double ground_height_m) {
  if (auto problem = position_problem(look_at.target)) return {std::nullopt, "--look-at: " + *problem};
  if (!(look_at.distance_m > 0.0 && std::isfinite(look_at.distance_m))) {
    return {std::nullopt, "--distance " + number(look_at.distance_m) + ": expects a distance in metres above 0"};
  }
  if (!std::isfinite(look_at.heading_deg)) {
    return {std::nullopt, "--heading: expects degrees clockwise from north, got a value that is not finite"};
  }
  if (!(std::abs(look_at.pitch_deg) <= 90.0)) {
    return {std::nullopt, "--pitch " + number(look_at.pitch_deg) +
                              ": expects degrees within -90..90 (0 is level, negative looks down)"};
  }
  if (auto problem = lens_problem(lens)) return {std::nullopt, *problem};
  if (!std::isfinite(ground_height_m))
    return {std::nullopt, "--look-at: the ground height under the target is unknown"};

  // The view direction is set at the target; the camera stands `distance` behind it. Its own
  // heading and pitch (in its own east-north-up frame, which is tilted from the target's by the
  // distance over the Earth's radius) are those of the same direction, so the target stays
  // exactly at the image centre.
  const glm::dvec3 target = ecef_from(look_at.target);
  const CameraAxes at_target = axes_from_angles(enu_axes_at(look_at.target.lat_deg, look_at.target.lon_deg),
                                                look_at.heading_deg, look_at.pitch_deg);
  const glm::dvec3 position = target - look_at.distance_m * at_target.forward;
  const geo::Geodetic at_camera = geo::geodetic_from_ecef(position);
  const double height = at_camera.height_m;
  const EnuAxes enu = enu_axes_at(at_camera.lat_deg, at_camera.lon_deg);
  const double east = glm::dot(at_target.forward, enu.east), north = glm::dot(at_target.forward, enu.north);
  const double up = std::clamp(glm::dot(at_target.forward, enu.up), -1.0, 1.0);
  // Straight down or up the heading only orients the screen: keep the one asked for.
  const double heading = std::hypot(east, north) > 1e-12 ? std::atan2(east, north) * kDegPerRad : look_at.heading_deg;
  const double pitch = std::asin(up) * kDegPerRad;
  const double clearance = std::min(look_at.distance_m, height - ground_height_m);
  return {Camera(position, heading, pitch, lens, depth_range_for(height, clearance)), {}};
}

}  // namespace trailray::scene
