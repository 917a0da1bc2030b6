#include "scene/camera/framing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "geo/local_frame.hpp"
#include "geo/wgs84.hpp"

namespace trailray::scene {
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
// A framing clear of the kept-clear corner must be this much closer than one that moves the
// points less to be preferred.
constexpr double kCloserBy = 0.01;

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

// A rectangle of the image in pixels (x right, y down from the top-left corner).
struct PixelBox {
  double left = 0.0, top = 0.0, right = 0.0, bottom = 0.0;
  bool contains(double x, double y) const { return x >= left && x <= right && y >= top && y <= bottom; }
  double width() const { return right - left; }
  double height() const { return bottom - top; }
};

// Where the points land in the image of a camera: their pixel bounds, whether all are in front
// of it, and whether any falls into `clear` (when given).
struct PixelBounds {
  double min_x = std::numeric_limits<double>::infinity(), max_x = -std::numeric_limits<double>::infinity();
  double min_y = std::numeric_limits<double>::infinity(), max_y = -std::numeric_limits<double>::infinity();
  bool all_in_front = true;
  bool enters_clear = false;
};
PixelBounds pixel_bounds(const Camera& camera, const std::vector<glm::dvec3>& points,
                         const std::optional<PixelBox>& clear = std::nullopt) {
  // project() for every point, with the matrices taken once.
  const glm::dmat3 rotation = camera.view_rotation();
  const glm::dmat4 projection = camera.projection();
  const glm::dvec3 eye = camera.position();
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
    if (clear && clear->contains(x, y)) b.enters_clear = true;
  }
  return b;
}

// What a framing aims for: the points inside `box`, their image centred in it, none in `clear`.
struct FramingGoal {
  PixelBox box;
  std::optional<PixelBox> clear;
};

// The rectangle of a kept-clear corner in the image.
PixelBox corner_box(const KeptClearCorner& corner, double width, double height) {
  const bool left = corner.corner == ImageCorner::top_left || corner.corner == ImageCorner::bottom_left;
  const bool top = corner.corner == ImageCorner::top_left || corner.corner == ImageCorner::top_right;
  return {left ? 0.0 : width - corner.width_px, top ? 0.0 : height - corner.height_px, left ? corner.width_px : width,
          top ? corner.height_px : height};
}

