#include "terrain/lod/lod_selection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "geo/tile_id.hpp"
#include "geo/wgs84.hpp"

namespace trailray::terrain {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// --- Views -------------------------------------------------------------------------------------

// Above Interlaken at 3000 m, looking at the summit of the Eiger (3967 m), 1920 x 1080, 60 degrees.
LodCamera interlaken_to_eiger() { return look_at(46.68, 7.86, 3000.0, 46.577, 8.005, 3967.0, 60.0 * kDeg, 1920, 1080); }

// Straight down from 5000 m over Interlaken.
LodCamera top_down_interlaken() { return look_at(46.68, 7.86, 5000.0, 46.68, 7.86, 0.0, 60.0 * kDeg, 1920, 1080); }

HeightRange constant_range(float min_m, float max_m) {
  return [=](const TileId&) { return std::optional<std::pair<float, float>>({min_m, max_m}); };
}

// --- Independent geometry for the checks -------------------------------------------------------

// Where a ray from `origin` first meets the surface `height_m` above the ellipsoid (approximated
// by the ellipsoid with both semi-axes grown by height_m, which is within a metre of it for the
// heights used here), as latitude/longitude; nullopt when it misses.
std::optional<geo::LatLon> ground_hit(const glm::dvec3& origin, const glm::dvec3& dir, double height_m) {
  const double a = geo::wgs84::kA + height_m;
  const double b = geo::wgs84::kA * (1.0 - geo::wgs84::kF) + height_m;
  const double s = a / b;  // squash the ellipsoid into a sphere of radius a
  const glm::dvec3 o{origin.x, origin.y, origin.z * s}, d{dir.x, dir.y, dir.z * s};
  const double qa = glm::dot(d, d), qb = 2.0 * glm::dot(o, d), qc = glm::dot(o, o) - a * a;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (disc < 0.0) return std::nullopt;
  const double t = (-qb - std::sqrt(disc)) / (2.0 * qa);
  if (t <= 0.0) return std::nullopt;
  const glm::dvec3 p = origin + dir * t;
  const geo::Geodetic g = geo::geodetic_from_ecef(p);
  return geo::LatLon{g.lat_deg, g.lon_deg};
}

std::unordered_set<TileId> id_set(const LodSelection& selection) {
  std::unordered_set<TileId> ids;
  for (const SelectedTile& t : selection.tiles) ids.insert(t.id);
  return ids;
}

// How many of the tiles contain a position (at most one when they are disjoint).
int covering_count(const std::unordered_set<TileId>& ids, double lat, double lon) {
  int count = 0;
  for (int zoom = 0; zoom <= geo::kMaxTileZoom; ++zoom) {
    const auto t = geo::tile_containing(lat, lon, zoom);
    if (t && ids.contains(*t)) ++count;
  }
  return count;
}

// Fails the test when a tile of the list is an ancestor of another or listed twice.
void expect_disjoint(const std::vector<TileId>& tiles) {
  const std::unordered_set<TileId> ids(tiles.begin(), tiles.end());
  EXPECT_EQ(ids.size(), tiles.size()) << "a tile is listed twice";
  for (const TileId& t : tiles) {
    for (auto up = geo::parent(t); up; up = geo::parent(*up)) {
      EXPECT_FALSE(ids.contains(*up)) << geo::to_string(*up) << " overlaps its descendant " << geo::to_string(t);
    }
  }
}
void expect_disjoint(const LodSelection& selection) {
  std::vector<TileId> ids;
  for (const SelectedTile& t : selection.tiles) ids.push_back(t.id);
  expect_disjoint(ids);
}

// Casts rays through a grid of pixels and checks that where a ray meets the surface at
// `ground_height_m` (inside the Web Mercator square) exactly one selected tile holds the point.
// Returns how many rays met the ground.
int expect_ground_covered_once(const LodCamera& camera, const LodSelection& selection, double ground_height_m,
                               int columns = 48, int rows = 27) {
  const std::unordered_set<TileId> ids = id_set(selection);
  int hits = 0;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const double x = (i + 0.5) * camera.viewport_width_px / columns;
      const double y = (j + 0.5) * camera.viewport_height_px / rows;
      const auto ground = ground_hit(camera.position, ray_through_pixel(camera, x, y), ground_height_m);
      if (!ground || std::abs(ground->lat) > geo::kMercatorMaxLatDeg) continue;
      ++hits;
      EXPECT_EQ(covering_count(ids, ground->lat, ground->lon), 1)
          << "pixel (" << x << ", " << y << ") sees " << ground->lat << ", " << ground->lon;
    }
  }
  return hits;
}

