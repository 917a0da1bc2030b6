#pragma once
// The renderer's camera: a perspective view placed in Earth-centred, Earth-fixed (ECEF, WGS84)
// metres, in doubles, and oriented by heading and pitch in the local east-north-up frame at the
// camera (roll is always 0: the screen's right is horizontal there). The same camera drives the
// terrain's level-of-detail selection (to_lod_camera) and every render pass.
//
// Precision (DESIGN.md): positions stay doubles on the CPU. The GPU sees float offsets from a
// per-object origin, and the matrices here take "origin minus camera" computed in double, so
// nothing near the camera loses precision however far it is from the Earth's centre or from
// any origin.
//
// GL conventions: right-handed view space looking down -Z, clip space depth in [-1, 1],
// column-major matrices (glm). Screen conventions as in terrain/lod/lod_camera.hpp: pixel (0, 0) is
// the top-left corner of the viewport, x grows right, y grows down, a pixel's centre is at
// (i + 0.5, j + 0.5).
//
// Depth precision, a hint for the passes: OpenGL ES 3.0 has no glClipControl, so reversed-Z
// gains nothing there (window depth = 0.5 * ndc + 0.5 rounds away the float precision near 0).
// With a 24-bit depth buffer the depth step at distance d is about d^2 / (near * 2^24): with
// near = 250 m it is 4 cm at 10 km and 40 m at 400 km. Passes that need more (tracks on
// distant terrain) compare the G-buffer's linear distance, or write a logarithmic depth,
// gl_FragDepth = log2(1 + w) / log2(1 + far) with w the clip-space w (the view depth).

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "geo/wgs84.hpp"
#include "terrain/lod/lod_camera.hpp"

namespace trailray::scene {

inline constexpr double kDefaultVerticalFovDeg = 45.0;

// A value, or why there is none: a message for the user that names the input and, for option
// text, the expected form.
template <class T>
struct Result {
  std::optional<T> value;
  std::string error;

  bool ok() const { return value.has_value(); }
};

// A geodetic position: degrees, and metres in the vertical datum of the terrain heights (which
// the terrain layer places on the WGS84 ellipsoid).
struct GeoPosition {
  double lat_deg = 0.0, lon_deg = 0.0, height_m = 0.0;
};

// What the image looks like: its vertical field of view and its size in pixels.
struct Lens {
  double vertical_fov_deg = kDefaultVerticalFovDeg;
  std::uint32_t width_px = 1920, height_px = 1080;

  double aspect() const { return static_cast<double>(width_px) / static_cast<double>(height_px); }
};

// Near and far clip distances along the view axis, metres.
struct DepthRange {
  double near_m = 1.0, far_m = 1.0e6;
};

// Near and far for a camera at `camera_height_m` (above the ellipsoid) whose nearest visible
// surface or object is `clearance_m` away (its height above the ground, or less where a track
// passes closer). Near is a quarter of the clearance, at least 0.5 m: a quarter, because the
// frustum's corners see the nearest point at an angle and terrain can rise in front of the
// camera. Far reaches the camera's horizon plus the horizon of anything up to 12 km high (peaks,
// and high flights), which can stand beyond the camera's own horizon and still be seen.
DepthRange depth_range_for(double camera_height_m, double clearance_m);

// Distance from a point `height_m` above a sphere of the WGS84 equatorial radius to its horizon;
// 0 at or below the surface.
double horizon_distance_m(double height_m);

// The camera's unit axes in ECEF: where it looks, the screen's right and the screen's up.
struct CameraAxes {
  glm::dvec3 forward, right, up;
};

// A ray from the camera's position: unit direction, both in ECEF.
struct Ray {
  glm::dvec3 origin{};
  glm::dvec3 direction;
};

class Camera {
 public:
  // Heading: degrees clockwise from north (any finite value, kept in [0, 360)); pitch: degrees
  // above the horizontal, within [-90, 90] (negative looks down). Throws std::invalid_argument
  // naming the values for a non-finite position or angle, a pitch outside [-90, 90], a field of
  // view outside (0, 180) degrees or an empty image; user input goes through camera_at /
  // camera_looking_at, which report such values as errors instead.
  Camera(const glm::dvec3& position, double heading_deg, double pitch_deg, const Lens& lens, const DepthRange& depth);

