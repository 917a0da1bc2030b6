// The terrain tile mesh on the CPU: grid and skirt layout, bilinear heights, positions relative to
// the tile's origin, normals, holes.
#include "render/passes/terrain_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geo/tile_id.hpp"
#include "geo/wgs84.hpp"
#include "scene/camera/camera.hpp"
#include "terrain/lod/lod_selection.hpp"

namespace trailray::render {
namespace {

terrain::HeightTile tile_from(const terrain::TileId& id, std::uint32_t size, terrain::SampleLayout layout,
                              const std::function<float(std::uint32_t, std::uint32_t)>& height) {
  terrain::HeightTile tile;
  tile.id = id;
  tile.width = tile.height = size;
  tile.layout = layout;
  for (std::uint32_t r = 0; r < size; ++r)
    for (std::uint32_t c = 0; c < size; ++c) tile.heights.push_back(height(c, r));
  terrain::update_height_range(tile);
  return tile;
}

const terrain::TileId kAlpsTile{12, 2137, 1445};

TEST(TerrainMesh, GridPlusOneSkirtVertexPerEdgeVertexAndTwoTrianglesPerCell) {
  const auto tile = tile_from(kAlpsTile, 65, terrain::SampleLayout::pixel_is_point, [](auto, auto) { return 1000.0f; });
  const TerrainMesh mesh = build_terrain_mesh(tile, 17, 0.0f);
  EXPECT_EQ(mesh.vertices.size(), 17u * 17u + 4u * 16u);
  EXPECT_EQ(mesh.indices.size(), 16u * 16u * 6u + 4u * 16u * 6u);
  for (const auto i : mesh.indices) ASSERT_LT(i, mesh.vertices.size());
}

TEST(TerrainMesh, VerticesLieOnTheEllipsoidAtTheirHeightRelativeToTheOrigin) {
  // Heights rising 1 m per sample eastwards: vertex (i, j) of a 65-vertex grid over a
  // pixel-is-point 65-sample tile sits exactly on sample (i, j).
  const auto tile = tile_from(kAlpsTile, 65, terrain::SampleLayout::pixel_is_point,
                              [](std::uint32_t c, std::uint32_t) { return 500.0f + static_cast<float>(c); });
  const TerrainMesh mesh = build_terrain_mesh(tile, 65, 0.0f);
  for (const std::uint32_t k : {0u, 64u, 65u * 32u + 17u, 65u * 65u - 1u}) {
    const std::uint32_t i = k % 65, j = k / 65;
    const TerrainVertex& v = mesh.vertices[k];
    EXPECT_FLOAT_EQ(v.height_m, 500.0f + static_cast<float>(i));
    const auto ll = geo::latlon_from_tile_pixel(kAlpsTile, i, j, 64);
    const glm::dvec3 expected = scene::ecef_from({ll->lat, ll->lon, 500.0 + i});
    const glm::dvec3 actual = mesh.origin + glm::dvec3(v.x, v.y, v.z);
    EXPECT_LT(glm::length(actual - expected), 0.01) << "vertex " << i << "," << j;
  }
  // The origin is the tile's centre at its mean height.
  const geo::Geodetic origin = geo::geodetic_from_ecef(mesh.origin);
  const auto centre = geo::latlon_from_tile_pixel(kAlpsTile, 0.5, 0.5, 1);
  EXPECT_NEAR(origin.lat_deg, centre->lat, 1e-9);
  EXPECT_NEAR(origin.lon_deg, centre->lon, 1e-9);
}

TEST(TerrainMesh, NormalsPointUpOnFlatGroundAndTiltAwayFromTheRise) {
  const auto flat = tile_from(kAlpsTile, 65, terrain::SampleLayout::pixel_is_point, [](auto, auto) { return 800.0f; });
  const TerrainMesh flat_mesh = build_terrain_mesh(flat, 33, 0.0f);
  const TerrainVertex& centre = flat_mesh.vertices[33 * 16 + 16];
  const auto ll = geo::latlon_from_tile_pixel(kAlpsTile, 16, 16, 32);
  const scene::EnuAxes enu = scene::enu_axes_at(ll->lat, ll->lon);
  const glm::dvec3 n(centre.nx, centre.ny, centre.nz);
  EXPECT_GT(glm::dot(n, enu.up), 0.99999);

  // Rising eastwards: the normal leans west.
  const auto slope = tile_from(kAlpsTile, 65, terrain::SampleLayout::pixel_is_point,
                               [](std::uint32_t c, std::uint32_t) { return 800.0f + 10.0f * static_cast<float>(c); });
  const TerrainMesh slope_mesh = build_terrain_mesh(slope, 33, 0.0f);
  const TerrainVertex& s = slope_mesh.vertices[33 * 16 + 16];
  const TerrainVertex& next = slope_mesh.vertices[33 * 16 + 17];
  const glm::dvec3 ns(s.nx, s.ny, s.nz);
  // 20 m higher per vertex (two samples); the normal of that slope leans west by rise / hypotenuse.
  const double run = glm::dot(glm::dvec3(next.x - s.x, next.y - s.y, next.z - s.z), enu.east);
  EXPECT_NEAR(glm::dot(ns, enu.east), -20.0 / std::hypot(20.0, run), 0.002);
  EXPECT_NEAR(glm::dot(ns, enu.north), 0.0, 0.01);
  EXPECT_NEAR(glm::length(ns), 1.0, 1e-5);
}

TEST(TerrainMesh, SkirtsHangBelowTheEdgesBySkirtDepth) {
  const auto tile = tile_from(kAlpsTile, 65, terrain::SampleLayout::pixel_is_point, [](auto, auto) { return 1200.0f; });
  const TerrainMesh mesh = build_terrain_mesh(tile, 9, 0.0f);
  const double depth = terrain::skirt_depth_m(kAlpsTile, 8);
  ASSERT_GT(depth, 0.0);
  const glm::dvec3 origin = mesh.origin;
  for (std::size_t k = 81; k < mesh.vertices.size(); ++k) {
    const TerrainVertex& v = mesh.vertices[k];
    const glm::dvec3 p = origin + glm::dvec3(v.x, v.y, v.z);
    const geo::Geodetic g = geo::geodetic_from_ecef(p);
    const double lat = g.lat_deg, lon = g.lon_deg;
    const double height = glm::dot(p - scene::ecef_from({lat, lon, 0.0}), scene::enu_axes_at(lat, lon).up);
    EXPECT_NEAR(height, 1200.0 - depth, 0.05) << "skirt vertex " << k;
  }
}

TEST(TerrainMesh, BilinearBetweenAreaSamplesAndHolesFilledAsUncovered) {
  // Pixel-is-area, 4 samples: sample c's centre lies at (c + 0.5) / 4 of the tile.
  auto tile = tile_from(kAlpsTile, 4, terrain::SampleLayout::pixel_is_area,
                        [](std::uint32_t c, std::uint32_t) { return 100.0f * static_cast<float>(c); });
  EXPECT_FLOAT_EQ(sample_height_bilinear(tile, 0.5 / 4, 0.5), 0.0f);
  EXPECT_FLOAT_EQ(sample_height_bilinear(tile, 1.0 / 4, 0.5), 50.0f);
  // The last half cell: extrapolated from the two outermost samples, so the edge of a ramp lies on
  // the ramp (and meets the neighbouring tile's edge) instead of holding the last sample flat.
  EXPECT_FLOAT_EQ(sample_height_bilinear(tile, 1.0, 0.5), 350.0f);
  EXPECT_FLOAT_EQ(sample_height_bilinear(tile, 0.0, 0.5), -50.0f);
  tile.heights[1] = terrain::kNoHeight;                               // row 0, column 1
  EXPECT_FLOAT_EQ(sample_height_bilinear(tile, 1.0 / 4, 0.0), 0.0f);  // the hole's weight goes to its neighbour

  const auto holes =
      tile_from(kAlpsTile, 2, terrain::SampleLayout::pixel_is_point, [](auto, auto) { return terrain::kNoHeight; });
  const TerrainMesh mesh = build_terrain_mesh(holes, 3, 432.0f);
  for (const auto& v : mesh.vertices) {
    EXPECT_EQ(v.covered, 0.0f);
    EXPECT_EQ(v.height_m, 432.0f);
  }
}

TEST(TerrainMesh, NeighbouringAreaTilesMeetOnTheirSharedEdge) {
  // A smooth surface sampled by two side-by-side tiles: the east edge of the western tile and the
  // west edge of the eastern one must lie at the same height, or skirts show as seams.
  auto surface = [](double x, double y) { return 500.0 + 3.0 * x + 0.02 * x * x - 1.5 * y; };
  const terrain::TileId west{12, 2137, 1445}, east{12, 2138, 1445};
  auto tile = [&](const terrain::TileId& id, double x0) {
    return tile_from(id, 8, terrain::SampleLayout::pixel_is_area, [&](std::uint32_t c, std::uint32_t r) {
      return static_cast<float>(surface(x0 + c + 0.5, r + 0.5));
    });
  };
  const auto a = tile(west, 0.0), b = tile(east, 8.0);
  for (double v : {0.1, 0.5, 0.9}) {
    const float from_west = sample_height_bilinear(a, 1.0, v), from_east = sample_height_bilinear(b, 0.0, v);
    EXPECT_NEAR(from_west, from_east, 0.05) << v;
    EXPECT_NEAR(from_west, surface(8.0, v * 8.0), 0.05) << v;
  }
}

TEST(TerrainMesh, BadTilesAreErrorsNamingTheTile) {
  terrain::HeightTile broken;
  broken.id = kAlpsTile;
  broken.width = broken.height = 4;
  broken.heights.resize(3);
  try {
    build_terrain_mesh(broken, 5, 0.0f);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("12/2137/1445"), std::string::npos) << e.what();
  }
  const auto tile = tile_from(kAlpsTile, 2, terrain::SampleLayout::pixel_is_point, [](auto, auto) { return 0.0f; });
  EXPECT_THROW(build_terrain_mesh(tile, 1, 0.0f), std::invalid_argument);
}

}  // namespace
}  // namespace trailray::render

