#include "render/framing.hpp"

#include <GeographicLib/Geocentric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace trailray::render {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kHeadingStepDeg = 0.5;
// Points whose largest horizontal extent is less than this times their smallest have no clear
// short axis (a circle has 1, a square 1.41, a 2:1 ellipse 2).
constexpr double kMinElongation = 1.25;
// Extents within this fraction of the largest count as equal (a square's two sides).
constexpr double kShortAxisTie = 1e-6;
// Bisection on the distance stops at this relative precision.
constexpr double kDistanceTolerance = 1e-4;
constexpr int kCentringRounds = 6;

std::string number(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

double angle_between_headings(double a_deg, double b_deg) {
  const double d = std::fmod(std::abs(a_deg - b_deg), 360.0);
  return std::min(d, 360.0 - d);
}

struct Point2 {
  double x = 0.0, y = 0.0;  // east, north
};

double turn(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The convex hull (Andrew's monotone chain): the extent in any direction is that of the hull,
// usually a few dozen points where the track has thousands.
std::vector<Point2> convex_hull(std::vector<Point2> points) {
  std::sort(points.begin(), points.end(),
            [](const Point2& a, const Point2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (points.size() < 3) return points;
  std::vector<Point2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point2& p : points) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Minimum and maximum of the points along the unit direction (sin h, cos h), h in degrees.
struct Extent {
  double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity();
  double size() const { return max - min; }
  double middle() const { return 0.5 * (min + max); }
};
Extent extent_along(const std::vector<Point2>& points, double heading_deg) {
  const double s = std::sin(heading_deg * kRadPerDeg), c = std::cos(heading_deg * kRadPerDeg);
  Extent e;
  for (const Point2& p : points) {
    const double v = p.x * s + p.y * c;
    e.min = std::min(e.min, v);
    e.max = std::max(e.max, v);
  }
  return e;
}

// The heading along the points' short axis: the direction of their smallest extent, or the
// one of the two opposite ones closer to `preferred`. A shape without a clear short axis (a
// circle, a point) gets the preferred heading itself; where two axes are equally short (a
// square), the one closer to it.
double short_axis_heading(const std::vector<Point2>& hull, double preferred_deg) {
  std::vector<double> sizes;
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (double h = 0.0; h < 180.0; h += kHeadingStepDeg) {
    sizes.push_back(extent_along(hull, h).size());
    smallest = std::min(smallest, sizes.back());
    largest = std::max(largest, sizes.back());
  }
  if (!(largest > kMinElongation * smallest)) return preferred_deg;
  double best = preferred_deg, best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (sizes[i] > smallest + kShortAxisTie * largest) continue;
    for (const double h :
         {static_cast<double>(i) * kHeadingStepDeg, static_cast<double>(i) * kHeadingStepDeg + 180.0}) {
      const double gap = angle_between_headings(h, preferred_deg);
      if (gap < best_gap) best = h, best_gap = gap;
    }
  }
  return best;
}

// Where the points land in the image of a camera: their pixel bounds, and whether all are in
// front of it.
struct PixelBounds {
  double min_x = std::numeric_limits<double>::infinity(), max_x = -std::numeric_limits<double>::infinity();
  double min_y = std::numeric_limits<double>::infinity(), max_y = -std::numeric_limits<double>::infinity();
  bool all_in_front = true;
};
PixelBounds pixel_bounds(const Camera& camera, const std::vector<glm::dvec3>& points) {
  // project() for every point, with the matrices taken once.
  const glm::dmat3 rotation = camera.view_rotation();
  const glm::dmat4 projection = camera.projection();
  const glm::dvec3 eye = to_dvec3(camera.position());
  const double width = camera.lens().width_px, height = camera.lens().height_px;
  PixelBounds b;
  for (const glm::dvec3& p : points) {
    const glm::dvec3 v = rotation * (p - eye);
    const double depth = -v.z;
    if (!(depth > 0.0)) {
      b.all_in_front = false;
      return b;
    }
    const double x = 0.5 * (projection[0][0] * v.x / depth + 1.0) * width;
    const double y = 0.5 * (1.0 - projection[1][1] * v.y / depth) * height;
    b.min_x = std::min(b.min_x, x), b.max_x = std::max(b.max_x, x);
    b.min_y = std::min(b.min_y, y), b.max_y = std::max(b.max_y, y);
  }
  return b;
}

class Framer {
 public:
  Framer(std::vector<glm::dvec3> points, const FramingOptions& options, double ground_height_m)
      : points_(std::move(points)), options_(options), ground_height_m_(ground_height_m) {}

  Camera camera(const LookAt& look_at) const {
    Result<Camera> c = camera_looking_at(look_at, options_.lens, ground_height_m_);
    // The options and the ground were checked, targets come from the ellipsoid, distances are
    // positive: a refusal here is a bug, not bad input.
    if (!c.ok()) throw std::logic_error("framing built an invalid camera: " + c.error);
    return *c.value;
  }

  bool fits(const LookAt& look_at) const {
    const PixelBounds b = pixel_bounds(camera(look_at), points_);
    const double mx = options_.margin_fraction * options_.lens.width_px;
    const double my = options_.margin_fraction * options_.lens.height_px;
    return b.all_in_front && b.min_x >= mx && b.max_x <= options_.lens.width_px - mx && b.min_y >= my &&
           b.max_y <= options_.lens.height_px - my;
  }

  // The smallest distance (not below `min_distance`) at which the points fit; nullopt if none.
  std::optional<double> fitting_distance(LookAt look_at, double min_distance) const {
    look_at.distance_m = min_distance;
    if (fits(look_at)) return min_distance;
    double inside = min_distance, outside = min_distance;
    for (int i = 0; i < 64 && !fits(look_at); ++i) {
      outside = look_at.distance_m;
      look_at.distance_m *= 2.0;
    }
    if (!fits(look_at)) return std::nullopt;
    inside = look_at.distance_m;
    while (inside - outside > kDistanceTolerance * inside) {
      look_at.distance_m = 0.5 * (inside + outside);
      (fits(look_at) ? inside : outside) = look_at.distance_m;
    }
    return inside;
  }

  // The target moved so that the points' image is centred (seen from the same distance).
  GeoPosition centred_target(const LookAt& look_at) const {
    const Camera c = camera(look_at);
    const PixelBounds b = pixel_bounds(c, points_);
    const double metres_per_px = 2.0 * look_at.distance_m *
                                 std::tan(0.5 * options_.lens.vertical_fov_deg * kRadPerDeg) / options_.lens.height_px;
    const double dx = 0.5 * (b.min_x + b.max_x) - 0.5 * options_.lens.width_px;
    const double dy = 0.5 * (b.min_y + b.max_y) - 0.5 * options_.lens.height_px;
    const glm::dvec3 target = to_dvec3(ecef_from(look_at.target)) + (dx * metres_per_px) * c.axes().right -
                              (dy * metres_per_px) * c.axes().up;
    GeoPosition moved;
    GeographicLib::Geocentric::WGS84().Reverse(target.x, target.y, target.z, moved.lat_deg, moved.lon_deg,
                                               moved.height_m);
    return moved;
  }

  double centring_error_px(const LookAt& look_at) const {
    const PixelBounds b = pixel_bounds(camera(look_at), points_);
    return std::max(std::abs(b.min_x + b.max_x - options_.lens.width_px),
                    std::abs(b.min_y + b.max_y - options_.lens.height_px)) *
           0.5;
  }

  double nearest_point_distance(const Camera& c) const {
    const glm::dvec3 eye = to_dvec3(c.position());
    double nearest = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& p : points_) nearest = std::min(nearest, glm::length(p - eye));
    return nearest;
  }

 private:
  std::vector<glm::dvec3> points_;
  FramingOptions options_;
  double ground_height_m_;
};

std::optional<std::string> options_problem(const FramingOptions& o) {
  if (auto problem = lens_problem(o.lens)) return problem;
  if (!(o.pitch_deg >= -90.0 && o.pitch_deg <= -5.0))
    return "framing pitch " + number(o.pitch_deg) + " is outside -90..-5";
  if (!(o.margin_fraction >= 0.0 && o.margin_fraction <= 0.45)) {
    return "framing margin " + number(o.margin_fraction) + " is outside 0..0.45 of the image";
  }
  if (!std::isfinite(o.preferred_heading_deg)) return "framing preferred heading is not finite";
  if (!(o.min_view_width_m > 0.0 && std::isfinite(o.min_view_width_m))) {
    return "framing minimum view width " + number(o.min_view_width_m) + " m is not above 0";
  }
  return std::nullopt;
}

}  // namespace

Result<Framing> frame_points(std::span<const GeoPosition> points, const FramingOptions& options) {
  if (auto problem = options_problem(options)) return {std::nullopt, *problem};

  std::vector<GeoPosition> usable;
  double lowest = std::numeric_limits<double>::infinity();
  for (const GeoPosition& p : points) {
    if (!(std::abs(p.lat_deg) <= 90.0) || !(std::abs(p.lon_deg) <= 180.0)) continue;
    usable.push_back(p);
    if (std::isfinite(p.height_m)) lowest = std::min(lowest, p.height_m);
  }
  if (usable.empty()) {
    return {std::nullopt, "framing: none of the " + std::to_string(points.size()) +
                              " points has a latitude within -90..90 and a longitude within -180..180"};
  }
  const double ground = std::isfinite(options.ground_height_m) ? options.ground_height_m
                        : std::isfinite(lowest)                ? lowest
                                                               : 0.0;

  // Centre: the points' mean in ECEF, brought onto the ellipsoid; a local frame there.
  std::vector<glm::dvec3> ecef;
  glm::dvec3 sum(0.0);
  for (GeoPosition& p : usable) {
    if (!std::isfinite(p.height_m)) p.height_m = ground;
    ecef.push_back(to_dvec3(ecef_from(p)));
    sum += ecef.back();
  }
  double lat0 = 0.0, lon0 = 0.0;
  geo::from_ecef(to_ecef(sum / static_cast<double>(ecef.size())), lat0, lon0);
  const geo::LocalFrame frame(lat0, lon0, 0.0);
  std::vector<Point2> horizontal;
  double lowest_up = std::numeric_limits<double>::infinity(), highest_up = -lowest_up;
  for (const GeoPosition& p : usable) {
    const geo::Enu e = frame.to_local(p.lat_deg, p.lon_deg, p.height_m);
    horizontal.push_back({e.east, e.north});
    lowest_up = std::min(lowest_up, e.up), highest_up = std::max(highest_up, e.up);
  }

  const std::vector<Point2> hull = convex_hull(horizontal);
  const double heading = short_axis_heading(hull, options.preferred_heading_deg);
  // First target: the middle of the points' box seen from that heading; centring refines it.
  const Extent along = extent_along(hull, heading), across = extent_along(hull, heading + 90.0);
  const double hs = std::sin(heading * kRadPerDeg), hc = std::cos(heading * kRadPerDeg);
  const geo::Enu middle{along.middle() * hs + across.middle() * hc, along.middle() * hc - across.middle() * hs,
                        0.5 * (lowest_up + highest_up)};
  LookAt look_at;
  frame.to_geodetic(middle, look_at.target.lat_deg, look_at.target.lon_deg, look_at.target.height_m);
  look_at.heading_deg = heading;
  look_at.pitch_deg = options.pitch_deg;

  const Framer framer(std::move(ecef), options, ground);
  const double tan_h = std::tan(0.5 * options.lens.vertical_fov_deg * kRadPerDeg) * options.lens.aspect();
  const double min_distance = 0.5 * options.min_view_width_m / tan_h;
  for (int round = 0;; ++round) {
    const std::optional<double> distance = framer.fitting_distance(look_at, min_distance);
    if (!distance) return {std::nullopt, "framing: no camera distance fits the points in the image"};
    look_at.distance_m = *distance;
    if (round == kCentringRounds || framer.centring_error_px(look_at) < 0.5) break;
    look_at.target = framer.centred_target(look_at);
  }

  Camera camera = framer.camera(look_at);
  const double clearance = std::min(camera.geodetic().height_m - ground, framer.nearest_point_distance(camera));
  camera.set_depth_range(depth_range_for(camera.geodetic().height_m, clearance));
  return {Framing{look_at, camera}, {}};
}

}  // namespace trailray::render
