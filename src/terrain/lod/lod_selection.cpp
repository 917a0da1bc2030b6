#include "terrain/lod/lod_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "geo/tile_id.hpp"
#include "geo/wgs84.hpp"
#include "terrain/codecs/height_encoding.hpp"

namespace trailray::terrain {
namespace {

using geo::wgs84::kA;
using geo::wgs84::kE2;
constexpr double kPi = std::numbers::pi;

// Latitude (radians) of the northern edge of XYZ row `row` at a zoom with `n` rows.
double row_edge_lat_rad(double row, double n) { return std::atan(std::sinh(kPi * (1.0 - 2.0 * row / n))); }

double prime_vertical_radius(double sin_lat) { return kA / std::sqrt(1.0 - kE2 * sin_lat * sin_lat); }

// The tile's latitude/longitude extent in radians.
struct TileExtent {
  double south, north, west, east;
};
TileExtent tile_extent(const TileId& tile) {
  const double n = std::ldexp(1.0, tile.zoom);
  return TileExtent{row_edge_lat_rad(tile.y + 1.0, n), row_edge_lat_rad(tile.y, n), 2.0 * kPi * tile.x / n - kPi,
                    2.0 * kPi * (tile.x + 1.0) / n - kPi};
}

// Ground width of a tile at the latitude of its edge nearest the equator (its widest).
double tile_ground_width_m(const TileId& tile, const TileExtent& e) {
  const double widest_lat = (e.south <= 0.0 && e.north >= 0.0) ? 0.0 : std::min(std::abs(e.south), std::abs(e.north));
  const double parallel_radius = prime_vertical_radius(std::sin(widest_lat)) * std::cos(widest_lat);
  return 2.0 * kPi * parallel_radius / std::ldexp(1.0, tile.zoom);
}

// A tile's bounding volume: a box in the east-north-up frame at the tile's centre, holding the
// tile's ground between its minimum and maximum heights. Built from a grid of points on the
// tile at both heights (corners, edge midpoints and centre; a finer grid for big low-zoom tiles,
// which bulge with the Earth's curvature), widened by the most the curved surface can rise
// between grid points, so that it contains the whole tile, not just the points.
struct TileVolume {
  glm::dvec3 centre{};
  std::array<glm::dvec3, 3> axes{};  // unit east, north, up at the tile's centre
  std::array<double, 3> half_extent;

  double distance_to(const glm::dvec3& p) const {
    const glm::dvec3 d = p - centre;
    double squared = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double outside = std::max(std::abs(glm::dot(d, axes[i])) - half_extent[i], 0.0);
      squared += outside * outside;
    }
    return std::sqrt(squared);
  }

  bool outside_of(const FrustumPlane& plane) const {
    double reach = 0.0;  // the box's extent along the plane's normal
    for (int i = 0; i < 3; ++i) reach += half_extent[i] * std::abs(glm::dot(plane.normal, axes[i]));
    return plane.signed_distance(centre) + reach < 0.0;
  }

  // Whether all of `points` lie beyond one face of the box (the other half of the separating-axis
  // test against the frustum: the planes alone keep boxes that pass near a frustum corner).
  bool separated_from(const std::array<glm::dvec3, 8>& points) const {
    for (int i = 0; i < 3; ++i) {
      bool all_above = true, all_below = true;
      for (const glm::dvec3& p : points) {
        const double q = glm::dot(p - centre, axes[i]);
        all_above = all_above && q > half_extent[i];
        all_below = all_below && q < -half_extent[i];
      }
      if (all_above || all_below) return true;
    }
    return false;
  }