// Points of a tile on a 9 x 9 grid at 9 heights from min to max (ECEF), from the tile_id
// functions.
std::vector<glm::dvec3> tile_points(const TileId& tile, double min_height_m, double max_height_m) {
  std::vector<glm::dvec3> points;
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      const auto ll = geo::latlon_from_tile_pixel(tile, 32.0 * i, 32.0 * j, 256);
      for (int k = 0; k <= 8; ++k) {
        const double h = min_height_m + (max_height_m - min_height_m) * k / 8.0;
        points.push_back(geo::ecef_from_geodetic(ll->lat, ll->lon, h));
      }
    }
  }
  return points;
}

const SelectedTile* nearest_tile(const LodSelection& s) {
  return &*std::min_element(s.tiles.begin(), s.tiles.end(),
                            [](const auto& a, const auto& b) { return a.distance_m < b.distance_m; });
}

const SelectedTile* tile_containing_point(const LodSelection& s, double lat, double lon) {
  for (const SelectedTile& t : s.tiles) {
    if (geo::tile_containing(lat, lon, t.id.zoom) == t.id) return &t;
  }
  return nullptr;
}

void expect_sane(const LodSelection& s, const LodSettings& settings) {
  EXPECT_LE(s.tiles.size(), settings.max_tiles);
  for (const SelectedTile& t : s.tiles) {
    EXPECT_TRUE(geo::is_valid(t.id)) << geo::to_string(t.id);
    EXPECT_GE(t.id.zoom, settings.min_zoom);
    EXPECT_LE(t.id.zoom, settings.max_zoom);
    EXPECT_TRUE(std::isfinite(t.screen_error_px) && t.screen_error_px >= 0.0) << geo::to_string(t.id);
    EXPECT_TRUE(std::isfinite(t.distance_m) && t.distance_m >= 0.0) << geo::to_string(t.id);
    EXPECT_TRUE(std::isfinite(t.priority) && t.priority > 0.0) << geo::to_string(t.id);
  }
  expect_disjoint(s);
}

// --- Selection ---------------------------------------------------------------------------------

TEST(LodSelection, TopDownViewMeetsTheErrorThreshold) {
  const LodCamera camera = top_down_interlaken();
  const LodSettings settings;  // 2 px, zoom 0..15, 600 tiles
  const LodSelection s = select_tiles(camera, settings, constant_range(0.0f, 1500.0f));
  expect_sane(s, settings);
  EXPECT_FALSE(s.budget_limited);
  ASSERT_GT(s.tiles.size(), 4u);
  for (const SelectedTile& t : s.tiles) {
    EXPECT_LE(t.screen_error_px, settings.max_screen_error_px) << geo::to_string(t.id);
  }
  // Under the camera the ground is at most 1500 m high, 3500 m away: 1080 / (2 * 3500 *
  // tan(30 deg)) = 0.267 px/m asks for samples at most 7.5 m apart. Zoom 14 tiles at 46.7 N are
  // 1683 m wide (6.6 m per sample), zoom 13 twice that: the tile under the camera is zoom 14.
  const SelectedTile* below = tile_containing_point(s, 46.68, 7.86);
  ASSERT_NE(below, nullptr);
  EXPECT_EQ(below->id.zoom, 14);
  EXPECT_NEAR(below->distance_m, 3500.0, 5.0);
  EXPECT_NEAR(below->screen_error_px, geometric_error_m(below->id) * camera.pixels_per_metre_at(3500.0), 0.01);
  for (const SelectedTile& t : s.tiles) EXPECT_LE(t.id.zoom, 14);

  EXPECT_GT(expect_ground_covered_once(camera, s, 0.0), 1000);
  EXPECT_GT(expect_ground_covered_once(camera, s, 1500.0), 1000);

  // A coarser threshold: 8 px allows 4x the sample spacing, two zoom levels less.
  LodSettings coarse = settings;
  coarse.max_screen_error_px = 8.0;
  const LodSelection c = select_tiles(camera, coarse, constant_range(0.0f, 1500.0f));
  EXPECT_LT(c.tiles.size(), s.tiles.size());
  EXPECT_EQ(tile_containing_point(c, 46.68, 7.86)->id.zoom, 12);
  expect_ground_covered_once(camera, c, 0.0);
}

