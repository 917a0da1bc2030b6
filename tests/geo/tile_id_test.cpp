#include "geo/tile_id.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <unordered_map>
#include <unordered_set>

namespace trailray::geo {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kZooms[] = {0, 1, 10, 20, 30};

// The OpenStreetMap wiki's slippy-map formula, written out independently of the implementation:
//   x = (lon + 180) / 360 * 2^z,  y = (1 - ln(tan(lat) + sec(lat)) / pi) / 2 * 2^z.
double osm_fx(double lon_deg, int z) { return (lon_deg + 180.0) / 360.0 * std::pow(2.0, z); }
double osm_fy(double lat_deg, int z) {
  const double lat = lat_deg * kPi / 180.0;
  return (1.0 - std::log(std::tan(lat) + 1.0 / std::cos(lat)) / kPi) / 2.0 * std::pow(2.0, z);
}
// Its inverse for a row edge: lat = atan(sinh(pi (1 - 2 y / 2^z))).
double osm_row_lat(double y, int z) {
  return std::atan(std::sinh(kPi * (1.0 - 2.0 * y / std::pow(2.0, z)))) * 180.0 / kPi;
}

double lon_distance(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

TEST(TileId, Validation) {
  EXPECT_TRUE(is_valid(TileId{0, 0, 0}));
  EXPECT_FALSE(is_valid(TileId{0, 1, 0}));
  EXPECT_FALSE(is_valid(TileId{0, 0, 1}));
  EXPECT_FALSE(is_valid(TileId{-1, 0, 0}));
  EXPECT_FALSE(is_valid(TileId{31, 0, 0}));
  EXPECT_FALSE(is_valid(TileId{std::numeric_limits<int>::max(), 0, 0}));
  EXPECT_FALSE(is_valid(TileId{std::numeric_limits<int>::min(), 0, 0}));
  EXPECT_TRUE(is_valid(TileId{12, 4095, 4095}));
  EXPECT_FALSE(is_valid(TileId{12, 4096, 0}));
  EXPECT_FALSE(is_valid(TileId{12, 0, 4096}));
  EXPECT_TRUE(is_valid(TileId{30, (1u << 30) - 1, (1u << 30) - 1}));
  EXPECT_FALSE(is_valid(TileId{30, 1u << 30, 0}));
  EXPECT_FALSE(is_valid(TileId{30, 0xFFFFFFFFu, 0xFFFFFFFFu}));
  EXPECT_EQ(make_tile_id(3, 7, 0), (TileId{3, 7, 0}));
  EXPECT_FALSE(make_tile_id(3, 8, 0));
  EXPECT_FALSE(make_tile_id(-3, 0, 0));
}

TEST(TileId, InvalidIdsAreRejectedEverywhere) {
  for (const TileId bad : {TileId{-1, 0, 0}, TileId{31, 0, 0}, TileId{2, 4, 0}, TileId{2, 0, 4},
                           TileId{30, 0xFFFFFFFFu, 0}, TileId{64, 1, 1}}) {
    EXPECT_FALSE(tms_y(bad)) << to_string(bad);
    EXPECT_FALSE(parent(bad)) << to_string(bad);
    EXPECT_FALSE(children(bad)) << to_string(bad);
    EXPECT_FALSE(tile_bounds_latlon(bad)) << to_string(bad);
    EXPECT_FALSE(tile_bounds_mercator(bad)) << to_string(bad);
    EXPECT_FALSE(latlon_from_tile_pixel(bad, 0.0, 0.0, 256)) << to_string(bad);
  }
  EXPECT_FALSE(tile_from_tms(2, 0, 4));
  EXPECT_FALSE(tile_from_tms(31, 0, 0));
  EXPECT_FALSE(tile_containing(0.0, 0.0, -1));
  EXPECT_FALSE(tile_containing(0.0, 0.0, 31));
  EXPECT_FALSE(fractional_tile_coord(0.0, 0.0, 31));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(tile_containing(nan, 0.0, 5));
  EXPECT_FALSE(tile_containing(0.0, nan, 5));
  EXPECT_FALSE(tile_containing(inf, 0.0, 5));
  EXPECT_FALSE(tile_containing(0.0, -inf, 5));
  EXPECT_FALSE(tile_pixel(0.0, 0.0, 5, 0));
  EXPECT_FALSE(tile_pixel(nan, 0.0, 5, 256));
  EXPECT_FALSE(latlon_from_tile_pixel(TileId{5, 0, 0}, 0.0, 0.0, 0));
  EXPECT_FALSE(latlon_from_tile_pixel(TileId{5, 0, 0}, nan, 0.0, 256));
  EXPECT_FALSE(latlon_from_tile_pixel(TileId{5, 0, 0}, 0.0, inf, 256));
}

TEST(TileId, ZoomOneQuadrants) {
  EXPECT_EQ(tile_containing(45.0, -90.0, 1), (TileId{1, 0, 0}));
  EXPECT_EQ(tile_containing(45.0, 90.0, 1), (TileId{1, 1, 0}));
  EXPECT_EQ(tile_containing(-45.0, -90.0, 1), (TileId{1, 0, 1}));
  EXPECT_EQ(tile_containing(-45.0, 90.0, 1), (TileId{1, 1, 1}));
  EXPECT_EQ(tile_containing(10.0, 10.0, 0), (TileId{0, 0, 0}));

  const LatLonBounds nw = *tile_bounds_latlon(TileId{1, 0, 0});
  EXPECT_DOUBLE_EQ(nw.min_lon, -180.0);
  EXPECT_DOUBLE_EQ(nw.max_lon, 0.0);
  EXPECT_NEAR(nw.min_lat, 0.0, 1e-12);
  EXPECT_NEAR(nw.max_lat, 85.0511287798066, 1e-12);
  const LatLonBounds se = *tile_bounds_latlon(TileId{1, 1, 1});
  EXPECT_DOUBLE_EQ(se.min_lon, 0.0);
  EXPECT_DOUBLE_EQ(se.max_lon, 180.0);
  EXPECT_NEAR(se.min_lat, -85.0511287798066, 1e-12);
  EXPECT_NEAR(se.max_lat, 0.0, 1e-12);

  const MercatorBounds world = *tile_bounds_mercator(TileId{0, 0, 0});
  EXPECT_NEAR(world.min_x, -20037508.342789244, 1e-7);
  EXPECT_NEAR(world.max_x, 20037508.342789244, 1e-7);
  EXPECT_NEAR(world.min_y, -20037508.342789244, 1e-7);
  EXPECT_NEAR(world.max_y, 20037508.342789244, 1e-7);
  const MercatorBounds ne = *tile_bounds_mercator(TileId{1, 1, 0});
  EXPECT_NEAR(ne.min_x, 0.0, 1e-7);
  EXPECT_NEAR(ne.min_y, 0.0, 1e-7);
  EXPECT_NEAR(ne.max_x, 20037508.342789244, 1e-7);
  EXPECT_NEAR(ne.max_y, 20037508.342789244, 1e-7);
}

TEST(TileId, InterlakenAtZoom12) {
  const double lat = 46.686, lon = 7.863;
  const TileId t = *tile_containing(lat, lon, 12);
  EXPECT_EQ(t.zoom, 12);
  EXPECT_EQ(t.x, static_cast<std::uint32_t>(std::floor(osm_fx(lon, 12))));
  EXPECT_EQ(t.y, static_cast<std::uint32_t>(std::floor(osm_fy(lat, 12))));
  // The numbers themselves, so that a wrong test formula cannot agree with a wrong implementation.
  EXPECT_EQ(t, (TileId{12, 2137, 1445}));
  EXPECT_EQ(to_string(t), "12/2137/1445");
  const LatLonBounds b = *tile_bounds_latlon(t);
  EXPECT_LE(b.min_lat, lat);
  EXPECT_GT(b.max_lat, lat);
  EXPECT_LE(b.min_lon, lon);
  EXPECT_GT(b.max_lon, lon);
}

// tiles/alpinemaps_ortho/7/{68,69}/{82,83}.jpg (shared/data/MANIFEST.md): TMS rows, together
// covering lon 11.25..16.875, lat 45.0890..48.9225, split at 14.0625 E and 47.0402 N.
TEST(TileId, AlpineMapsOrthoTilesInTms) {
  struct Expected {
    std::uint32_t x, y_tms;
    double min_lon, max_lon, min_lat, max_lat;
  };
  const Expected tiles[] = {{68, 82, 11.25, 14.0625, 45.0890, 47.0402},
                            {68, 83, 11.25, 14.0625, 47.0402, 48.9225},
                            {69, 82, 14.0625, 16.875, 45.0890, 47.0402},
                            {69, 83, 14.0625, 16.875, 47.0402, 48.9225}};
  for (const Expected& e : tiles) {
    const std::optional<TileId> t = tile_from_tms(7, e.x, e.y_tms);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->x, e.x);
    EXPECT_EQ(t->y, 127u - e.y_tms);
    EXPECT_EQ(tms_y(*t), e.y_tms);
    const LatLonBounds b = *tile_bounds_latlon(*t);
    EXPECT_NEAR(b.min_lon, e.min_lon, 1e-4) << to_string(*t);
    EXPECT_NEAR(b.max_lon, e.max_lon, 1e-4) << to_string(*t);
    EXPECT_NEAR(b.min_lat, e.min_lat, 1e-4) << to_string(*t);
    EXPECT_NEAR(b.max_lat, e.max_lat, 1e-4) << to_string(*t);
    // The tile containing its own centre is itself.
    EXPECT_EQ(tile_containing(0.5 * (b.min_lat + b.max_lat), 0.5 * (b.min_lon + b.max_lon), 7), *t);
  }
  // The quad shares one parent: z6 x34, XYZ row 22 (TMS row 41).
  const TileId p = *parent(*tile_from_tms(7, 68, 82));
  EXPECT_EQ(p, (TileId{6, 34, 22}));
  EXPECT_EQ(tms_y(p), 41u);
  for (const Expected& e : tiles) EXPECT_EQ(*parent(*tile_from_tms(7, e.x, e.y_tms)), p);
}

TEST(TileId, TmsFlipIsAnInvolution) {
  EXPECT_EQ(tile_from_tms(0, 0, 0), (TileId{0, 0, 0}));
  EXPECT_EQ(tile_from_tms(1, 0, 0), (TileId{1, 0, 1}));
  EXPECT_EQ(tms_y(TileId{1, 0, 0}), 1u);
  EXPECT_EQ(tms_y(TileId{30, 5, 0}), (1u << 30) - 1);
  EXPECT_EQ(tms_y(TileId{30, 5, (1u << 30) - 1}), 0u);
  std::mt19937_64 rng(99);
  for (int z = 0; z <= kMaxTileZoom; ++z) {
    std::uniform_int_distribution<std::uint32_t> coord(0, static_cast<std::uint32_t>((std::uint64_t{1} << z) - 1));
    for (int i = 0; i < 50; ++i) {
      const TileId t{z, coord(rng), coord(rng)};
      const std::uint32_t yt = *tms_y(t);
      EXPECT_EQ(static_cast<std::uint64_t>(yt) + t.y, (std::uint64_t{1} << z) - 1);
      EXPECT_EQ(tile_from_tms(z, t.x, yt), t);
    }
  }
}

TEST(TileId, ParentAndChildren) {
  EXPECT_FALSE(parent(TileId{0, 0, 0}));
  EXPECT_FALSE(children(TileId{30, 0, 0}));
  EXPECT_TRUE(children(TileId{29, (1u << 29) - 1, (1u << 29) - 1}));
  const std::array<TileId, 4> c = *children(TileId{0, 0, 0});
  EXPECT_EQ(c[0], (TileId{1, 0, 0}));
  EXPECT_EQ(c[1], (TileId{1, 1, 0}));
  EXPECT_EQ(c[2], (TileId{1, 0, 1}));
  EXPECT_EQ(c[3], (TileId{1, 1, 1}));

  std::mt19937_64 rng(1234);
  for (int z = 0; z < kMaxTileZoom; ++z) {
    std::uniform_int_distribution<std::uint32_t> coord(0, static_cast<std::uint32_t>((std::uint64_t{1} << z) - 1));
    for (int i = 0; i < 20; ++i) {
      const TileId t{z, coord(rng), coord(rng)};
      const LatLonBounds pb = *tile_bounds_latlon(t);
      const MercatorBounds pm = *tile_bounds_mercator(t);
      const std::array<TileId, 4> kids = *children(t);
      for (const TileId& k : kids) {
        ASSERT_TRUE(is_valid(k));
        EXPECT_EQ(parent(k), t);
        // Children lie inside the parent, and the four share its corners.
        const LatLonBounds kb = *tile_bounds_latlon(k);
        EXPECT_GE(kb.min_lon, pb.min_lon);
        EXPECT_LE(kb.max_lon, pb.max_lon);
        EXPECT_GE(kb.min_lat, pb.min_lat - 1e-12);
        EXPECT_LE(kb.max_lat, pb.max_lat + 1e-12);
      }
      EXPECT_EQ(tile_bounds_latlon(kids[0])->max_lat, pb.max_lat);
      EXPECT_EQ(tile_bounds_latlon(kids[0])->min_lon, pb.min_lon);
      EXPECT_EQ(tile_bounds_latlon(kids[3])->min_lat, pb.min_lat);
      EXPECT_EQ(tile_bounds_latlon(kids[3])->max_lon, pb.max_lon);
      const MercatorBounds nw = *tile_bounds_mercator(kids[0]);
      const MercatorBounds se = *tile_bounds_mercator(kids[3]);
      const double tol = 1e-9 * 20037508.342789244;
      EXPECT_NEAR(nw.min_x, pm.min_x, tol);
      EXPECT_NEAR(nw.max_y, pm.max_y, tol);
      EXPECT_NEAR(se.max_x, pm.max_x, tol);
      EXPECT_NEAR(se.min_y, pm.min_y, tol);
      EXPECT_NEAR(nw.max_x, se.min_x, tol);  // they meet in the middle
      EXPECT_NEAR(nw.min_y, se.max_y, tol);
    }
  }
}

TEST(TileId, BoundsAgreeWithTheOsmFormulaAndTheProjection) {
  std::mt19937_64 rng(42);
  for (const int z : kZooms) {
    std::uniform_int_distribution<std::uint32_t> coord(0, static_cast<std::uint32_t>((std::uint64_t{1} << z) - 1));
    for (int i = 0; i < 100; ++i) {
      const TileId t{z, coord(rng), coord(rng)};
      const LatLonBounds b = *tile_bounds_latlon(t);
      EXPECT_NEAR(b.max_lat, osm_row_lat(t.y, z), 1e-12);
      EXPECT_NEAR(b.min_lat, osm_row_lat(t.y + 1.0, z), 1e-12);
      EXPECT_NEAR(b.min_lon, t.x / std::pow(2.0, z) * 360.0 - 180.0, 1e-12);
      const MercatorBounds m = *tile_bounds_mercator(t);
      const MercatorPoint sw = mercator_from_latlon(b.min_lat, b.min_lon);
      const MercatorPoint ne = mercator_from_latlon(b.max_lat, b.max_lon);
      EXPECT_NEAR(m.min_x, sw.x, 1e-6);
      EXPECT_NEAR(m.min_y, sw.y, 1e-6);
      EXPECT_NEAR(m.max_x, ne.x, 1e-6);
      EXPECT_NEAR(m.max_y, ne.y, 1e-6);
      // Square in Mercator metres: 2 pi R / 2^z on a side.
      EXPECT_NEAR(m.max_x - m.min_x, 2.0 * 20037508.342789244 / std::pow(2.0, z), 1e-6);
      EXPECT_NEAR(m.max_y - m.min_y, 2.0 * 20037508.342789244 / std::pow(2.0, z), 1e-6);
    }
  }
}

// lat/lon -> tile + pixel -> lat/lon, and the tile against the OSM formula.
void check_round_trip(double lat, double lon, int z, std::uint32_t size) {
  SCOPED_TRACE(testing::Message() << "lat " << lat << " lon " << lon << " z " << z << " size " << size);
  const std::optional<TilePixel> tp = tile_pixel(lat, lon, z, size);
  ASSERT_TRUE(tp);
  ASSERT_TRUE(is_valid(tp->tile));
  EXPECT_EQ(tp->tile, tile_containing(lat, lon, z));
  EXPECT_GE(tp->px, 0.0);
  EXPECT_GE(tp->py, 0.0);
  EXPECT_LE(tp->px, size);
  EXPECT_LE(tp->py, size);
  const std::optional<LatLon> back = latlon_from_tile_pixel(tp->tile, tp->px, tp->py, size);
  ASSERT_TRUE(back);
  const double clamped_lat = std::clamp(lat, -kMercatorMaxLatDeg, kMercatorMaxLatDeg);
  EXPECT_NEAR(back->lat, clamped_lat, 1e-9);
  EXPECT_LE(lon_distance(back->lon, lon), 1e-9) << back->lon;
  // Independent tile index, except within rounding of a tile edge (or of the world's edges, where
  // the implementation clamps and wraps on purpose).
  const double n = std::pow(2.0, z);
  // The formula wants a longitude in [-180, 180): bring it there (180 wraps to -180).
  const double lon_w = lon - 360.0 * std::floor((lon + 180.0) / 360.0);
  const double fx = osm_fx(lon_w, z), fy = osm_fy(clamped_lat, z);
  const auto near_edge = [](double f) { return std::abs(f - std::round(f)) < 1e-6; };
  const bool x_inside = fx > 0.0 && fx<n, y_inside = fy> 0.0 && fy < n;
  if (!near_edge(fx) && x_inside) {
    EXPECT_EQ(tp->tile.x, static_cast<std::uint32_t>(std::floor(fx)));
  }
  if (!near_edge(fy) && y_inside) {
    EXPECT_EQ(tp->tile.y, static_cast<std::uint32_t>(std::floor(fy)));
  }
  // The pixel is where the fractional coordinate says, in the tile's pixel scale (at zoom 30 the
  // fraction of a coordinate near 2^30 holds only about 1e-7 of a tile).
  const double tol = (z == 30 ? 1e-4 : 1e-6) * size;
  if (x_inside) {
    EXPECT_NEAR(tp->px, (fx - tp->tile.x) * size, tol);
  }
  if (y_inside) {
    EXPECT_NEAR(tp->py, (fy - tp->tile.y) * size, tol);
  }
}

TEST(TileId, RoundTripRandomPositions) {
  std::mt19937_64 rng(20250101);
  std::uniform_real_distribution<double> lat(-kMercatorMaxLatDeg, kMercatorMaxLatDeg), lon(-180.0, 180.0);
  for (const int z : kZooms) {
    for (int i = 0; i < 2000; ++i) check_round_trip(lat(rng), lon(rng), z, i % 2 == 0 ? 256u : 512u);
  }
}

TEST(TileId, RoundTripNearTheAntimeridianAndTheLatitudeLimit) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> eps(0.0, 1e-6);
  for (const int z : kZooms) {
    for (const std::uint32_t size : {256u, 512u, 65u}) {
      for (int i = 0; i < 50; ++i) {
        const double e = eps(rng);
        check_round_trip(10.0, 180.0 - e, z, size);
        check_round_trip(-10.0, -180.0 + e, z, size);
        check_round_trip(kMercatorMaxLatDeg - e, 179.9999999, z, size);
        check_round_trip(-kMercatorMaxLatDeg + e, -179.9999999, z, size);
      }
      for (const double la : {kMercatorMaxLatDeg, -kMercatorMaxLatDeg, 85.06, -85.06, 90.0, -90.0, 0.0}) {
        for (const double lo : {-180.0, 180.0, 0.0, -1e-300, 540.0, -540.0, 1e6 + 0.5})
          check_round_trip(la, lo, z, size);
      }
    }
  }
}