  const glm::dvec3& position() const { return position_; }
  // The camera's geodetic position (height above the ellipsoid).
  const GeoPosition& geodetic() const { return geodetic_; }
  double heading_deg() const { return heading_deg_; }
  double pitch_deg() const { return pitch_deg_; }
  const Lens& lens() const { return lens_; }
  const DepthRange& depth_range() const { return depth_; }
  const CameraAxes& axes() const { return axes_; }

  // A resized image keeps the vertical field of view (the picture widens, it is not zoomed).
  void set_image_size(std::uint32_t width_px, std::uint32_t height_px);
  void set_depth_range(const DepthRange& depth);

  // World-to-view rotation (ECEF directions into view space): the view matrix without its
  // translation, which is applied to "point minus camera" in double first.
  glm::dmat3 view_rotation() const;
  // The GL perspective projection (clip depth in [-1, 1]).
  glm::dmat4 projection() const;
  // Projection * view for vertices given as float offsets from `origin`: the translation
  // origin - camera is taken in double, the product rounded to float once. Column-major, ready
  // for glUniformMatrix4fv(location, 1, GL_FALSE, m.data()).
  std::array<float, 16> view_projection_relative_to(const glm::dvec3& origin) const;
  // origin - camera, computed in double and rounded once: the uniform for shaders that add it
  // to their float offsets before rotating.
  glm::vec3 origin_minus_camera(const glm::dvec3& origin) const;

  // A point's pixel and view depth (metres along the view axis); nullopt at or behind the camera
  // plane. Points outside the viewport or the depth range still get their pixel.
  std::optional<terrain::ScreenPoint> project(const glm::dvec3& point) const;
  // The ray through a (continuous) pixel, the inverse of project.
  Ray ray_through_pixel(double x_px, double y_px) const;

  // The row (continuous, y down) where the WGS84 ellipsoid's horizon crosses pixel column
  // `x_px`: exact for the ellipsoid, not a spherical approximation. When the column sees the
  // horizon twice (from orbit) it is the upper crossing. nullopt when the column does not see
  // the horizon in front of the camera (looking up, or the camera is at or below the ellipsoid).
  // The row may lie outside [0, height] when the horizon is above or below the image.
  std::optional<double> horizon_row_px(double x_px) const;

 private:
  glm::dvec3 position_;
  GeoPosition geodetic_;
  double heading_deg_ = 0.0, pitch_deg_ = 0.0;
  Lens lens_;
  DepthRange depth_;
  CameraAxes axes_;
};

// The camera as the level-of-detail selection sees it: the same position, orientation, field of
// view, image size and depth range.
terrain::LodCamera to_lod_camera(const Camera& camera);

// Unit east, north and up directions in ECEF at a geodetic position.
struct EnuAxes {
  glm::dvec3 east, north, up;
};
EnuAxes enu_axes_at(double lat_deg, double lon_deg);

// The ECEF position of a geodetic one.
inline glm::dvec3 ecef_from(const GeoPosition& p) { return geo::ecef_from_geodetic(p.lat_deg, p.lon_deg, p.height_m); }

// `--camera LAT,LON,ALT,HEADING,PITCH`: the camera's position (degrees, metres) and orientation.
struct CameraPlacement {
  GeoPosition position;
  double heading_deg = 0.0, pitch_deg = 0.0;
};

// `--look-at LAT,LON,ALT --distance M --heading DEG --pitch DEG`: the camera `distance_m` away
// from the target, looking at it with that heading and pitch (as seen at the target).
struct LookAt {
  GeoPosition target;
  double distance_m = 1000.0;
  double heading_deg = 0.0, pitch_deg = -45.0;
};

// Option text parsers. Errors quote the text and state the expected form and ranges.
Result<CameraPlacement> parse_camera_option(std::string_view text);
Result<GeoPosition> parse_look_at_option(std::string_view text);

// Cameras from the options. `ground_height_m` is the terrain height under the camera (under the
// target, for look-at; the neutral ground's height without terrain), which with the camera's
// height sets the depth range (a camera at or below it gets the smallest near plane). Errors
// name the option and the value.
Result<Camera> camera_at(const CameraPlacement& placement, const Lens& lens, double ground_height_m);
Result<Camera> camera_looking_at(const LookAt& look_at, const Lens& lens, double ground_height_m);

// Why a lens is unusable ("--fov ..." or "--size ..."), or nullopt.
std::optional<std::string> lens_problem(const Lens& lens);

}  // namespace trailray::scene