  std::array<glm::dvec3, 8> corners() const {
    std::array<glm::dvec3, 8> c{};
    for (int k = 0; k < 8; ++k) {
      c[k] = centre + axes[0] * ((k & 1) ? half_extent[0] : -half_extent[0]) +
             axes[1] * ((k & 2) ? half_extent[1] : -half_extent[1]) +
             axes[2] * ((k & 4) ? half_extent[2] : -half_extent[2]);
    }
    return c;
  }
};

// Grid points are at most this far apart (radians): a zoom-0 tile gets 33 x 33 points, tiles from
// zoom 5 on the minimum 3 x 3. The bulge between points is then at most R (1 - cos(step)).
constexpr double kMaxSampleStepRad = 0.2;
constexpr int kMaxSamplesPerSide = 33;

// Points on a tile at its minimum and maximum heights (ECEF, relative to `origin`): a grid of
// samples x samples, odd, so that the middle point is the tile's centre.
class TileGrid {
 public:
  TileGrid(const TileExtent& e, float min_height_m, float max_height_m) : heights_{min_height_m, max_height_m} {
    const double span = std::max(e.north - e.south, e.east - e.west);
    samples_ = std::max(3, static_cast<int>(std::ceil(span / kMaxSampleStepRad)) + 1);
    samples_ = std::min(samples_ | 1, kMaxSamplesPerSide);
    const double lat_step = (e.north - e.south) / (samples_ - 1), lon_step = (e.east - e.west) / (samples_ - 1);
    for (int i = 0; i < samples_; ++i) {
      const double lat = e.south + lat_step * i, lon = e.west + lon_step * i;
      lats_[i] = {std::sin(lat), std::cos(lat)};
      lons_[i] = {std::sin(lon), std::cos(lon)};
    }
    // The surface rises above the chords between grid points by at most R (1 - cos(step)); a
    // centimetre more covers rounding.
    const double radius = kA + std::max(static_cast<double>(max_height_m), 0.0);
    bulge_m_ = radius * (1.0 - std::cos(std::max(lat_step, lon_step))) + 0.01;
  }

  int samples() const { return samples_; }
  double bulge_m() const { return bulge_m_; }
  struct Angle {
    double sin, cos;
  };
  Angle centre_lat() const { return lats_[samples_ / 2]; }
  Angle centre_lon() const { return lons_[samples_ / 2]; }

  // Calls visit(point - origin) for every grid point at both heights.
  template <class Visit>
  void for_each_point(const glm::dvec3& origin, Visit&& visit) const {
    for (int i = 0; i < samples_; ++i) {
      const double n = prime_vertical_radius(lats_[i].sin);
      for (const float height : heights_) {
        const double h = static_cast<double>(height);
        const double rho = (n + h) * lats_[i].cos;  // distance from the Earth's axis
        const double z = (n * (1.0 - kE2) + h) * lats_[i].sin - origin.z;
        for (int j = 0; j < samples_; ++j)
          visit(glm::dvec3{rho * lons_[j].cos - origin.x, rho * lons_[j].sin - origin.y, z});
      }
    }
  }

 private:
  std::array<float, 2> heights_;
  int samples_ = 3;
  double bulge_m_ = 0.0;
  std::array<Angle, kMaxSamplesPerSide> lats_{}, lons_{};
};

// The box in the east-north-up frame at the tile's centre around the grid's points, widened by
// the bulge between them.
TileVolume tile_volume(const TileGrid& grid) {
  const auto lat_c = grid.centre_lat(), lon_c = grid.centre_lon();
  const glm::dvec3 east{-lon_c.sin, lon_c.cos, 0.0};
  const glm::dvec3 north{-lat_c.sin * lon_c.cos, -lat_c.sin * lon_c.sin, lat_c.cos};
  const glm::dvec3 up{lat_c.cos * lon_c.cos, lat_c.cos * lon_c.sin, lat_c.sin};
  const double n_c = prime_vertical_radius(lat_c.sin);
  const glm::dvec3 origin{n_c * lat_c.cos * lon_c.cos, n_c * lat_c.cos * lon_c.sin, n_c * (1.0 - kE2) * lat_c.sin};

  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  grid.for_each_point(origin, [&](const glm::dvec3& p) {
    const double q[3] = {glm::dot(p, east), glm::dot(p, north), glm::dot(p, up)};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], q[k]);
      hi[k] = std::max(hi[k], q[k]);
    }
  });
  TileVolume v;
  v.axes = {east, north, up};
  v.centre = origin;
  for (int k = 0; k < 3; ++k) {
    v.centre = v.centre + v.axes[k] * (0.5 * (lo[k] + hi[k]));
    v.half_extent[k] = 0.5 * (hi[k] - lo[k]) + grid.bulge_m();
  }
  return v;
}

