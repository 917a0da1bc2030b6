// Quantized-mesh tiles from a small generator (a grid of triangles over a plane with a bump, its
// vertices numbered by first use as encoders do): a round trip, exact heights on the mesh
// (barycentric in the triangle holding the point), gzip, 32-bit indices past 65536 vertices, and
// damaged tiles refused naming the byte, cut anywhere without a crash.
#include "terrain/codecs/quantized_mesh.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <random>

namespace trailray::terrain {
namespace {

// Heights of the made-up ground: a plane with a bump, at fractions (x, y) of the tile.
double ground(double x, double y) { return 1000.0 + 200.0 * x + 100.0 * y + 50.0 * std::exp(-30.0 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5))); }

// An n x n grid of vertices, two triangles a cell, vertices numbered by first use.
QuantizedMesh grid_mesh(int n) {
  QuantizedMesh m;
  m.min_height_m = 1000.0f;
  m.max_height_m = 1360.0f;
  std::vector<std::int64_t> number(std::size_t(n) * n, -1);
  const auto vertex = [&](int i, int j) {
    std::int64_t& k = number[std::size_t(j) * n + i];
    if (k < 0) {
      k = static_cast<std::int64_t>(m.u.size());
      const double x = double(i) / (n - 1), y = double(j) / (n - 1);
      m.u.push_back(static_cast<std::uint16_t>(std::lround(x * kQuantizedMax)));
      m.v.push_back(static_cast<std::uint16_t>(std::lround(y * kQuantizedMax)));
      m.h.push_back(static_cast<std::uint16_t>(std::lround((ground(x, y) - 1000.0) / 360.0 * kQuantizedMax)));
    }
    return static_cast<std::uint32_t>(k);
  };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const std::uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
    }
  for (int k = 0; k < n; ++k) {
    m.west.push_back(vertex(0, k));
    m.east.push_back(vertex(n - 1, k));
    m.south.push_back(vertex(k, 0));
    m.north.push_back(vertex(k, n - 1));
  }
  return m;
}

std::vector<unsigned char> gzip(const std::vector<unsigned char>& in) {
  z_stream z{};
  deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
  std::vector<unsigned char> out(deflateBound(&z, static_cast<uLong>(in.size())) + 32);
  z.next_in = const_cast<unsigned char*>(in.data());
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

void expect_same(const QuantizedMesh& a, const QuantizedMesh& b) {
  EXPECT_EQ(a.u, b.u);
  EXPECT_EQ(a.v, b.v);
  EXPECT_EQ(a.h, b.h);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.west, b.west);
  EXPECT_EQ(a.north, b.north);
  EXPECT_EQ(a.min_height_m, b.min_height_m);
  EXPECT_EQ(a.max_height_m, b.max_height_m);
}

TEST(QuantizedMesh, RoundTripAndExactHeightsOnTheMesh) {
  const QuantizedMesh made = grid_mesh(17);
  const std::vector<unsigned char> bytes = encode_quantized_mesh(made);
  const QuantizedMesh read = decode_quantized_mesh(bytes);
  expect_same(made, read);
  EXPECT_EQ(read.vertex_count(), 17u * 17u);
  EXPECT_EQ(read.triangle_count(), 2u * 16u * 16u);
  const MeshHeights heights(read);
  // At a vertex: its height (quantized: within half a step of 360 m / 32767).
  EXPECT_NEAR(heights.at(0.5, 0.5), ground(0.5, 0.5), 0.006);
  EXPECT_NEAR(heights.at(0.0, 0.0), 1000.0, 0.006);
  EXPECT_NEAR(heights.at(1.0, 1.0), 1300.0 + 50.0 * std::exp(-15.0), 0.006);
  // Inside a triangle: the plane through its three vertices, not the ground between them.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const double x = fraction(random), y = fraction(random);
    const int i = std::min(15, int(x * 16)), j = std::min(15, int(y * 16));
    const double fx = x * 16 - i, fy = y * 16 - j;
    const double x0 = i / 16.0, x1 = (i + 1) / 16.0, y0 = j / 16.0, y1 = (j + 1) / 16.0;
    // The cell's two triangles: (a, b, c) below the diagonal a-c, (a, c, d) above it.
    const double expected = fx >= fy ? ground(x0, y0) + fx * (ground(x1, y0) - ground(x0, y0)) +
                                           fy * (ground(x1, y1) - ground(x1, y0))
                                     : ground(x0, y0) + fy * (ground(x0, y1) - ground(x0, y0)) +
                                           fx * (ground(x1, y1) - ground(x0, y1));
    EXPECT_NEAR(heights.at(x, y), expected, 0.02) << x << "," << y;
  }
  EXPECT_TRUE(std::isnan(heights.at(1.2, 0.5)));
  EXPECT_TRUE(std::isnan(heights.at(-0.01, 0.5)));
}