TEST(LodSelection, ObliqueMountainViewIsFinerNearAndCoarserFar) {
  const LodCamera camera = interlaken_to_eiger();
  const LodSettings settings;
  const LodSelection s = select_tiles(camera, settings, constant_range(500.0f, 4200.0f));
  expect_sane(s, settings);
  EXPECT_FALSE(s.budget_limited);
  for (const SelectedTile& t : s.tiles) {
    EXPECT_TRUE(t.screen_error_px <= settings.max_screen_error_px || t.id.zoom == settings.max_zoom)
        << geo::to_string(t.id) << " " << t.screen_error_px;
  }
  // The zoom falls with the distance: a tile four times as far away (and at least 2 km) is
  // at least one level coarser (the screen error halves per level and with distance).
  int coarser_pairs = 0;
  for (const SelectedTile& near : s.tiles) {
    for (const SelectedTile& far : s.tiles) {
      if (far.distance_m < 4.0 * std::max(near.distance_m, 2000.0)) continue;
      EXPECT_LT(far.id.zoom, near.id.zoom) << geo::to_string(far.id) << " at " << far.distance_m << " m vs "
                                           << geo::to_string(near.id) << " at " << near.distance_m << " m";
      ++coarser_pairs;
    }
  }
  EXPECT_GT(coarser_pairs, 100);
  const auto [min_zoom, max_zoom] = std::minmax_element(
      s.tiles.begin(), s.tiles.end(), [](const auto& a, const auto& b) { return a.id.zoom < b.id.zoom; });
  EXPECT_EQ(max_zoom->id.zoom, settings.max_zoom);  // the mountain next to the camera
  EXPECT_LE(min_zoom->id.zoom, 9);                  // the distant Alps and plains
  // The Eiger's summit, 16 km away in the centre of the view, is drawn at a middle level.
  const SelectedTile* eiger = tile_containing_point(s, 46.577, 8.005);
  ASSERT_NE(eiger, nullptr);
  EXPECT_GE(eiger->id.zoom, 12);
  EXPECT_LT(eiger->id.zoom, max_zoom->id.zoom);

  EXPECT_GT(expect_ground_covered_once(camera, s, 600.0), 300);
  EXPECT_GT(expect_ground_covered_once(camera, s, 2000.0), 300);
}

TEST(LodSelection, PriorityFavoursNearTilesAndOrdersTheList) {
  const LodSelection s = select_tiles(interlaken_to_eiger(), LodSettings{}, constant_range(500.0f, 4200.0f));
  ASSERT_GT(s.tiles.size(), 10u);
  for (std::size_t i = 1; i < s.tiles.size(); ++i) EXPECT_GE(s.tiles[i - 1].priority, s.tiles[i].priority);
  for (const SelectedTile& a : s.tiles) {
    for (const SelectedTile& b : s.tiles) {
      if (a.distance_m < b.distance_m) {
        EXPECT_GE(a.priority, b.priority);
      }
    }
  }
  EXPECT_EQ(s.tiles.front().id, nearest_tile(s)->id);
}

TEST(LodSelection, SameViewSameTiles) {
  const LodSelection a = select_tiles(interlaken_to_eiger(), LodSettings{});
  const LodSelection b = select_tiles(interlaken_to_eiger(), LodSettings{});
  ASSERT_EQ(a.tiles.size(), b.tiles.size());
  for (std::size_t i = 0; i < a.tiles.size(); ++i) EXPECT_EQ(a.tiles[i].id, b.tiles[i].id);
}

TEST(LodSelection, DefaultHeightRangeCoversAnyTerrain) {
  // No height ranges known: every tile spans -500..9000 m, the camera at 3000 m is inside the
  // volumes around it, and the selection still covers the ground wherever it is.
  const LodCamera camera = interlaken_to_eiger();
  const LodSettings settings;
  const LodSelection s = select_tiles(camera, settings);
  expect_sane(s, settings);
  for (double h : {-400.0, 0.0, 600.0, 3000.0}) expect_ground_covered_once(camera, s, h);
  // The volume of the tile under the camera holds the camera.
  const SelectedTile* below = tile_containing_point(s, 46.68, 7.86);
  ASSERT_NE(below, nullptr);
  EXPECT_EQ(below->distance_m, 0.0);
  EXPECT_EQ(below->id.zoom, settings.max_zoom);
}