// Horizon culling. No terrain lies below kPlausibleMinHeightM (the deepest ocean floor), so the
// ball of radius b + that height (b the polar semi-axis, the ellipsoid's smallest radius; 200 m
// more for the geoid's undulation) is solid ground everywhere, and what it hides from the camera
// is not seen. What it hides includes the part of its tangent cone from the camera that lies
// beyond the plane of the tangent circle: a convex set H, so a tile is hidden when the corners of
// its box are in H, or (tighter for big tiles, whose boxes are loose) when its grid points are
// in H by more than the bulge between them.
class HorizonOccluder {
 public:
  explicit HorizonOccluder(const glm::dvec3& camera) : camera_(camera) {
    constexpr double kPolarRadiusM = kA * (1.0 - geo::wgs84::kF);
    const double radius = kPolarRadiusM + static_cast<double>(kPlausibleMinHeightM) - 200.0;
    const double distance = glm::length(camera);
    active_ = distance > radius;  // a camera inside the ball sees nothing of it as an occluder
    if (!active_) return;
    to_centre_ = camera * (-1.0 / distance);
    const double tangent = std::sqrt(distance * distance - radius * radius);
    plane_distance_ = tangent * tangent / distance;
    sin_half_angle_ = radius / distance;
    cos_half_angle_ = tangent / distance;
  }

  bool hides(const TileVolume& volume, const TileGrid& grid) const {
    if (!active_) return false;
    const auto corners = volume.corners();
    if (std::all_of(corners.begin(), corners.end(), [&](const glm::dvec3& p) { return inside(p - camera_, 0.0); })) {
      return true;
    }
    if (grid.samples() == 3 && volume.half_extent[0] < kBigTileM) return false;  // the box is tight enough
    bool all_inside = true;
    grid.for_each_point(camera_, [&](const glm::dvec3& p) { all_inside = all_inside && inside(p, grid.bulge_m()); });
    return all_inside;
  }

 private:
  // Tiles wider than this (zoom 7 and coarser) also get the test on their grid points.
  static constexpr double kBigTileM = 150e3;

  // Whether p - camera lies in H at least `margin` from its boundary (the plane and the cone's
  // side, distance |v| sin(half angle - angle off the axis)).
  bool inside(const glm::dvec3& v, double margin) const {
    const double along = glm::dot(v, to_centre_);
    if (along < plane_distance_ + margin) return false;
    const double off_axis = std::sqrt(std::max(glm::dot(v, v) - along * along, 0.0));
    return sin_half_angle_ * along - cos_half_angle_ * off_axis >= margin;
  }

  glm::dvec3 camera_{};
  glm::dvec3 to_centre_{};
  double plane_distance_ = 0.0, sin_half_angle_ = 0.0, cos_half_angle_ = 0.0;
  bool active_ = false;
};

// The corners of the camera's frustum: the near and far rectangles.
std::array<glm::dvec3, 8> frustum_corners(const LodCamera& camera) {
  const glm::dvec3 forward = normalized(camera.forward);
  const glm::dvec3 right = normalized(glm::cross(forward, camera.up));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tan_v = std::tan(0.5 * camera.vertical_fov_rad), tan_h = tan_v * camera.aspect();
  std::array<glm::dvec3, 8> c{};
  int k = 0;
  for (const double depth : {camera.near_m, camera.far_m}) {
    for (const double sx : {-1.0, 1.0}) {
      for (const double sy : {-1.0, 1.0}) {
        c[k++] = camera.position + (forward + right * (sx * tan_h) + up * (sy * tan_v)) * depth;
      }
    }
  }
  return c;
}

// A visible tile on its way through the selection.
struct Candidate {
  TileId id;
  std::pair<float, float> heights;  // the range its volume was built from, inherited by its children
  double distance_m = 0.0;
  double screen_error_px = 0.0;
};
bool less_error(const Candidate& a, const Candidate& b) { return a.screen_error_px < b.screen_error_px; }

