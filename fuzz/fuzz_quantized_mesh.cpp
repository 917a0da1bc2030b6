// libFuzzer target: arbitrary bytes as a quantized-mesh terrain tile (plain or gzip), through
// decode_quantized_mesh and the exact heights on the mesh. Contract: a QuantizedMeshError, or a
// mesh whose every index is a vertex, whose height index is built (or refused with a
// QuantizedMeshError) and whose heights inside the tile are NaN or within its height range;
// anything else aborts, saying which.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>

#include "terrain/codecs/quantized_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace trailray::terrain;
  QuantizedMesh mesh;
  try {
    mesh = decode_quantized_mesh(std::span(data, size));
  } catch (const QuantizedMeshError&) {
    return 0;
  }
  const std::size_t n = mesh.vertex_count();
  const auto violated = [](const char* what) {
    std::fprintf(stderr, "fuzz: contract violated: %s\n", what);
    std::abort();
  };
  if (mesh.v.size() != n || mesh.h.size() != n || mesh.triangles.size() % 3 != 0) violated("channel sizes differ");
  for (const auto* list : {&mesh.triangles, &mesh.west, &mesh.south, &mesh.east, &mesh.north})
    for (std::uint32_t i : *list)
      if (i >= n) violated("an index past the vertices");
  std::optional<MeshHeights> built;
  try {
    built.emplace(std::move(mesh));
  } catch (const QuantizedMeshError&) {
    return 0;  // overlapping triangles past the index's budget
  }
  const MeshHeights& heights = *built;
  const double low = heights.mesh().min_height_m, high = heights.mesh().max_height_m;
  for (double x : {0.0, 0.3, 0.5, 0.77, 1.0})
    for (double y : {0.0, 0.41, 0.5, 1.0}) {
      const double h = heights.at(x, y);
      // Rounding grows with the heights' size; nothing else may take a height out of the range.
      const double slack = 1e-9 * (std::abs(low) + std::abs(high)) + 1e-6;
      if (!std::isnan(h) && (h < low - slack || h > high + slack)) {
        std::fprintf(stderr, "fuzz: contract violated: height %.9g outside %.9g..%.9g\n", h, low, high);
        std::abort();
      }
    }
  return 0;
}