TEST(LodSelection, TilesBehindTheCameraAreCulled) {
  const LodCamera camera = interlaken_to_eiger();
  const LodSelection s = select_tiles(camera, LodSettings{}, constant_range(500.0f, 4200.0f));
  ASSERT_FALSE(s.tiles.empty());
  const Frustum frustum = frustum_planes(camera);
  for (const SelectedTile& t : s.tiles) {
    // Some point of the tile (between its heights) lies in front of the camera and within the
    // side planes, give or take a small part of the tile's size for the box around it.
    const std::vector<glm::dvec3> points = tile_points(t.id, 500.0, 4200.0);
    const double tolerance = 0.1 * glm::length(points.front() - points[720]) + 10.0;  // corner to corner
    const bool seen =
        std::any_of(points.begin(), points.end(), [&](const glm::dvec3& p) { return frustum.contains(p, tolerance); });
    EXPECT_TRUE(seen) << geo::to_string(t.id) << " is outside the view";
  }
  // Interlaken's lake, 10 km behind the camera (north-west), is in no selected tile; the
  // ground in front is.
  EXPECT_EQ(tile_containing_point(s, 46.74, 7.74), nullptr);
  EXPECT_NE(tile_containing_point(s, 46.62, 7.94), nullptr);

  // Looking straight up from above ground no higher than 2000 m: nothing to see.
  const LodCamera sky = look_at(46.68, 7.86, 3000.0, 46.68, 7.86, 10000.0, 60.0 * kDeg, 1920, 1080);
  EXPECT_TRUE(select_tiles(sky, LodSettings{}, constant_range(0.0f, 2000.0f)).tiles.empty());
}

TEST(LodSelection, HeightRangesDecideWhatIsInView) {
  // The camera at 1000 m looks 30 degrees up: the bottom edge of the view is level, so flat
  // ground at 0 m is out of sight. A 4000 m peak 10 km to the north is in sight.
  const double peak_lat = 46.68 + 10000.0 / 111200.0, peak_lon = 7.86;
  const LodCamera camera = look_at(46.68, 7.86, 1000.0, 46.68 + 0.009, 7.86, 1000.0 + 1000.0 * std::tan(30.0 * kDeg),
                                   60.0 * kDeg, 1920, 1080);
  const LodSettings settings;

  const LodSelection flat = select_tiles(camera, settings, constant_range(0.0f, 0.0f));
  EXPECT_TRUE(flat.tiles.empty()) << flat.tiles.size() << " tiles, first " << geo::to_string(flat.tiles[0].id);

  // Tiles holding the peak reach 4000 m; the rest is flat.
  auto with_peak = [&](const TileId& id) {
    const bool has_peak = geo::tile_containing(peak_lat, peak_lon, id.zoom) == id;
    return std::optional<std::pair<float, float>>({0.0f, has_peak ? 4000.0f : 0.0f});
  };
  const LodSelection peak = select_tiles(camera, settings, with_peak);
  expect_sane(peak, settings);
  const SelectedTile* summit = tile_containing_point(peak, peak_lat, peak_lon);
  ASSERT_NE(summit, nullptr);
  EXPECT_GE(summit->id.zoom, 12);  // 10 km away: fine enough to show the peak
  for (const SelectedTile& t : peak.tiles) {
    EXPECT_EQ(geo::tile_containing(peak_lat, peak_lon, t.id.zoom), t.id) << "only the peak's tiles are in view";
  }

  // Known only at zoom 6: finer tiles inherit their zoom-6 ancestor's range (the peak's tile
  // reaches 4000 m), and the result is the same as for a range known everywhere.
  std::set<int> asked_zooms;
  auto zoom6_only = [&](const TileId& id) -> std::optional<std::pair<float, float>> {
    asked_zooms.insert(id.zoom);
    if (id.zoom != 6) return std::nullopt;
    const bool has_peak = geo::tile_containing(peak_lat, peak_lon, 6) == id;
    return std::pair<float, float>{0.0f, has_peak ? 4000.0f : 0.0f};
  };
  const LodSelection inherited = select_tiles(camera, settings, zoom6_only);
  EXPECT_GT(asked_zooms.size(), 7u);  // also asked for the finer tiles
  ASSERT_NE(tile_containing_point(inherited, peak_lat, peak_lon), nullptr);
  // With [0, 4000] over the whole zoom-6 tile more of it is in view than the peak alone, and
  // everything in view lies in that tile.
  EXPECT_GE(inherited.tiles.size(), peak.tiles.size());
  const TileId peak6 = *geo::tile_containing(peak_lat, peak_lon, 6);
  for (const SelectedTile& t : inherited.tiles) {
    TileId up = t.id;
    while (up.zoom > 6) up = *geo::parent(up);
    EXPECT_EQ(up, peak6) << geo::to_string(t.id);
  }
  // Unknown everywhere: the default range (up to 9000 m) keeps the peak in view too.
  const LodSelection unknown = select_tiles(camera, settings);
  EXPECT_NE(tile_containing_point(unknown, peak_lat, peak_lon), nullptr);
}