class Selector {
 public:
  Selector(const LodCamera& camera, const LodSettings& settings, const HeightRange& height_range)
      : camera_(camera),
        settings_(settings),
        height_range_(height_range),
        frustum_(frustum_planes(camera)),
        frustum_corners_(frustum_corners(camera)),
        horizon_(camera.position) {}

  // The tile as a candidate when any of it can be seen; `inherited` is its parent's range.
  std::optional<Candidate> visit(const TileId& id, std::pair<float, float> inherited) const {
    std::pair<float, float> heights = inherited;
    if (height_range_) {
      // A range that is not a finite min <= max is no information.
      const auto known = height_range_(id);
      if (known && known->first <= known->second && std::isfinite(known->first) && std::isfinite(known->second)) {
        heights = *known;
      }
    }
    const TileExtent extent = tile_extent(id);
    const TileGrid grid(extent, heights.first, heights.second);
    const TileVolume volume = tile_volume(grid);
    for (const FrustumPlane& plane : frustum_.planes) {
      if (volume.outside_of(plane)) return std::nullopt;
    }
    if (volume.separated_from(frustum_corners_)) return std::nullopt;
    if (horizon_.hides(volume, grid)) return std::nullopt;
    Candidate c{id, heights, volume.distance_to(camera_.position), 0.0};
    const double geometric_error = tile_ground_width_m(id, extent) / settings_.tile_samples;
    c.screen_error_px = geometric_error * camera_.pixels_per_metre_at(std::max(c.distance_m, camera_.near_m));
    return c;
  }

  // The visible children of a candidate (none at kMaxTileZoom).
  std::vector<Candidate> visible_children(const Candidate& c) const {
    std::vector<Candidate> out;
    if (const auto kids = geo::children(c.id)) {
      for (const TileId& kid : *kids) {
        if (auto v = visit(kid, c.heights)) out.push_back(*v);
      }
    }
    return out;
  }

  SelectedTile selected(const Candidate& c) const {
    return SelectedTile{c.id, c.screen_error_px, c.distance_m,
                        camera_.pixels_per_metre_at(std::max(c.distance_m, camera_.near_m))};
  }

 private:
  const LodCamera& camera_;
  const LodSettings& settings_;
  const HeightRange& height_range_;
  Frustum frustum_;
  std::array<glm::dvec3, 8> frustum_corners_{};
  HorizonOccluder horizon_;
};

void check_settings(const LodSettings& s) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("lod settings: " + what); };
  if (s.min_zoom < 0 || s.max_zoom > geo::kMaxTileZoom || s.min_zoom > s.max_zoom) {
    fail("zooms " + std::to_string(s.min_zoom) + ".." + std::to_string(s.max_zoom) + " are not within 0.." +
         std::to_string(geo::kMaxTileZoom) + " in order");
  }
  if (!(s.max_screen_error_px > 0.0) || !std::isfinite(s.max_screen_error_px)) {
    fail("max_screen_error_px " + std::to_string(s.max_screen_error_px) + " is not a positive number");
  }
  if (s.tile_samples == 0) fail("tile_samples is 0");
  if (!(s.default_min_height_m <= s.default_max_height_m) || !std::isfinite(s.default_min_height_m) ||
      !std::isfinite(s.default_max_height_m)) {
    fail("default height range is not finite min <= max");
  }
}

// Most selected tiles the budgets allow.
std::size_t tile_limit(const LodSettings& s) {
  std::size_t limit = s.max_tiles;
  if (s.bytes_per_tile > 0) limit = std::min(limit, s.max_memory_bytes / s.bytes_per_tile);
  return limit;
}

}  // namespace

