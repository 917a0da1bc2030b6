#pragma once
// Level-of-detail tile selection: which Web Mercator tiles a camera wants, as the quadtree of
// AlpineMaps (and Cesium, and most tiled terrain renderers) picks them. Starting from the world
// tile, a tile is split into its four children while its screen-space error is too large:
//
//   geometric error  = the tile's ground width in metres / tile_samples (the spacing of its
//                      height samples, at its widest: the edge nearest the equator);
//   screen error     = geometric error * camera.pixels_per_metre_at(d), d the distance from the
//                      camera to the nearest point of the tile's bounding volume.
//
// Splitting goes most-important first (a priority queue on screen error), so when the tile or
// memory budget runs out the far tiles stay coarse, not the near ones. Tiles whose bounding
// volume lies entirely outside the view frustum, or entirely behind the Earth's horizon, are
// dropped. The result is a set of disjoint tiles covering the visible ground.
//
// Bounding volumes come from the tiles' height ranges (HeightRange): a tile that is not known yet
// takes its nearest known ancestor's range (a tile's heights lie within its parent's), else the
// settings' default. Unknown heights only make volumes larger, so they can cost extra tiles but
// never holes.
//
// Cracks: neighbouring tiles of different zoom do not share their edge vertices, so a coarse
// tile's straight edge and the finer neighbour's edge can leave a sliver of sky between them.
// The renderer hides it with skirts, a strip hanging down from each tile edge by
// skirt_depth_m(tile), deeper than any such gap.
//
// While tiles load, tiles_to_draw() picks what to draw from what is in memory: a wanted tile if
// it is loaded, else its nearest loaded ancestor, which then stands in for all of its wanted
// descendants until every one of them is loaded (the AlpineMaps rule), so the drawn set is always
// disjoint: no overlaps, no z-fighting.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "terrain/lod/lod_camera.hpp"
#include "terrain/tile.hpp"

namespace trailray::terrain {

struct LodSettings {
  double max_screen_error_px = 2.0;  // split while a tile's screen error exceeds this
  int min_zoom = 0;                  // coarser tiles are always split (a source's first level)
  int max_zoom = 15;                 // never split past this (a source's finest level)
  std::uint32_t tile_samples = 256;  // height samples across a tile (256 Terrarium, 65 AlpineMaps)
  // Budgets for the selected tiles; reaching either stops the splitting. The tiles at min_zoom
  // are always selected, even beyond the budgets: the view needs something to draw.
  std::size_t max_tiles = 600;
  std::size_t max_memory_bytes = std::size_t{512} << 20;
  std::size_t bytes_per_tile = std::size_t{512} << 10;  // a 256 x 256 float height grid + RGBA image
  // Height range of a tile with no known range itself nor on any ancestor: from below the Dead
  // Sea shore to above Everest.
  float default_min_height_m = -500.0f;
  float default_max_height_m = 9000.0f;
};

// A tile's [min, max] height in metres above the ellipsoid, when known (from a loaded tile's
// HeightTile::min_m / max_m, or a source's metadata); nullopt when not.
using HeightRange = std::function<std::optional<std::pair<float, float>>(const TileId&)>;

struct SelectedTile {
  TileId id;
  double screen_error_px = 0.0;  // at the tile's nearest point
  double distance_m = 0.0;       // camera to the nearest point of the tile's bounding volume (0 inside)
  // For loading order, higher = more important: the screen pixels per ground metre at the
  // tile's nearest point (near tiles first; equal for tiles at the same distance).
  double priority = 0.0;
};

struct LodSelection {
  // The wanted leaves of the quadtree: disjoint, covering the visible ground; most important
  // (highest priority) first.
  std::vector<SelectedTile> tiles;
  // Whether the tile or memory budget stopped a split that the screen error asked for: some
  // tiles are then coarser than max_screen_error_px.
  bool budget_limited = false;
};

// The tiles `camera` wants. Throws std::invalid_argument for an unusable camera (camera_problem)
// or settings (zooms outside [0, geo::kMaxTileZoom] or min_zoom > max_zoom, a non-positive or
// non-finite error threshold, zero tile_samples, an inverted default height range).
LodSelection select_tiles(const LodCamera& camera, const LodSettings& settings, const HeightRange& height_range = {});

// What to draw now, given which tiles are loaded: for each wanted tile the tile itself if loaded,
// else its nearest loaded ancestor (nothing where no ancestor is loaded either); an ancestor
// drawn for one wanted tile replaces every other drawn tile under it. The result is disjoint (no
// tile in it is an ancestor of another) and covers every wanted tile that is loaded or has a
// loaded ancestor. Ordered as the selection, each tile once.
std::vector<TileId> tiles_to_draw(const LodSelection& selection, const std::function<bool(const TileId&)>& is_loaded);

// The spacing of a tile's height samples on the ground, in metres: its width at the latitude of
// its edge nearest the equator divided by tile_samples. NaN for an invalid tile or zero samples.
double geometric_error_m(const TileId& tile, std::uint32_t tile_samples = 256);

// How far the skirts of a tile hang below its edges, metres: a few times its geometric error
// (the gap to a coarser neighbour is at most the height difference across about one of the
// neighbour's samples, which is a few times this tile's spacing on steep ground), at least
// kMinSkirtDepthM. An invalid tile gets kMinSkirtDepthM.
inline constexpr double kMinSkirtDepthM = 5.0;
double skirt_depth_m(const TileId& tile, std::uint32_t tile_samples = 256);

}  // namespace trailray::terrain