TEST(TileId, WorldEdges) {
  // 180 and -180 are the same meridian: the western edge of column 0.
  EXPECT_EQ(tile_containing(0.0, 180.0, 4)->x, 0u);
  EXPECT_EQ(tile_containing(0.0, -180.0, 4)->x, 0u);
  EXPECT_EQ(tile_containing(0.0, 179.999, 4)->x, 15u);
  EXPECT_EQ(tile_containing(0.0, -180.001, 4)->x, 15u);
  EXPECT_EQ(tile_containing(0.0, 190.0, 4), tile_containing(0.0, -170.0, 4));
  EXPECT_EQ(tile_containing(0.0, 900.0, 4)->x, 0u);  // 900 = 180 + 2 turns
  EXPECT_EQ(tile_containing(0.0, -900.0, 4)->x, 0u);
  // Far outside [-180, 180] the wrap must still land exactly: one turn west of (k * 360 + 180)
  // is the western edge of column 0 (x 0, px 0), a hair before it the last column.
  for (const double k : {1.0, 1e3, 1e6, 1e9}) {
    const double edge = k * 360.0 + 180.0;
    const TilePixel p = *tile_pixel(0.0, edge, 20, 256);
    EXPECT_EQ(p.tile.x, 0u) << k;
    EXPECT_EQ(p.px, 0.0) << k;
    const TilePixel q = *tile_pixel(0.0, std::nextafter(edge, 0.0), 20, 256);
    EXPECT_EQ(q.tile.x, (1u << 20) - 1) << k;
    const double step_px = (edge - std::nextafter(edge, 0.0)) / 360.0 * std::pow(2.0, 20) * 256.0;
    EXPECT_NEAR(q.px, 256.0 - step_px, 1e-6) << k;
    const TilePixel r = *tile_pixel(0.0, -edge, 20, 256);
    EXPECT_EQ(r.tile.x, 0u) << k;
    EXPECT_EQ(r.px, 0.0) << k;
  }
  // Beyond the latitude limit: the first and last rows.
  EXPECT_EQ(tile_containing(90.0, 0.0, 30)->y, 0u);
  EXPECT_EQ(tile_containing(-90.0, 0.0, 30)->y, (1u << 30) - 1);
  EXPECT_EQ(tile_containing(-kMercatorMaxLatDeg, 0.0, 30)->y, (1u << 30) - 1);
  const TilePixel south = *tile_pixel(-90.0, 0.0, 3, 256);
  EXPECT_EQ(south.tile, (TileId{3, 4, 7}));
  EXPECT_NEAR(south.py, 256.0, 1e-9);
  const TilePixel north = *tile_pixel(90.0, 0.0, 3, 256);
  EXPECT_EQ(north.tile, (TileId{3, 4, 0}));
  EXPECT_NEAR(north.py, 0.0, 1e-9);
}