LodSelection select_tiles(const LodCamera& camera, const LodSettings& settings, const HeightRange& height_range) {
  if (const auto problem = camera_problem(camera)) throw std::invalid_argument(std::string("lod camera: ") + *problem);
  check_settings(settings);
  const Selector selector(camera, settings, height_range);
  const std::pair<float, float> default_heights{settings.default_min_height_m, settings.default_max_height_m};

  // Tiles coarser than min_zoom are no use to draw: split them all first.
  std::vector<Candidate> queue;
  if (auto root = selector.visit(TileId{0, 0, 0}, default_heights)) queue.push_back(*root);
  for (int zoom = 0; zoom < settings.min_zoom; ++zoom) {
    std::vector<Candidate> finer;
    for (const Candidate& c : queue) {
      for (Candidate& kid : selector.visible_children(c)) finer.push_back(kid);
    }
    queue = std::move(finer);
  }

  // Then split the tile with the largest screen error while it is too large and the budget
  // allows; once a split does not fit, the rest stay as they are.
  LodSelection result;
  const std::size_t limit = tile_limit(settings);
  bool budget_stopped = queue.size() > limit;
  result.budget_limited = budget_stopped;
  std::vector<Candidate> leaves;
  std::make_heap(queue.begin(), queue.end(), less_error);
  while (!queue.empty()) {
    std::pop_heap(queue.begin(), queue.end(), less_error);
    const Candidate c = queue.back();
    queue.pop_back();
    const bool wants_split = c.screen_error_px > settings.max_screen_error_px && c.id.zoom < settings.max_zoom;
    if (!wants_split || budget_stopped) {
      leaves.push_back(c);
      continue;
    }
    std::vector<Candidate> kids = selector.visible_children(c);
    if (queue.size() + leaves.size() + kids.size() > limit) {
      budget_stopped = result.budget_limited = true;
      leaves.push_back(c);
      continue;
    }
    for (Candidate& kid : kids) {
      queue.push_back(kid);
      std::push_heap(queue.begin(), queue.end(), less_error);
    }
  }

  result.tiles.reserve(leaves.size());
  for (const Candidate& c : leaves) result.tiles.push_back(selector.selected(c));
  // Most important first; ties in a fixed order so that equal views give equal lists.
  std::sort(result.tiles.begin(), result.tiles.end(), [](const SelectedTile& a, const SelectedTile& b) {
    if (a.priority != b.priority) return a.priority > b.priority;
    if (a.id.zoom != b.id.zoom) return a.id.zoom < b.id.zoom;
    if (a.id.y != b.id.y) return a.id.y < b.id.y;
    return a.id.x < b.id.x;
  });
  return result;
}

std::vector<TileId> tiles_to_draw(const LodSelection& selection, const std::function<bool(const TileId&)>& is_loaded) {
  std::vector<TileId> drawn;
  if (!is_loaded) return drawn;
  std::unordered_map<TileId, bool> loaded_memo;  // is_loaded may take a lock: ask once per tile
  auto loaded = [&](const TileId& id) {
    const auto [it, inserted] = loaded_memo.try_emplace(id, false);
    if (inserted) it->second = is_loaded(id);
    return it->second;
  };

  // Each wanted tile's stand-in: itself or its nearest loaded ancestor.
  std::unordered_set<TileId> stand_ins;
  std::vector<TileId> order;
  for (const SelectedTile& wanted : selection.tiles) {
    std::optional<TileId> t = geo::is_valid(wanted.id) ? std::optional<TileId>(wanted.id) : std::nullopt;
    while (t && !loaded(*t)) t = geo::parent(*t);
    if (t && stand_ins.insert(*t).second) order.push_back(*t);
  }
  // A stand-in under another one is covered by it: drop it, so nothing is drawn twice.
  for (const TileId& t : order) {
    bool covered = false;
    for (auto up = geo::parent(t); up && !covered; up = geo::parent(*up)) covered = stand_ins.contains(*up);
    if (!covered) drawn.push_back(t);
  }
  return drawn;
}

double geometric_error_m(const TileId& tile, std::uint32_t tile_samples) {
  if (!geo::is_valid(tile) || tile_samples == 0) return std::numeric_limits<double>::quiet_NaN();
  return tile_ground_width_m(tile, tile_extent(tile)) / tile_samples;
}

double skirt_depth_m(const TileId& tile, std::uint32_t tile_samples) {
  const double error = geometric_error_m(tile, tile_samples);
  if (std::isnan(error)) return kMinSkirtDepthM;
  return std::max(kMinSkirtDepthM, 4.0 * error);
}

}  // namespace trailray::terrain
