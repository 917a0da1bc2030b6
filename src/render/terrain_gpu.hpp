#pragma once
// The terrain on the GPU: the meshes and imagery textures of the tiles a TerrainView hands out,
// uploaded on first use and kept between frames under byte budgets (GpuResourceCache), so
// turning back to a place seen a moment ago costs no upload.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "render/gl/gpu_resource_cache.hpp"
#include "render/passes/terrain_mesh.hpp"
#include "render/passes/terrain_pass.hpp"
#include "scene/terrain_view.hpp"

namespace trailray::render {

// GPU memory for tiles kept between frames, 512 MiB in all (as much as one TileLoader keeps
// decoded by default). A view (at most 600 tiles, lod_selection.hpp) takes 20-80 MiB of meshes
// from a DEM (a 65 x 65 mesh about 280 KiB, a full-resolution one of a 256-sample tile about
// 4 MiB) and up to 200 MiB of imagery (341 KiB a 256 x 256 image with mipmaps): several views'
// meshes and at least one view's imagery stay, so turning back costs no upload.
inline constexpr std::size_t kDefaultMeshBudgetBytes = std::size_t{256} << 20;
inline constexpr std::size_t kDefaultImageryBudgetBytes = std::size_t{256} << 20;

class TerrainGpu {
 public:
  TerrainGpu() = default;

  // Starts a frame: what the frame uploads or reuses stays until its end.
  void begin_frame();
  // The tiles' draw list, uploading the meshes (holes filled at `neutral_m`) and imagery not on
  // the GPU yet. The pointers in it stay valid until end_frame.
  std::vector<TerrainDrawItem> upload(std::span<const scene::TerrainTile> tiles, float neutral_m);
  // Between frames: frees the least recently used beyond the budgets, never what the frame drew
  // (a view that needs more keeps it, and frees it later).
  void end_frame(std::size_t mesh_budget_bytes, std::size_t imagery_budget_bytes);

  GpuCacheStats mesh_stats() const { return meshes_.stats(); }
  GpuCacheStats imagery_stats() const { return imagery_.stats(); }

 private:
  const Texture* imagery_texture(const scene::TerrainTile& tile);

  TerrainMeshCache meshes_{kDefaultMeshBudgetBytes};
  GpuResourceCache<terrain::TileId, Texture> imagery_{kDefaultImageryBudgetBytes};
};

}  // namespace trailray::render