TEST(TileId, PixelCornersAndCentre) {
  for (const int z : kZooms) {
    const std::uint32_t n1 = static_cast<std::uint32_t>((std::uint64_t{1} << z) - 1);
    for (const TileId t : {TileId{z, 0, 0}, TileId{z, n1, n1}, TileId{z, n1 / 2, n1 / 3}}) {
      for (const std::uint32_t size : {256u, 512u}) {
        const LatLonBounds b = *tile_bounds_latlon(t);
        const LatLon nw = *latlon_from_tile_pixel(t, 0.0, 0.0, size);
        const LatLon se = *latlon_from_tile_pixel(t, size, size, size);
        EXPECT_NEAR(nw.lat, b.max_lat, 1e-12);
        EXPECT_NEAR(nw.lon, b.min_lon, 1e-12);
        EXPECT_NEAR(se.lat, b.min_lat, 1e-12);
        EXPECT_NEAR(se.lon, b.max_lon, 1e-12);
        // The centre pixel maps back to the middle of the tile.
        const LatLon c = *latlon_from_tile_pixel(t, 0.5 * size, 0.5 * size, size);
        const TilePixel p = *tile_pixel(c.lat, c.lon, z, size);
        EXPECT_EQ(p.tile, t);
        EXPECT_NEAR(p.px, 0.5 * size, z == 30 ? 1e-3 : 1e-6);
        EXPECT_NEAR(p.py, 0.5 * size, z == 30 ? 1e-3 : 1e-6);
      }
    }
  }
  // A 512 px tile's pixel is half a 256 px tile's pixel.
  const TilePixel a = *tile_pixel(46.686, 7.863, 12, 256);
  const TilePixel b = *tile_pixel(46.686, 7.863, 12, 512);
  EXPECT_EQ(a.tile, b.tile);
  EXPECT_NEAR(2.0 * a.px, b.px, 1e-9);
  EXPECT_NEAR(2.0 * a.py, b.py, 1e-9);
  // Pixel 1000 at zoom 12 with 256 px tiles is pixel 1000 - 3 * 256 of the tile three columns on:
  // the arithmetic through the pixel of another tile stays consistent.
  const LatLon far = *latlon_from_tile_pixel(TileId{12, 2137, 1445}, 1000.0, 10.0, 256);
  const LatLon near = *latlon_from_tile_pixel(TileId{12, 2140, 1445}, 1000.0 - 768.0, 10.0, 256);
  EXPECT_NEAR(far.lat, near.lat, 1e-12);
  EXPECT_NEAR(far.lon, near.lon, 1e-12);
}