// Where the points may go when the centred framing puts some into the kept-clear corner, in the
// order of preference (the least moved first): the whole image, points kept out one by one
// (which only moves them further away); then the box's edge next to the corner moved a third,
// two thirds and all the way past it, vertically (the points above or below the corner) and
// horizontally (beside it). Boxes too thin to hold anything, or whose centre lies in the corner
// (shrinking towards it never clears the corner), are left out.
std::vector<PixelBox> clearing_boxes(const PixelBox& margins, const PixelBox& clear, ImageCorner corner) {
  const bool left = corner == ImageCorner::top_left || corner == ImageCorner::bottom_left;
  const bool top = corner == ImageCorner::top_left || corner == ImageCorner::top_right;
  std::vector<PixelBox> boxes{margins};
  for (const double fraction : {1.0 / 3.0, 2.0 / 3.0, 1.0}) {
    PixelBox vertical = margins, horizontal = margins;
    if (top)
      vertical.top = std::max(margins.top, margins.top + fraction * (clear.bottom - margins.top));
    else
      vertical.bottom = std::min(margins.bottom, margins.bottom - fraction * (margins.bottom - clear.top));
    if (left)
      horizontal.left = std::max(margins.left, margins.left + fraction * (clear.right - margins.left));
    else
      horizontal.right = std::min(margins.right, margins.right - fraction * (margins.right - clear.left));
    boxes.push_back(vertical);
    boxes.push_back(horizontal);
  }
  std::erase_if(boxes, [&](const PixelBox& b) {
    return !(b.width() >= 1.0 && b.height() >= 1.0) ||
           clear.contains(0.5 * (b.left + b.right), 0.5 * (b.top + b.bottom));
  });
  return boxes;
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

  bool fits(const LookAt& look_at, const FramingGoal& goal) const {
    const PixelBounds b = pixel_bounds(camera(look_at), points_, goal.clear);
    return b.all_in_front && !b.enters_clear && b.min_x >= goal.box.left && b.max_x <= goal.box.right &&
           b.min_y >= goal.box.top && b.max_y <= goal.box.bottom;
  }

  bool enters(const LookAt& look_at, const PixelBox& clear) const {
    return pixel_bounds(camera(look_at), points_, clear).enters_clear;
  }

  // The smallest distance (not below `min_distance`) at which the points fit; nullopt if none.
  std::optional<double> fitting_distance(LookAt look_at, double min_distance, const FramingGoal& goal) const {
    look_at.distance_m = min_distance;
    if (fits(look_at, goal)) return min_distance;
    double inside = min_distance, outside = min_distance;
    for (int i = 0; i < 64 && !fits(look_at, goal); ++i) {
      outside = look_at.distance_m;
      look_at.distance_m *= 2.0;
    }
    if (!fits(look_at, goal)) return std::nullopt;
    inside = look_at.distance_m;
    while (inside - outside > kDistanceTolerance * inside) {
      look_at.distance_m = 0.5 * (inside + outside);
      (fits(look_at, goal) ? inside : outside) = look_at.distance_m;
    }
    return inside;
  }

  // The target moved so that the points' image is centred in the goal's box (seen from the same
  // distance).
  GeoPosition centred_target(const LookAt& look_at, const FramingGoal& goal) const {
    const Camera c = camera(look_at);
    const PixelBounds b = pixel_bounds(c, points_);
    const double metres_per_px = 2.0 * look_at.distance_m *
                                 std::tan(0.5 * options_.lens.vertical_fov_deg * kRadPerDeg) / options_.lens.height_px;
    const double dx = 0.5 * (b.min_x + b.max_x) - 0.5 * (goal.box.left + goal.box.right);
    const double dy = 0.5 * (b.min_y + b.max_y) - 0.5 * (goal.box.top + goal.box.bottom);
    const glm::dvec3 target =
        ecef_from(look_at.target) + (dx * metres_per_px) * c.axes().right - (dy * metres_per_px) * c.axes().up;
    const geo::Geodetic moved = geo::geodetic_from_ecef(target);
    return GeoPosition{moved.lat_deg, moved.lon_deg, moved.height_m};
  }

  double centring_error_px(const LookAt& look_at, const FramingGoal& goal) const {
    const PixelBounds b = pixel_bounds(camera(look_at), points_);
    return std::max(std::abs(b.min_x + b.max_x - (goal.box.left + goal.box.right)),
                    std::abs(b.min_y + b.max_y - (goal.box.top + goal.box.bottom))) *
           0.5;
  }

  // The closest view (not nearer than `min_distance`) reaching the goal, from `look_at`'s
  // heading and pitch: the fitting distance, then the target moved to centre the points, a few
  // rounds (each move changes the perspective a little). Whatever round it ends in, the points
  // fit. nullopt when no distance fits them.
  std::optional<LookAt> frame(LookAt look_at, double min_distance, const FramingGoal& goal) const {
    for (int round = 0;; ++round) {
      const std::optional<double> distance = fitting_distance(look_at, min_distance, goal);
      if (!distance) return std::nullopt;
      look_at.distance_m = *distance;
      if (round == kCentringRounds || centring_error_px(look_at, goal) < 0.5) return look_at;
      look_at.target = centred_target(look_at, goal);
    }
  }

  double nearest_point_distance(const Camera& c) const {
    const glm::dvec3 eye = c.position();
    double nearest = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& p : points_) nearest = std::min(nearest, glm::length(p - eye));
    return nearest;
  }

 private:
  std::vector<glm::dvec3> points_;
  FramingOptions options_;
  double ground_height_m_;
};

}  // namespace

