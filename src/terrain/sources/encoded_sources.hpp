#pragma once
// Decoding sources over an EncodedTileSource (a folder, an MBTiles file, an HTTP server):
//   EncodedHeightSource   - fetch + decode_height_tile with a HeightEncoding;
//   EncodedImagerySource  - fetch + decode_image_tile.
// And TileMetadata, the metadata keys the folder and MBTiles sources share (MBTiles' metadata
// table, mb-util's and tippecanoe's metadata.json).

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "terrain/loading/stop_token.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

// What a tile pyramid says about itself. Each value is set only when the metadata has it.
struct TileMetadata {
  std::optional<int> min_zoom, max_zoom;
  std::optional<geo::LatLonBounds> bounds;
  std::optional<HeightEncoding> encoding;  // the non-standard "encoding" key
  std::optional<TileScheme> scheme;        // "scheme": only folders have a choice (MBTiles is TMS)
  std::string format;                      // lower case; "jpeg" is stored as "jpg"
  std::string attribution;

  // Takes one key: "minzoom", "maxzoom" (integers 0..30, as text or numbers), "bounds"
  // ("west,south,east,north" degrees), "encoding", "scheme" ("xyz" or "tms"), "format",
  // "attribution"; other keys are ignored. Throws SourceError naming `where` (the file) and the
  // key for a malformed value, e.g. "tiles.mbtiles: metadata minzoom \"abc\" is not a zoom level
  // 0..30".
  void set(std::string_view key, std::string_view value, const std::string& where);

  // Also throws SourceError when min_zoom > max_zoom.
  void check(const std::string& where) const;

  // Copies what is set into `info`.
  void apply_to(SourceInfo& info) const;
};

class EncodedHeightSource : public HeightSource {
 public:
  // `encoding` when given, else the one in the source's metadata (info().encoding); SourceError
  // naming the source when neither says.
  explicit EncodedHeightSource(std::shared_ptr<EncodedTileSource> tiles,
                               std::optional<HeightEncoding> encoding = std::nullopt);

  const SourceInfo& info() const override { return info_; }
  HeightEncoding encoding() const { return *info_.encoding; }

  // The fetch's status; a tile that does not decode is `failed` with "<source name> <z/x/y>:
  // <what is wrong>" (so is a fetch failure, prefixed thus unless its message already is).
  TileResult<HeightTile> load(const TileId& tile, StopToken stop) override;

 private:
  std::shared_ptr<EncodedTileSource> tiles_;
  SourceInfo info_;
};

class EncodedImagerySource : public ImagerySource {
 public:
  explicit EncodedImagerySource(std::shared_ptr<EncodedTileSource> tiles);

  const SourceInfo& info() const override { return tiles_->info(); }
  TileResult<ImageTile> load(const TileId& tile, StopToken stop) override;
  // The tiles as stored, for those who pass them on undecoded (`trailray serve`).
  EncodedTileSource& tiles() const { return *tiles_; }

 private:
  std::shared_ptr<EncodedTileSource> tiles_;
};

}  // namespace trailray::terrain
