#pragma once
// A terrain tile as a triangle mesh: a regular grid over the tile's Web Mercator square, each
// vertex lifted to its height (bilinear between the tile's samples), plus skirts hanging from the
// four edges (lod_selection.hpp: they hide the cracks between tiles of different zoom).
//
// Precision (DESIGN.md): vertex positions are float offsets in ECEF from the tile's own origin,
// the tile's centre at its mean height, so no coordinate the GPU sees is larger than the tile
// (a zoom-0 tile is the exception, and is only ever seen from far away). Earth curvature is in
// the positions: every vertex is placed on the ellipsoid at its latitude and longitude.
//
// Holes (NaN samples) are filled at `fill_height_m` and marked uncovered, so the renderer can
// draw them as the neutral ground instead of leaving sky-coloured gaps.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/gl/gl_objects.hpp"
#include "render/gl/gpu_resource_cache.hpp"
#include "terrain/tile.hpp"

namespace trailray::render {

struct TerrainVertex {
  float x = 0, y = 0, z = 0;     // ECEF offset from the mesh origin, metres
  float nx = 0, ny = 0, nz = 1;  // unit surface normal in ECEF
  float height_m = 0;            // height above the ellipsoid (for the hypsometric tint)
  float u = 0, v = 0;            // position in the tile, 0..1 from the north-west (imagery lookup)
  float covered = 1;             // 1 where the source has data, 0 for filled holes (neutral ground)
};

struct TerrainMesh {
  terrain::TileId id;
  glm::dvec3 origin{};  // the tile's centre at its mean height
  std::vector<TerrainVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles
  std::uint32_t grid_vertices = 0;     // per side, skirts not counted
};

// Vertices per side of the grid at the finest level of a source: one per sample (a
// pixel-is-point tile), or the tile's edges plus one per sample boundary (pixel-is-area), so the
// mesh carries every sample the source has.
std::uint32_t full_resolution_grid(const terrain::HeightTile& tile);

// The mesh of `tile` with `grid_vertices` x `grid_vertices` vertices (at least 2) plus skirts of
// terrain::skirt_depth_m(tile.id, grid_vertices - 1); or, for a tile with its source's own
// triangles (HeightTile::triangles), those triangles as they are (grid_vertices 0 in the mesh),
// with skirts under the edges on the tile's border. Throws std::invalid_argument naming the
// tile for an invalid id, an empty or inconsistent grid, or fewer than 2 grid vertices.
TerrainMesh build_terrain_mesh(const terrain::HeightTile& tile, std::uint32_t grid_vertices, float fill_height_m);

// The height of `tile` at a continuous position (u, v) in [0, 1] from the north-west corner,
// bilinear between the four nearest samples (NaN neighbours left out, the weights of the others
// renormalised); NaN when all four are NaN. On the outer half cell of a pixel-is-area tile the
// two outermost samples are extrapolated linearly (when none is a hole), so neighbouring tiles
// meet on their shared edge and no seam shows.
float sample_height_bilinear(const terrain::HeightTile& tile, double u, double v);

// One mesh on the GPU: a vertex array with its vertex and index buffers. Attribute locations:
// 0 position (vec3), 1 normal (vec3), 2 height (float), 3 uv (vec2), 4 covered (float).
struct TerrainTileGpu {
  VertexArray vertex_array;
  Buffer vertices, indices;
  GLsizei index_count = 0;
  glm::dvec3 origin{};
  double bounding_radius_m = 0.0;  // the farthest vertex (skirts included) from the origin
  std::size_t gpu_bytes = 0;       // vertex and index buffers (GPU memory budgets)
  bool has_holes = false;          // some vertices filled (their height depends on the fill height)
};

// Uploads a mesh (the GL context must be current). Throws RenderError when GL refuses.
TerrainTileGpu upload_terrain_mesh(const TerrainMesh& mesh);

// Meshes on the GPU by tile, so a tile drawn in several frames is built and uploaded once, under
// a byte budget (gpu_resource_cache.hpp): begin_frame() before a frame's meshes are asked for,
// evict_to_budget() after it is drawn.
//
// A mesh is kept per tile and grid size. The fill height is not part of the key: a mesh without
// holes does not depend on it (kept when the neutral ground moves, as it does in the viewer with
// the lowest terrain in view), and one with holes is rebuilt in place for a new fill height, so
// meshes for old fill heights do not pile up.
class TerrainMeshCache {
 public:
  explicit TerrainMeshCache(std::size_t budget_bytes) : tiles_(budget_bytes) {}

  void begin_frame() { tiles_.begin_frame(); }
  // The tile's mesh, built and uploaded on first use (or for another fill height where it has
  // holes). Valid until evicted, never within the frame. Throws std::logic_error when a mesh
  // with holes already used in this frame is asked for with another fill height (a frame has one).
  const TerrainTileGpu& get_or_upload(const terrain::HeightTile& tile, std::uint32_t grid_vertices,
                                      float fill_height_m);
  // Between frames: the least recently used meshes not used in this frame go while over the budget.
  void evict_to_budget(std::size_t budget_bytes) {
    tiles_.set_budget(budget_bytes);
    tiles_.evict_to_budget();
  }
  GpuCacheStats stats() const { return tiles_.stats(); }
  std::size_t size() const { return tiles_.size(); }
  void clear() { tiles_.clear(); }

 private:
  struct Key {
    terrain::TileId id;
    std::uint32_t grid_vertices;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept { return geo::TileIdHash{}(k.id) * 31u + k.grid_vertices; }
  };
  struct Entry {
    TerrainTileGpu gpu;
    float fill_height_m;
  };
  GpuResourceCache<Key, Entry, KeyHash> tiles_;
};

}  // namespace trailray::render