TEST(QuantizedMesh, GzipAndWideIndices) {
  const QuantizedMesh small = grid_mesh(9);
  expect_same(small, decode_quantized_mesh(gzip(encode_quantized_mesh(small))));
  const QuantizedMesh big = grid_mesh(260);  // 67,600 vertices: 32-bit indices, aligned to 4
  ASSERT_GT(big.vertex_count(), 65536u);
  const QuantizedMesh read = decode_quantized_mesh(encode_quantized_mesh(big));
  expect_same(big, read);
  EXPECT_NEAR(MeshHeights(read).at(0.25, 0.75), ground(0.25, 0.75), 0.05);
}

TEST(QuantizedMesh, DamagedTilesAreRefusedNamingTheByte) {
  const std::vector<unsigned char> good = encode_quantized_mesh(grid_mesh(5));
  // Cut anywhere: an error, never a crash or a read past the end.
  for (std::size_t n = 0; n < good.size(); ++n) {
    const std::vector<unsigned char> cut(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(n));
    EXPECT_THROW(decode_quantized_mesh(cut), QuantizedMeshError) << n;
  }
  // A triangle index past the vertices (the first triangle's third code, raised).
  std::vector<unsigned char> bad = good;
  const std::size_t triangles_at = 88 + 4 + 3 * 2 * 25;  // after the header and 25 vertices' three channels
  bad[triangles_at + 4 + 4] = 0xff;
  try {
    decode_quantized_mesh(bad);
    FAIL();
  } catch (const QuantizedMeshError& e) {
    EXPECT_EQ(e.byte(), triangles_at + 4 + 4);
    EXPECT_NE(std::string(e.what()).find("triangle indices"), std::string::npos) << e.what();
  }
  // An inverted height range.
  bad = good;
  const float low = 2000.0f;
  std::memcpy(bad.data() + 24, &low, sizeof low);
  EXPECT_THROW(decode_quantized_mesh(bad), QuantizedMeshError);
  // A height range far from the Earth's (a damaged header).
  bad = good;
  const float far = 1.0e20f;
  std::memcpy(bad.data() + 28, &far, sizeof far);
  EXPECT_THROW(decode_quantized_mesh(bad), QuantizedMeshError);
  // A damaged gzip stream.
  std::vector<unsigned char> packed = gzip(good);
  packed.resize(packed.size() / 2);
  EXPECT_THROW(decode_quantized_mesh(packed), QuantizedMeshError);
}

// One triangle over the south-west half of the tile, its three vertices at quantized height q.
QuantizedMesh half_tile(float low, float high, std::uint16_t q) {
  QuantizedMesh m;
  m.min_height_m = low;
  m.max_height_m = high;
  m.u = {0, kQuantizedMax, 0};
  m.v = {0, 0, kQuantizedMax};
  m.h = {q, q, q};
  m.triangles = {0, 1, 2};
  return m;
}

TEST(QuantizedMesh, TheTopOfTheHeightRangeIsItsHighestHeightExactly) {
  // Found by fuzz_quantized_mesh: the range subtracted in float rounded 0.0002 m past its top.
  const QuantizedMesh m = half_tile(-8559.03906f, -0.126182854f, kQuantizedMax);
  EXPECT_EQ(m.height_m(0), double(m.max_height_m));
  const MeshHeights heights(m);
  EXPECT_LE(heights.at(0.2, 0.2), double(m.max_height_m));
  EXPECT_EQ(half_tile(-8559.03906f, -0.126182854f, 0).height_m(0), double(-8559.03906f));
}

TEST(QuantizedMesh, OverlappingTrianglesPastATerrainMeshsAreRefused) {
  // A long fan of slivers from one corner, as a flat tile may hold: each spans most of the
  // tile's cells, and the index takes them.
  QuantizedMesh fan = half_tile(0.0f, 100.0f, 0);
  fan.u = {0};
  fan.v = {0};
  fan.h = {0};
  fan.triangles.clear();
  for (std::uint16_t k = 0; k <= 200; ++k) {
    fan.u.push_back(kQuantizedMax);
    fan.v.push_back(static_cast<std::uint16_t>(k * (kQuantizedMax / 200)));
    fan.h.push_back(static_cast<std::uint16_t>(k * 100));
  }
  for (std::uint32_t k = 1; k <= 200; ++k) fan.triangles.insert(fan.triangles.end(), {0, k, k + 1});
  const MeshHeights fan_heights(fan);
  EXPECT_FALSE(std::isnan(fan_heights.at(0.9, 0.5)));
  // The same tile-sized triangle 50,000 times (a hostile tile: 300 kB that would ask for 200 MB
  // of index): refused.
  QuantizedMesh stacked = half_tile(0.0f, 100.0f, 0);
  for (int k = 1; k < 50000; ++k) stacked.triangles.insert(stacked.triangles.end(), {0, 1, 2});
  try {
    const MeshHeights refused(stacked);
    FAIL() << "50,000 stacked triangles were indexed";
  } catch (const QuantizedMeshError& e) {
    EXPECT_NE(std::string(e.what()).find("overlap"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace trailray::terrain