TEST(LodSelection, BudgetsAreRespectedAndSpentOnNearTilesFirst) {
  const LodCamera camera = interlaken_to_eiger();
  const LodSelection full = select_tiles(camera, LodSettings{}, constant_range(500.0f, 4200.0f));
  ASSERT_GT(full.tiles.size(), 120u);

  LodSettings tight;
  tight.max_tiles = 60;
  const LodSelection s = select_tiles(camera, tight, constant_range(500.0f, 4200.0f));
  expect_sane(s, tight);
  EXPECT_TRUE(s.budget_limited);
  EXPECT_GT(s.tiles.size(), 50u);  // the budget is used, not abandoned
  // Still no gaps and no overlaps: a budget makes tiles coarser, never missing.
  expect_ground_covered_once(camera, s, 600.0);
  expect_ground_covered_once(camera, s, 2000.0);
  // Near tiles keep their detail, far ones give it up: the nearest tile is as fine as without
  // a budget, and the tiles in the nearest quarter are finer on average than in the farthest.
  EXPECT_EQ(nearest_tile(s)->id.zoom, nearest_tile(full)->id.zoom);
  std::vector<SelectedTile> by_distance = s.tiles;
  std::sort(by_distance.begin(), by_distance.end(),
            [](const auto& a, const auto& b) { return a.distance_m < b.distance_m; });
  const std::size_t quarter = by_distance.size() / 4;
  double near_zoom = 0.0, far_zoom = 0.0;
  for (std::size_t i = 0; i < quarter; ++i) {
    near_zoom += by_distance[i].id.zoom;
    far_zoom += by_distance[by_distance.size() - 1 - i].id.zoom;
  }
  const double count = static_cast<double>(quarter);
  EXPECT_GT(near_zoom / count, far_zoom / count + 3.0);
  // The far tiles are the ones left too coarse.
  const auto worst = std::max_element(s.tiles.begin(), s.tiles.end(), [](const auto& a, const auto& b) {
    return a.screen_error_px < b.screen_error_px;
  });
  EXPECT_GT(worst->screen_error_px, tight.max_screen_error_px);

  // The memory budget counts too: 25 tiles' worth.
  LodSettings memory;
  memory.bytes_per_tile = 1000;
  memory.max_memory_bytes = 25 * 1000 + 999;
  const LodSelection m = select_tiles(camera, memory, constant_range(500.0f, 4200.0f));
  EXPECT_TRUE(m.budget_limited);
  EXPECT_LE(m.tiles.size(), 25u);
  EXPECT_GT(m.tiles.size(), 15u);
  expect_ground_covered_once(camera, m, 600.0);

  // A budget smaller than the tiles at min_zoom: those are returned anyway, flagged.
  LodSettings tiny;
  tiny.min_zoom = 8;
  tiny.max_tiles = 1;
  const LodSelection t = select_tiles(camera, tiny, constant_range(500.0f, 4200.0f));
  EXPECT_TRUE(t.budget_limited);
  EXPECT_GT(t.tiles.size(), 1u);
  for (const SelectedTile& tile : t.tiles) EXPECT_EQ(tile.id.zoom, 8);
  expect_ground_covered_once(camera, t, 600.0);
}

TEST(LodSelection, MinZoomAndMaxZoomBoundTheLevels) {
  const LodCamera camera = interlaken_to_eiger();
  LodSettings settings;
  settings.min_zoom = 10;
  settings.max_zoom = 12;
  const LodSelection s = select_tiles(camera, settings, constant_range(500.0f, 4200.0f));
  expect_sane(s, settings);
  EXPECT_FALSE(s.budget_limited);
  std::set<int> zooms;
  for (const SelectedTile& t : s.tiles) zooms.insert(t.id.zoom);
  EXPECT_EQ(zooms, (std::set<int>{10, 11, 12}));
  expect_ground_covered_once(camera, s, 600.0);
}

TEST(LodSelection, AntimeridianViewSelectsBothSides) {
  // Over Taveuni (Fiji) at 2000 m looking east across 180 degrees.
  const LodCamera camera = look_at(-16.8, 179.95, 2000.0, -16.8, -179.8, 0.0, 60.0 * kDeg, 1920, 1080);
  const LodSettings settings;
  const LodSelection s = select_tiles(camera, settings, constant_range(0.0f, 1200.0f));
  expect_sane(s, settings);
  bool west_edge = false, east_edge = false;
  for (const SelectedTile& t : s.tiles) {
    const std::uint32_t last = (std::uint32_t{1} << t.id.zoom) - 1;
    if (t.id.zoom >= 6 && t.id.x == last) east_edge = true;  // just west of 180
    if (t.id.zoom >= 6 && t.id.x == 0) west_edge = true;     // just east of -180
  }
  EXPECT_TRUE(west_edge && east_edge);
  EXPECT_GT(expect_ground_covered_once(camera, s, 0.0), 300);
  EXPECT_NE(tile_containing_point(s, -16.8, -179.8), nullptr);
  EXPECT_NE(tile_containing_point(s, -16.8, 179.97), nullptr);
}

