// Quantized-mesh terrain as a source: a layer (layer.json and .terrain tiles, EPSG:4326, TMS rows)
// written by a small generator around Interlaken, read from a folder and from a local server.
// Heights come off the triangles exactly: a plane is reproduced to the quantization, and inside a
// triangle the height is its vertices' barycentric mean, not a grid's bilinear one.
#include "terrain/sources/quantized_mesh_source.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "terrain/local_tile_server.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/sources/source_factory.hpp"

namespace trailray::terrain {
namespace {

namespace fs = std::filesystem;
constexpr int kZoom = 12;
constexpr double kSize = 180.0 / (1 << kZoom);  // degrees a tile side at zoom 12 (EPSG:4326)

double plane(double lat, double lon) { return 1000.0 + 2000.0 * (lat - 46.6) + 1000.0 * (lon - 7.8); }

// A tile of the layer: a 9 x 9 grid of vertices on the plane, two triangles a cell, except that
// the vertex at (4, 4) of the tile holding the bump is raised by 80 m.
QuantizedMesh tile_mesh(std::uint32_t x, std::uint32_t y_xyz, bool bump) {
  const double west = -180.0 + x * kSize, north = 90.0 - y_xyz * kSize;
  QuantizedMesh m;
  m.min_height_m = 0.0f;
  m.max_height_m = 4000.0f;
  const int n = 9;
  std::vector<std::int64_t> number(n * n, -1);
  const auto vertex = [&](int i, int j) {
    std::int64_t& k = number[j * n + i];
    if (k < 0) {
      k = static_cast<std::int64_t>(m.u.size());
      const auto u = static_cast<std::uint16_t>(i * 4096), v = static_cast<std::uint16_t>(j * 4096 - (j == 8 ? 1 : 0));
      const double lon = west + kSize * u / kQuantizedMax, lat = north - kSize + kSize * v / kQuantizedMax;
      const double h = plane(lat, lon) + (bump && i == 4 && j == 4 ? 80.0 : 0.0);
      m.u.push_back(i == 8 ? kQuantizedMax : u);
      m.v.push_back(v);
      m.h.push_back(static_cast<std::uint16_t>(std::lround(h / 4000.0 * kQuantizedMax)));
    }
    return static_cast<std::uint32_t>(k);
  };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const std::uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
    }
  for (int k = 0; k < n; ++k) m.west.push_back(vertex(0, k));
  return m;
}

struct Layer {
  test::http::TempFolder folder;
  std::vector<std::pair<std::string, fs::path>> files;  // name under the layer, path
  std::uint32_t x0 = 0, y0 = 0;                         // the north-west tile (XYZ)
  Layer() {
    x0 = static_cast<std::uint32_t>(std::floor((7.85 + 180.0) / kSize));
    y0 = static_cast<std::uint32_t>(std::floor((90.0 - 46.72) / kSize));
    const std::string layer = R"({"tilejson":"2.1.0","format":"quantized-mesh-1.0","version":"1.2.0","scheme":"tms",)"
                              R"("tiles":["{z}/{x}/{y}.terrain?v={version}"],"projection":"EPSG:4326",)"
                              R"("minzoom":12,"maxzoom":12,"bounds":[7.7,46.6,8.0,46.8]})";
    write("layer.json", std::vector<unsigned char>(layer.begin(), layer.end()));
    for (std::uint32_t dx = 0; dx < 2; ++dx)
      for (std::uint32_t dy = 0; dy < 2; ++dy) {
        const std::uint32_t x = x0 + dx, y = y0 + dy, tms = (1u << kZoom) - 1 - y;
        write(std::to_string(kZoom) + "/" + std::to_string(x) + "/" + std::to_string(tms) + ".terrain",
              encode_quantized_mesh(tile_mesh(x, y, dx == 0 && dy == 0)));
      }
  }
  void write(const std::string& name, const std::vector<unsigned char>& bytes) {
    const fs::path path = folder.path() / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    files.emplace_back(name, path);
  }
};

TEST(QuantizedMeshSource, HeightsOffTheTrianglesFromAFolder) {
  const Layer layer;
  const std::string folder = layer.folder.path().string();
  EXPECT_EQ(classify_source(folder), SourceKind::quantized_mesh);
  QuantizedMeshSource source(folder);
  EXPECT_EQ(source.info().format, "quantized-mesh");
  EXPECT_EQ(source.info().max_zoom, kZoom + 1);
  // A plane is reproduced (to the quantization: 4000 m / 32767 and 1/32767 of a tile).
  for (double lat = 46.70; lat < 46.715; lat += 0.0013)
    for (double lon = 7.86; lon < 7.88; lon += 0.0017) {
      const auto id = source.mesh_tile_at(lat, lon, kZoom);
      ASSERT_TRUE(id);
      if (id->x == layer.x0 && id->y == layer.y0) continue;  // the bump's tile: below
      EXPECT_NEAR(*source.sample_native(lat, lon), plane(lat, lon), 0.2) << lat << "," << lon;
    }
  // The bump: 80 m on its vertex, and in each triangle around it the barycentric share.
  const double west = -180.0 + layer.x0 * kSize, south = 90.0 - (layer.y0 + 1) * kSize;
  const double step = kSize * 4096.0 / kQuantizedMax;
  const double vlat = south + 4 * step, vlon = west + 4 * step;
  EXPECT_NEAR(*source.sample_native(vlat, vlon) - plane(vlat, vlon), 80.0, 0.2);
  // A third of the way into the triangle (4,4)-(5,4)-(5,5): weights 2/3, 1/6, 1/6 -> 80 * 2/3
  // above the plane, where a grid's bilinear would give 80 * (1 - 1/3)(1 - 1/6).
  const double plat = vlat + step / 6.0, plon = vlon + step / 3.0;
  EXPECT_NEAR(*source.sample_native(plat, plon) - plane(plat, plon), 80.0 * (1.0 - 1.0 / 3.0), 0.3);
  // Outside the tiles written: no height.
  EXPECT_TRUE(std::isnan(*source.sample_native(46.60, 7.70)));
  // Through the sampler, as `elevation` reads it: the same.
  std::unique_ptr<HeightSource> opened = open_height_source(SourceSettings{folder, {}, {}, {}, {}, {}, {}, {}}, {});
  EXPECT_NEAR(HeightSampler(*opened).sample(plat, plon), *source.sample_native(plat, plon), 1e-9);
  // The renderer's Mercator tiles: the layer's own triangles clipped to the tile, covering it (the
  // fractions' areas add up to the tile's), every vertex on the mesh.
  const geo::TileId mercator = *geo::tile_containing(46.705, 7.87, 13);
  const TileResult<HeightTile> tile = source.load(mercator, {});
  ASSERT_EQ(tile.status, TileStatus::ok);
  EXPECT_GT(tile.tile.max_m, 1100.0f);
  EXPECT_LT(tile.tile.min_m, 1400.0f);
  ASSERT_NE(tile.tile.triangles, nullptr);
  const TileTriangles& t = *tile.tile.triangles;
  double area = 0.0;
  for (std::size_t f = 0; f < t.indices.size(); f += 3) {
    const std::uint32_t a = t.indices[f], b = t.indices[f + 1], c = t.indices[f + 2];
    area += 0.5 * std::abs((t.u[b] - t.u[a]) * (t.v[c] - t.v[a]) - (t.u[c] - t.u[a]) * (t.v[b] - t.v[a]));
  }
  EXPECT_NEAR(area, 1.0, 1e-4);
  for (std::size_t k = 0; k < t.u.size(); k += 7) {
    ASSERT_TRUE(t.u[k] >= 0.0f && t.u[k] <= 1.0f && t.v[k] >= 0.0f && t.v[k] <= 1.0f) << k;
    // (The tile's east edge is the written layer's: a point on it belongs to the next column,
    // which this layer has not.)
    if (t.u[k] >= 1.0f) continue;
    const auto ll = geo::latlon_from_tile_pixel(mercator, t.u[k], t.v[k], 1);
    EXPECT_NEAR(t.height_m[k], *source.sample_native(ll->lat, ll->lon), 0.5) << k;
  }
}

TEST(QuantizedMeshSource, FromAServerAndItsErrors) {
  const Layer layer;
  test::http::LocalTileServer server;
  for (const auto& [name, path] : layer.files) server.serve_file(name, path);
  QuantizedMeshSource folder(layer.folder.path().string());
  const std::string url = server.url("/files/layer.json");
  EXPECT_EQ(classify_source(url), SourceKind::quantized_mesh);
  QuantizedMeshSource remote(url);
  EXPECT_NEAR(*remote.sample_native(46.705, 7.87), *folder.sample_native(46.705, 7.87), 1e-9);
  EXPECT_GT(server.request_count("/files/12/"), 0);
  NetworkSettings offline;
  offline.offline = true;
  EXPECT_THROW(QuantizedMeshSource(url, offline), SourceError);
  EXPECT_THROW(QuantizedMeshSource(server.url("/files/missing/layer.json")), SourceError);
  EXPECT_THROW(parse_quantized_mesh_layer("{\"format\":\"pbf\",\"tiles\":[\"x\"]}", "l.json"), SourceError);
  EXPECT_THROW(parse_quantized_mesh_layer("{\"tiles\":[\"x\"],\"projection\":\"EPSG:2056\"}", "l.json"), SourceError);
  EXPECT_THROW(parse_quantized_mesh_layer("[1]", "l.json"), SourceError);
}

}  // namespace
}  // namespace trailray::terrain
