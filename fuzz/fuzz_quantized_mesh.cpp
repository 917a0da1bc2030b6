// libFuzzer target: arbitrary bytes as a quantized-mesh terrain tile (plain or gzip), through
// decode_quantized_mesh and the exact heights on the mesh. Contract: a QuantizedMeshError, or a
// mesh whose every index is a vertex and whose heights inside the tile are NaN or within its
// height range; anything else aborts.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "terrain/quantized_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace trailray::terrain;
  QuantizedMesh mesh;
  try {
    mesh = decode_quantized_mesh(std::span(data, size));
  } catch (const QuantizedMeshError&) {
    return 0;
  }
  const std::size_t n = mesh.vertex_count();
  if (mesh.v.size() != n || mesh.h.size() != n || mesh.triangles.size() % 3 != 0) std::abort();
  for (const auto* list : {&mesh.triangles, &mesh.west, &mesh.south, &mesh.east, &mesh.north})
    for (std::uint32_t i : *list)
      if (i >= n) std::abort();
  if (mesh.triangle_count() > 200000) return 0;  // the index build is linear; keep runs quick
  const MeshHeights heights(std::move(mesh));
  const double low = heights.mesh().min_height_m, high = heights.mesh().max_height_m;
  for (double x : {0.0, 0.3, 0.5, 0.77, 1.0})
    for (double y : {0.0, 0.41, 0.5, 1.0}) {
      const double h = heights.at(x, y);
      // Rounding grows with the heights' size; nothing else may take a height out of the range.
      const double slack = 1e-9 * (std::abs(low) + std::abs(high)) + 1e-6;
      if (!std::isnan(h) && (h < low - slack || h > high + slack)) {
        std::fprintf(stderr, "fuzz: height %f outside %f..%f\n", h, low, high);
        std::abort();
      }
    }
  return 0;
}
