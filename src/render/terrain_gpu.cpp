#include "render/terrain_gpu.hpp"

#include <algorithm>

namespace trailray::render {
namespace {

// Vertices per side of a neutral ground tile: the LOD splits it until its geometric error (a
// 64th of its width) is 2 px, so 16 cells keep its curvature's sag within a pixel or so.
constexpr std::uint32_t kNeutralGridVertices = 17;

// An RGBA8 texture with its full mipmap chain (upload_imagery_texture).
std::size_t imagery_texture_bytes(std::uint32_t width, std::uint32_t height) {
  std::size_t bytes = 0;
  for (;;) {
    bytes += std::size_t{width} * height * 4;
    if (width == 1 && height == 1) return bytes;
    width = std::max(1u, width / 2);
    height = std::max(1u, height / 2);
  }
}

}  // namespace

void TerrainGpu::begin_frame() {
  meshes_.begin_frame();
  imagery_.begin_frame();
}

std::vector<TerrainDrawItem> TerrainGpu::upload(std::span<const scene::TerrainTile> tiles, float neutral_m) {
  std::vector<TerrainDrawItem> items;
  items.reserve(tiles.size());
  for (const scene::TerrainTile& t : tiles) {
    // The finest level carries every sample the source has; coarser levels the LOD grid; the flat
    // neutral ground only bends with the Earth, which a few vertices follow.
    std::uint32_t grid = scene::kTerrainGridVertices;
    if (!t.has_data)
      grid = kNeutralGridVertices;
    else if (t.finest)
      grid = std::max(scene::kTerrainGridVertices, full_resolution_grid(*t.heights));
    TerrainDrawItem item;
    item.mesh = &meshes_.get_or_upload(*t.heights, grid, neutral_m);
    if (t.image) item.imagery = {imagery_texture(t), t.image_scale, t.image_offset};
    items.push_back(item);
  }
  return items;
}

const Texture* TerrainGpu::imagery_texture(const scene::TerrainTile& tile) {
  if (const Texture* texture = imagery_.find(tile.image_id)) return texture;
  const terrain::ImageTile& image = *tile.image;
  return &imagery_.insert(tile.image_id, upload_imagery_texture(image.width, image.height, image.rgba),
                          imagery_texture_bytes(image.width, image.height));
}

void TerrainGpu::end_frame(std::size_t mesh_budget_bytes, std::size_t imagery_budget_bytes) {
  meshes_.evict_to_budget(mesh_budget_bytes);
  imagery_.set_budget(imagery_budget_bytes);
  imagery_.evict_to_budget();
}

}  // namespace trailray::render