TEST(LodSelection, PolarViewsStaySane) {
  const LodSettings settings;
  // Straight down at the pole: the pyramid ends at 85.05 degrees, which a 60 degree view from
  // 50 km does not reach.
  const LodCamera pole = look_at(89.9, 10.0, 50000.0, 89.9, 10.0, 0.0, 60.0 * kDeg, 1920, 1080);
  const LodSelection at_pole = select_tiles(pole, settings);
  expect_sane(at_pole, settings);
  // From 84 N, 20 km up, looking towards the pole: the northern row of every zoom.
  const LodCamera north = look_at(84.0, -40.0, 20000.0, 87.0, -40.0, 0.0, 60.0 * kDeg, 1920, 1080);
  const LodSelection s = select_tiles(north, settings);
  expect_sane(s, settings);
  ASSERT_FALSE(s.tiles.empty());
  EXPECT_TRUE(std::any_of(s.tiles.begin(), s.tiles.end(), [](const auto& t) { return t.id.y == 0 && t.id.zoom > 4; }));
  EXPECT_GT(expect_ground_covered_once(north, s, 0.0), 100);
  // Over the south pole from orbit.
  const LodCamera south = look_at(-89.0, 0.0, 3.0e6, -90.0, 0.0, 0.0, 60.0 * kDeg, 1920, 1080);
  const LodSelection s2 = select_tiles(south, settings);
  expect_sane(s2, settings);
  expect_ground_covered_once(south, s2, 0.0);
}

TEST(LodSelection, TilesBeyondTheHorizonAreCulled) {
  // 2000 km above (0, 0) with a 120 degree view: the whole Earth is inside the frustum, but
  // only ground within acos(R / (R + 2000 km)) = 40 degrees of (0, 0) can be seen.
  const LodCamera camera = look_at(0.0, 0.0, 2.0e6, 0.0, 0.0, 0.0, 120.0 * kDeg, 1920, 1080);
  const LodSettings settings;
  const LodSelection s = select_tiles(camera, settings, constant_range(-500.0f, 9000.0f));
  expect_sane(s, settings);
  const glm::dvec3 sub_camera = geodetic_up(0.0, 0.0);
  for (const SelectedTile& t : s.tiles) {
    const std::vector<glm::dvec3> points = tile_points(t.id, 0.0, 0.0);
    const double nearest_angle_deg =
        std::acos(std::transform_reduce(
            points.begin(), points.end(), -1.0, [](double a, double b) { return std::max(a, b); },
            [&](const glm::dvec3& p) { return glm::dot(normalized(p), sub_camera); })) /
        kDeg;
    EXPECT_LT(nearest_angle_deg, 55.0) << geo::to_string(t.id) << " lies behind the horizon";
  }
  EXPECT_GT(expect_ground_covered_once(camera, s, 0.0), 200);
}

TEST(LodSelection, RefusesUnusableInput) {
  const LodCamera camera = interlaken_to_eiger();
  LodSettings s;
  s.min_zoom = 5;
  s.max_zoom = 4;
  EXPECT_THROW(select_tiles(camera, s), std::invalid_argument);
  s = LodSettings{};
  s.max_zoom = 31;
  EXPECT_THROW(select_tiles(camera, s), std::invalid_argument);
  s = LodSettings{};
  s.max_screen_error_px = 0.0;
  EXPECT_THROW(select_tiles(camera, s), std::invalid_argument);
  s = LodSettings{};
  s.max_screen_error_px = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(select_tiles(camera, s), std::invalid_argument);
  s = LodSettings{};
  s.tile_samples = 0;
  EXPECT_THROW(select_tiles(camera, s), std::invalid_argument);
  LodCamera broken = camera;
  broken.forward = glm::dvec3{};
  try {
    select_tiles(broken, LodSettings{});
    ADD_FAILURE() << "a zero forward vector was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("forward"), std::string::npos) << e.what();
  }
  // Nonsense height ranges from the callback are ignored (the ancestor's range is used).
  auto bad = [](const TileId&) {
    return std::optional<std::pair<float, float>>({std::numeric_limits<float>::quiet_NaN(), 100.0f});
  };
  const LodSelection r = select_tiles(camera, LodSettings{}, bad);
  expect_sane(r, LodSettings{});
  expect_ground_covered_once(camera, r, 600.0);
}

