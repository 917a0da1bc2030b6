#pragma once
// The terrain a camera sees (DESIGN.md "The frame", step 1): owns the asynchronous loaders of a
// height and an imagery source and, for a camera, selects the tiles (level of detail by screen
// error), requests the missing ones and hands out what to draw: each tile's heights (or the
// neutral ground where the source has nothing) with the imagery over it. The renderer only
// uploads and draws them.
//
// The selection depends on the tiles' height ranges, which are known only once tiles are loaded,
// so when waiting it is repeated (a few rounds at most) until it no longer changes. Without
// waiting (the viewer), one round per frame: coarser tiles in memory stand in for those still
// loading, and the ancestors of the wanted tiles are requested first so the view fills
// coarse-to-fine. Where the height source has no data (no_data tiles, holes in tiles) or there is
// no source at all, the neutral ground is drawn (DESIGN.md "Terrain sources").

#include <glm/glm.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene/camera/camera.hpp"
#include "terrain/tile.hpp"
#include "terrain/loading/tile_loader.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::scene {

// Vertices per side of a tile's mesh (the level-of-detail selection's samples per tile are one
// less); tiles of the source's finest level get every sample instead.
inline constexpr std::uint32_t kTerrainGridVertices = 65;

// How long a view waits for its tiles.
struct TileLoadPolicy {
  // false (the viewer's mode): never wait; draw what is in memory and leave the loaders working
  // for the next call. `timeout` and `on_progress` are then unused.
  bool wait = true;
  std::chrono::milliseconds timeout{std::chrono::seconds(120)};  // for all tiles of a call together
  // Called about every 100 ms while waiting (on the calling thread).
  std::function<void(const terrain::LoadProgress&)> on_progress;
  double max_screen_error_px = 2.0;  // the level-of-detail selection's target
};

// A tile to draw: its heights, and the imagery over it when there is some.
struct TerrainTile {
  std::shared_ptr<const terrain::HeightTile> heights;  // a neutral tile (all holes) without data
  bool has_data = false;                               // heights from the source
  bool finest = false;                                 // at the height source's finest level
  // The image covering the tile (nullptr: none, the hypsometric tint): the tile's own or an
  // ancestor's (`image_id`), of which the tile covers uv * image_scale + image_offset.
  std::shared_ptr<const terrain::ImageTile> image;
  terrain::TileId image_id;
  glm::vec2 image_scale{1.0f, 1.0f}, image_offset{0.0f, 0.0f};
};

struct TerrainReport {
  int selection_rounds = 0;
  bool timed_out = false;             // handed out what had arrived
  std::vector<std::string> failures;  // tile errors ("<source> z/x/y: ...")
  // Height and imagery tiles wanted and how many have arrived (a loading indicator's figures;
  // pending() > 0 only without waiting or after a timeout).
  terrain::LoadProgress progress;
  double neutral_ground_m = 0.0;  // where the neutral ground is drawn
};

struct TerrainTiles {
  std::vector<TerrainTile> tiles;
  TerrainReport report;
};

class TerrainView {
 public:
  // Either source may be nullptr (no heights: the neutral ground everywhere; no imagery: the
  // tint). The sources must outlive the view.
  TerrainView(terrain::HeightSource* heights, terrain::ImagerySource* imagery,
              terrain::TileLoaderOptions loader_options = {});
  ~TerrainView();
  TerrainView(const TerrainView&) = delete;
  TerrainView& operator=(const TerrainView&) = delete;

  void set_policy(TileLoadPolicy policy) { policy_ = std::move(policy); }
  const TileLoadPolicy& policy() const { return policy_; }

  // The tiles to draw for a camera, requesting (and, by the policy, waiting for) what is missing.
  // `neutral_ground_m`: the neutral ground's height; NaN: the lowest terrain loaded for the view
  // (0 where there is none).
  TerrainTiles tiles_for(const Camera& camera, double neutral_ground_m);

  // The terrain height at a place from the finest height tile already in memory, bilinear
  // (terrain/tile_sampling; NaN: no loaded tile there, or a hole). Never loads: for the viewer's
  // camera, which must not go below the ground and must not wait for it either.
  double height_in_memory(double lat_deg, double lon_deg) const;

  terrain::HeightSource* heights() const { return heights_; }
  terrain::ImagerySource* imagery() const { return imagery_; }

 private:
  using Clock = std::chrono::steady_clock;
  struct Selected;
  Selected select(const Camera& camera, double neutral_ground_m, Clock::time_point deadline, TerrainReport& report);
  std::vector<TerrainTile> height_tiles(const Selected& selected, TerrainReport& report) const;
  void add_imagery(std::vector<TerrainTile>& tiles, Clock::time_point deadline, TerrainReport& report);

  terrain::HeightSource* heights_;
  terrain::ImagerySource* imagery_;
  TileLoadPolicy policy_;
  std::unique_ptr<terrain::TileLoader<terrain::HeightTile>> height_loader_;
  std::unique_ptr<terrain::TileLoader<terrain::ImageTile>> imagery_loader_;
};

}  // namespace trailray::scene
