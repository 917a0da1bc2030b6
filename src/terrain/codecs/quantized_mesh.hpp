#pragma once
// Cesium's quantized-mesh-1.0 terrain tiles (.terrain: what Cesium ion, cesium-terrain-builder
// and AlpineMaps' terrain builder write): a tile's triangles as they were made, vertices at
// quantized positions (u, v across the tile from its south-west corner, 0..32767) and heights
// (0..32767 between the tile's lowest and highest), all zig-zag delta coded; triangles by index,
// "high water mark" coded; the vertices on each edge; then optional extensions (normals, water
// mask, metadata), skipped. Little-endian throughout; a gzip-compressed tile is inflated first.
//
// Decoding is bounded and checked: every count against the bytes left, every index against the
// vertices, so a damaged tile is an error naming the byte, never a read past the end.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace trailray::terrain {

// A tile that cannot be decoded: what is wrong and at which byte of the (inflated) tile.
class QuantizedMeshError : public std::runtime_error {
 public:
  QuantizedMeshError(std::size_t byte, const std::string& what)
      : std::runtime_error("quantized-mesh byte " + std::to_string(byte) + ": " + what), byte_(byte) {}
  std::size_t byte() const { return byte_; }

 private:
  std::size_t byte_;
};

inline constexpr std::uint16_t kQuantizedMax = 32767;

struct QuantizedMesh {
  double center_ecef[3] = {0, 0, 0};
  float min_height_m = 0.0f, max_height_m = 0.0f;
  // Per vertex: position across the tile (0 west/south .. 32767 east/north) and quantized height.
  std::vector<std::uint16_t> u, v, h;
  std::vector<std::uint32_t> triangles;  // three vertex indices each, counter-clockwise
  std::vector<std::uint32_t> west, south, east, north;  // the vertices on each edge

  std::size_t vertex_count() const { return u.size(); }
  std::size_t triangle_count() const { return triangles.size() / 3; }
  // In double throughout: the range subtracted in float may round past its top (found by fuzzing).
  double height_m(std::size_t vertex) const {
    const double low = min_height_m, high = max_height_m;
    return low + (high - low) * (double(h[vertex]) / kQuantizedMax);
  }
};

// Decodes a tile (gzip-compressed or not). Throws QuantizedMeshError for anything malformed: a
// count past the end, an index past the vertices, a height range that is not finite, a vertex
// outside 0..32767, inflated data over 64 MiB.
QuantizedMesh decode_quantized_mesh(std::span<const unsigned char> bytes);

// Writes a tile (uncompressed; no extensions): the tests' generator, and a round trip for the
// decoder. Vertex counts over 65536 get 32-bit indices, as the format says.
std::vector<unsigned char> encode_quantized_mesh(const QuantizedMesh& mesh);

// The height at (x, y), fractions of the tile from its south-west corner (0..1), exactly on the
// mesh: the triangle holding the point, its three vertices' heights weighted barycentrically.
// NaN outside every triangle. A grid of cells, each listing the triangles whose bounds meet it,
// finds the triangle. Terrain triangles do not overlap, so the lists stay short; a tile whose
// triangles would fill them far past that (a damaged or hostile tile: 1 MiB of overlapping
// tile-sized triangles would ask for over a gigabyte) is refused with QuantizedMeshError.
class MeshHeights {
 public:
  explicit MeshHeights(QuantizedMesh mesh);
  double at(double x, double y) const;
  const QuantizedMesh& mesh() const { return mesh_; }

 private:
  QuantizedMesh mesh_;
  static constexpr int kCells = 32;
  std::vector<std::vector<std::uint32_t>> cells_;  // triangles overlapping each cell
};

}  // namespace trailray::terrain