// --- Geometric error and skirts ------------------------------------------------------------------

TEST(LodSelection, GeometricErrorIsTheSampleSpacing) {
  // Zoom 0: the equator's length over 256 samples.
  EXPECT_NEAR(geometric_error_m(TileId{0, 0, 0}), 2.0 * std::numbers::pi * 6378137.0 / 256.0, 1e-6);
  EXPECT_NEAR(geometric_error_m(TileId{0, 0, 0}, 65), 2.0 * std::numbers::pi * 6378137.0 / 65.0, 1e-6);
  // Zoom 14 at Interlaken: the parallel's circumference (N cos(lat)) at the tile's southern
  // edge over 2^14 tiles and 256 samples.
  const TileId t = *geo::tile_containing(46.68, 7.86, 14);
  const double south = geo::tile_bounds_latlon(t)->min_lat * kDeg;
  const double n = 6378137.0 / std::sqrt(1.0 - geo::wgs84::kE2 * std::sin(south) * std::sin(south));
  EXPECT_NEAR(geometric_error_m(t), 2.0 * std::numbers::pi * n * std::cos(south) / 16384.0 / 256.0, 1e-9);
  // In the southern hemisphere the northern edge is the wider one.
  const TileId s = *geo::tile_containing(-46.68, 7.86, 14);
  const double north = geo::tile_bounds_latlon(s)->max_lat * kDeg;
  EXPECT_NEAR(geometric_error_m(s), geometric_error_m(t) * std::cos(north) / std::cos(south), 1e-6);
  EXPECT_TRUE(std::isnan(geometric_error_m(TileId{3, 8, 0})));
  EXPECT_TRUE(std::isnan(geometric_error_m(TileId{3, 1, 0}, 0)));
}

TEST(LodSelection, SkirtsHangSeveralSampleSpacingsAndAtLeastAFewMetres) {
  for (int zoom = 0; zoom <= 20; ++zoom) {
    const TileId t = *geo::tile_containing(46.68, 7.86, zoom);
    EXPECT_GE(skirt_depth_m(t), 3.0 * geometric_error_m(t)) << zoom;
    EXPECT_GE(skirt_depth_m(t), kMinSkirtDepthM) << zoom;
    if (zoom > 0) {
      EXPECT_LE(skirt_depth_m(t), skirt_depth_m(*geo::parent(t))) << zoom;
    }
  }
  EXPECT_EQ(skirt_depth_m(*geo::tile_containing(46.68, 7.86, 20)), kMinSkirtDepthM);
  EXPECT_GT(skirt_depth_m(*geo::tile_containing(46.68, 7.86, 10)), 50.0);
  EXPECT_EQ(skirt_depth_m(TileId{2, 9, 9}), kMinSkirtDepthM);
}

// --- Drawing while tiles load -------------------------------------------------------------------

LodSelection wanting(const std::vector<TileId>& ids) {
  LodSelection s;
  for (const TileId& id : ids) s.tiles.push_back(SelectedTile{id, 1.0, 100.0, 1.0});
  return s;
}

std::function<bool(const TileId&)> loaded_set(const std::vector<TileId>& ids) {
  return [set = std::unordered_set<TileId>(ids.begin(), ids.end())](const TileId& id) { return set.contains(id); };
}

std::set<std::string> names(const std::vector<TileId>& ids) {
  std::set<std::string> out;
  for (const TileId& id : ids) out.insert(geo::to_string(id));
  return out;
}