bool area_holds_centre(const ImageArea& a, const Lens& lens, double margin_fraction) {
  const double mx = margin_fraction * (a.right_px - a.left_px), my = margin_fraction * (a.bottom_px - a.top_px);
  const double cx = 0.5 * lens.width_px, cy = 0.5 * lens.height_px;
  return a.left_px + mx < cx && a.right_px - mx > cx && a.top_px + my < cy && a.bottom_px - my > cy;
}

namespace {

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
  if (o.area) {
    const ImageArea& a = *o.area;
    const bool inside = a.left_px >= 0.0 && a.top_px >= 0.0 && a.right_px <= o.lens.width_px &&
                        a.bottom_px <= o.lens.height_px && a.right_px - a.left_px >= 16.0 &&
                        a.bottom_px - a.top_px >= 16.0;  // also false for NaN
    // The framing moves the camera away until the points fit: their image shrinks toward the
    // image's centre, so an area whose margins leave out the centre is never reached that way.
    const bool centred = area_holds_centre(a, o.lens, o.margin_fraction);
    if (!inside || !centred)
      return "framing area " + number(a.left_px) + "," + number(a.top_px) + " to " + number(a.right_px) + "," +
             number(a.bottom_px) + " px is not a rectangle of at least 16x16 px within the " +
             std::to_string(o.lens.width_px) + "x" + std::to_string(o.lens.height_px) + " image holding its centre";
  }
  const KeptClearCorner& k = o.keep_clear;
  if (!(k.width_px >= 0.0 && std::isfinite(k.width_px) && k.height_px >= 0.0 && std::isfinite(k.height_px))) {
    return "framing kept-clear corner " + number(k.width_px) + " x " + number(k.height_px) + " px is not a size";
  }
  return std::nullopt;
}

// The terrain height under the points: options.ground_height_m, else the lowest height among
// them (NaN: none has one), else sea level.
double ground_under(const FramingOptions& options, double lowest) {
  return std::isfinite(options.ground_height_m) ? options.ground_height_m : std::isfinite(lowest) ? lowest : 0.0;
}

// The framing of points given in ECEF over the ground at `ground` metres.
Result<Framing> frame_ecef(std::vector<glm::dvec3> ecef, double ground, const FramingOptions& options) {
  // Centre: the points' mean in ECEF, brought onto the ellipsoid; a local frame there.
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& p : ecef) sum += p;
  const geo::Geodetic centre = geo::geodetic_from_ecef(sum / static_cast<double>(ecef.size()));
  const geo::LocalFrame frame(centre.lat_deg, centre.lon_deg, 0.0);
  std::vector<Point2> horizontal;
  double lowest_up = std::numeric_limits<double>::infinity(), highest_up = -lowest_up;
  for (const glm::dvec3& p : ecef) {
    const geo::Enu e = frame.to_local(p);
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
  const double width = options.lens.width_px, height = options.lens.height_px;
  const PixelBox area = options.area ? PixelBox{options.area->left_px, options.area->top_px, options.area->right_px,
                                                options.area->bottom_px}
                                     : PixelBox{0.0, 0.0, width, height};
  const double mx = options.margin_fraction * area.width(), my = options.margin_fraction * area.height();
  const PixelBox margins{area.left + mx, area.top + my, area.right - mx, area.bottom - my};
  const std::optional<LookAt> centred = framer.frame(look_at, min_distance, {margins, std::nullopt});
  if (!centred) return {std::nullopt, "framing: no camera distance fits the points in the image"};
  look_at = *centred;
  if (!options.keep_clear.empty()) {
    const PixelBox clear = corner_box(options.keep_clear, width, height);
    if (framer.enters(look_at, clear)) {
      // The closest of the goals that keep the corner clear; a nearly equal distance does not
      // pay for moving the points further from the centre.
      std::optional<LookAt> best;
      for (const PixelBox& box : clearing_boxes(margins, clear, options.keep_clear.corner)) {
        const std::optional<LookAt> candidate = framer.frame(*centred, min_distance, {box, clear});
        if (candidate && (!best || candidate->distance_m < best->distance_m * (1.0 - kCloserBy))) best = candidate;
      }
      if (best) look_at = *best;
    }
  }

  Camera camera = framer.camera(look_at);
  const double clearance = std::min(camera.geodetic().height_m - ground, framer.nearest_point_distance(camera));
  camera.set_depth_range(depth_range_for(camera.geodetic().height_m, clearance));
  return {Framing{look_at, camera, ground}, {}};
}

}  // namespace