TEST(TileId, EqualityHashAndToString) {
  EXPECT_EQ((TileId{3, 1, 2}), (TileId{3, 1, 2}));
  EXPECT_NE((TileId{3, 1, 2}), (TileId{3, 2, 1}));
  EXPECT_NE((TileId{3, 1, 2}), (TileId{4, 1, 2}));
  EXPECT_EQ(std::hash<TileId>{}(TileId{7, 68, 45}), TileIdHash{}(TileId{7, 68, 45}));
  EXPECT_EQ(to_string(TileId{0, 0, 0}), "0/0/0");
  EXPECT_EQ(to_string(TileId{30, (1u << 30) - 1, 5}), "30/1073741823/5");
  EXPECT_EQ(to_string(TileId{-1, 4294967295u, 0}), "-1/4294967295/0");

  // Every tile of zooms 0..6 (5461 ids): distinct hashes, and usable as keys.
  std::unordered_set<TileId> set;
  std::unordered_set<std::size_t> hashes;
  for (int z = 0; z <= 6; ++z) {
    for (std::uint32_t x = 0; x < (1u << z); ++x) {
      for (std::uint32_t y = 0; y < (1u << z); ++y) {
        EXPECT_TRUE(set.insert(TileId{z, x, y}).second);
        hashes.insert(std::hash<TileId>{}(TileId{z, x, y}));
      }
    }
  }
  EXPECT_EQ(set.size(), 5461u);
  EXPECT_EQ(hashes.size(), 5461u);
  EXPECT_FALSE(set.insert(TileId{4, 3, 9}).second);
  EXPECT_EQ(set.count(TileId{7, 0, 0}), 0u);
  std::unordered_map<TileId, int, TileIdHash> map;
  map[TileId{7, 68, 45}] = 1;
  map[TileId{7, 68, 45}] += 1;
  map[TileId{7, 45, 68}] = 5;
  EXPECT_EQ(map.size(), 2u);
  EXPECT_EQ(map.at(TileId{7, 68, 45}), 2);
  // Invalid ids hash too (no UB from the zoom).
  EXPECT_EQ(TileIdHash{}(TileId{-5, 1, 1}), TileIdHash{}(TileId{-5, 1, 1}));
  EXPECT_EQ(TileIdHash{}(TileId{1000, 1, 1}), TileIdHash{}(TileId{1000, 1, 1}));
}

}  // namespace
}  // namespace trailray::geo