TEST(LodTilesToDraw, ParentStandsInUntilAllFourChildrenAreLoaded) {
  const TileId parent_tile{10, 533, 362};
  const auto kids = *geo::children(parent_tile);
  const TileId neighbour{10, 534, 362};
  const LodSelection s = wanting({kids[0], kids[1], kids[2], kids[3], neighbour});

  EXPECT_TRUE(tiles_to_draw(s, loaded_set({})).empty());
  EXPECT_EQ(names(tiles_to_draw(s, loaded_set({parent_tile}))), names({parent_tile}));
  // Three of four children loaded: the parent still stands in for all four.
  EXPECT_EQ(names(tiles_to_draw(s, loaded_set({parent_tile, kids[0], kids[1], kids[3], neighbour}))),
            names({parent_tile, neighbour}));
  // All four: the children replace it.
  EXPECT_EQ(names(tiles_to_draw(s, loaded_set({parent_tile, kids[0], kids[1], kids[2], kids[3]}))),
            names({kids[0], kids[1], kids[2], kids[3]}));
  // Children loaded without the parent (evicted): the loaded ones are drawn, the other is a gap.
  EXPECT_EQ(names(tiles_to_draw(s, loaded_set({kids[0], kids[1]}))), names({kids[0], kids[1]}));
  // Only the grandparent loaded: it stands in for the children and the neighbour alike, once.
  const TileId grandparent = *geo::parent(parent_tile);
  const std::vector<TileId> drawn = tiles_to_draw(s, loaded_set({grandparent}));
  ASSERT_EQ(drawn.size(), 1u);
  EXPECT_EQ(drawn[0], grandparent);
  // Without a callback nothing is known to be loaded.
  EXPECT_TRUE(tiles_to_draw(s, {}).empty());
}

TEST(LodTilesToDraw, AnAncestorReplacesEveryWantedTileUnderIt) {
  // Wanted: the four grandchildren under child 0, and children 1..3 of P.
  const TileId p{9, 266, 181};
  const auto c = *geo::children(p);
  const auto g = *geo::children(c[0]);
  const LodSelection s = wanting({g[0], g[1], g[2], g[3], c[1], c[2], c[3]});
  // g[3] missing, c[0] not loaded: P stands in for g[3], and so for everything under it.
  EXPECT_EQ(names(tiles_to_draw(s, loaded_set({p, g[0], g[1], g[2], c[1], c[2], c[3]}))), names({p}));
  // c[0] loaded: it stands in for its grandchildren only; c[1..3] are drawn themselves.
  EXPECT_EQ(names(tiles_to_draw(s, loaded_set({p, c[0], g[0], g[1], g[2], c[1], c[2], c[3]}))),
            names({c[0], c[1], c[2], c[3]}));
  // Everything loaded: exactly the wanted tiles, in the selection's order.
  const std::vector<TileId> all = tiles_to_draw(s, loaded_set({p, c[0], g[0], g[1], g[2], g[3], c[1], c[2], c[3]}));
  ASSERT_EQ(all.size(), s.tiles.size());
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], s.tiles[i].id);
}

TEST(LodTilesToDraw, RandomLoadStatesNeverOverlapAndCoverWhatTheyCan) {
  const LodSelection s = select_tiles(interlaken_to_eiger(), LodSettings{}, constant_range(500.0f, 4200.0f));
  ASSERT_GT(s.tiles.size(), 50u);
  // Every wanted tile and its ancestors, the tiles a loader may hold.
  std::vector<TileId> candidates;
  {
    std::unordered_set<TileId> seen;
    for (const SelectedTile& t : s.tiles) {
      for (std::optional<TileId> up = t.id; up && seen.insert(*up).second; up = geo::parent(*up))
        candidates.push_back(*up);
    }
  }
  std::mt19937 rng(20240618);
  for (int round = 0; round < 40; ++round) {
    std::bernoulli_distribution coin(round / 40.0);
    std::vector<TileId> loaded;
    for (const TileId& t : candidates) {
      if (coin(rng)) loaded.push_back(t);
    }
    const auto is_loaded = loaded_set(loaded);
    const std::vector<TileId> drawn = tiles_to_draw(s, is_loaded);
    expect_disjoint(drawn);
    const std::unordered_set<TileId> drawn_set(drawn.begin(), drawn.end());
    for (const TileId& d : drawn) EXPECT_TRUE(is_loaded(d)) << geo::to_string(d);
    for (const SelectedTile& wanted : s.tiles) {
      // Drawn: the tile itself or one ancestor, exactly when it or an ancestor is loaded.
      int cover = 0;
      bool loadable = false;
      for (std::optional<TileId> up = wanted.id; up; up = geo::parent(*up)) {
        cover += drawn_set.contains(*up) ? 1 : 0;
        loadable = loadable || is_loaded(*up);
      }
      EXPECT_EQ(cover, loadable ? 1 : 0) << geo::to_string(wanted.id) << " round " << round;
    }
    // Nothing drawn that no wanted tile needs.
    for (const TileId& d : drawn) {
      const bool needed = std::any_of(s.tiles.begin(), s.tiles.end(), [&](const SelectedTile& w) {
        for (std::optional<TileId> up = w.id; up; up = geo::parent(*up)) {
          if (*up == d) return true;
        }
        return false;
      });
      EXPECT_TRUE(needed) << geo::to_string(d);
    }
  }
}

}  // namespace
}  // namespace trailray::terrain