Result<Framing> frame_points(std::span<const GeoPosition> points, const FramingOptions& options) {
  if (auto problem = options_problem(options)) return {std::nullopt, *problem};
  std::vector<GeoPosition> usable;
  double lowest = std::numeric_limits<double>::quiet_NaN();
  for (const GeoPosition& p : points) {
    if (!(std::abs(p.lat_deg) <= 90.0) || !(std::abs(p.lon_deg) <= 180.0)) continue;
    usable.push_back(p);
    if (std::isfinite(p.height_m) && !(p.height_m >= lowest)) lowest = p.height_m;
  }
  if (usable.empty())
    return {std::nullopt, "framing: none of the " + std::to_string(points.size()) +
                              " points has a latitude within -90..90 and a longitude within -180..180"};
  const double ground = ground_under(options, lowest);
  std::vector<glm::dvec3> ecef;
  ecef.reserve(usable.size());
  for (const GeoPosition& p : usable)
    ecef.push_back(ecef_from({p.lat_deg, p.lon_deg, std::isfinite(p.height_m) ? p.height_m : ground}));
  return frame_ecef(std::move(ecef), ground, options);
}

Result<Framing> frame_tracks(std::span<const Track* const> tracks, const FramingOptions& options) {
  if (auto problem = options_problem(options)) return {std::nullopt, *problem};
  std::vector<glm::dvec3> ecef;
  double lowest = std::numeric_limits<double>::quiet_NaN();
  for (const Track* track : tracks) {
    const Track& t = *track;
    for (const TrackPolyline& line : t.geometry.segments)
      ecef.insert(ecef.end(), line.points_ecef.begin(), line.points_ecef.end());
    const double track_lowest = t.lowest_altitude();
    if (!(track_lowest >= lowest)) lowest = track_lowest;
  }
  if (ecef.empty()) return {std::nullopt, "framing: no track has a point"};
  return frame_ecef(std::move(ecef), ground_under(options, lowest), options);
}

Result<Framing> frame_tracks(const TrackSet& tracks, const FramingOptions& options) {
  std::vector<const Track*> visible;
  for (const Track& t : tracks.tracks())
    if (t.visible) visible.push_back(&t);
  return frame_tracks(visible, options);
}

std::vector<const Track*> largest_track_group(const TrackSet& tracks, double radius_m) {
  std::vector<const Track*> with_points;
  std::vector<glm::dvec3> centres;
  for (const Track& t : tracks.tracks()) {
    if (!t.visible) continue;
    glm::dvec3 sum(0.0);
    std::size_t count = 0;
    for (const TrackPolyline& line : t.geometry.segments)
      for (const glm::dvec3& p : line.points_ecef) sum += p, ++count;
    if (count == 0) continue;
    with_points.push_back(&t);
    centres.push_back(sum / static_cast<double>(count));
  }
  // Quadratic in the tracks: asked once for a first camera (10,000 tracks: 1e8 distances); a grid
  // of cells the radius wide would make it linear if seasons grow larger.
  const double radius2 = radius_m * radius_m;
  const auto near = [&](std::size_t a, std::size_t b) {
    const glm::dvec3 d = centres[a] - centres[b];
    return glm::dot(d, d) <= radius2;
  };
  std::size_t best = 0, best_count = 0;
  for (std::size_t a = 0; a < centres.size(); ++a) {
    std::size_t count = 0;
    for (std::size_t b = 0; b < centres.size(); ++b) count += near(a, b) ? 1 : 0;
    if (count > best_count) best = a, best_count = count;
  }
  std::vector<const Track*> group;
  for (std::size_t b = 0; b < centres.size(); ++b)
    if (near(best, b)) group.push_back(with_points[b]);
  return group;
}

}  // namespace trailray::scene