namespace trailray::render {
namespace {

// A tile with its source's own triangles (a quantized-mesh layer's): drawn as they are, each
// vertex at its place and height, wound as the grid's, skirts under the border edges only.
TEST(TerrainMesh, TheSourcesOwnTrianglesAreDrawnAsTheyAre) {
  auto tile = tile_from(kAlpsTile, 2, terrain::SampleLayout::pixel_is_point, [](auto, auto) { return 1000.0f; });
  auto t = std::make_shared<terrain::TileTriangles>();
  // The tile's four corners and a peak inside, four triangles around the peak, one wound the other way.
  t->u = {0.0f, 1.0f, 1.0f, 0.0f, 0.3f};
  t->v = {0.0f, 0.0f, 1.0f, 1.0f, 0.6f};
  t->height_m = {1000.0f, 1010.0f, 1020.0f, 1030.0f, 1500.0f};
  t->indices = {0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 0, 4};
  tile.triangles = t;
  const TerrainMesh mesh = build_terrain_mesh(tile, 65, 0.0f);
  EXPECT_EQ(mesh.grid_vertices, 0u);
  // Five vertices, then two skirt vertices for each of the four border edges.
  ASSERT_EQ(mesh.vertices.size(), 5u + 4u * 2u);
  EXPECT_EQ(mesh.indices.size(), 4u * 3u + 4u * 6u);
  for (std::size_t k = 0; k < 5; ++k) {
    const auto ll = geo::latlon_from_tile_pixel(kAlpsTile, t->u[k], t->v[k], 1);
    const glm::dvec3 at = scene::ecef_from({ll->lat, ll->lon, double{t->height_m[k]}}) - mesh.origin;
    EXPECT_NEAR(mesh.vertices[k].x, at.x, 0.01) << k;
    EXPECT_NEAR(mesh.vertices[k].y, at.y, 0.01) << k;
    EXPECT_NEAR(mesh.vertices[k].z, at.z, 0.01) << k;
    EXPECT_EQ(mesh.vertices[k].height_m, t->height_m[k]);
  }
  // Every triangle faces up (the same winding), whatever order the source gave.
  for (std::size_t f = 0; f < 12; f += 3) {
    const auto p = [&](std::uint32_t i) {
      return glm::dvec3(mesh.vertices[i].x, mesh.vertices[i].y, mesh.vertices[i].z) + mesh.origin;
    };
    const glm::dvec3 n = glm::cross(p(mesh.indices[f + 1]) - p(mesh.indices[f]), p(mesh.indices[f + 2]) - p(mesh.indices[f]));
    EXPECT_GT(glm::dot(n, glm::normalize(p(4))), 0.0) << f;
  }
  // The peak's normal leans no way in particular: it points up within the slopes around it.
  EXPECT_GT(glm::dot(glm::dvec3(mesh.vertices[4].nx, mesh.vertices[4].ny, mesh.vertices[4].nz),
                     scene::enu_axes_at(geo::latlon_from_tile_pixel(kAlpsTile, 0.3, 0.6, 1)->lat,
                                        geo::latlon_from_tile_pixel(kAlpsTile, 0.3, 0.6, 1)->lon)
                         .up),
            0.5);
}

}  // namespace
}  // namespace trailray::render
