#pragma once
// A folder of tiles, {z}/{x}/{y}.png (or .webp, .jpg, .jpeg, .tif), as gdal2tiles, mb-util,
// tippecanoe --output-to-directory and most tile downloaders write them. Read-only.
//
// The row numbering is the options' scheme when given, else the metadata's, else XYZ:
//   metadata.json (mb-util, tippecanoe): "scheme", "format", "minzoom", "maxzoom",
//                  "bounds" ("w,s,e,n"), "encoding", "attribution";
//   tilemapresource.xml (gdal2tiles):   TMS.
// Without zoom levels in the metadata they come from the numeric folders (0/, 7/, ...); without
// bounds, from the tiles present at the coarsest level.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "terrain/loading/stop_token.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

struct DirectorySourceOptions {
  std::optional<TileScheme> scheme;  // overrides the metadata
};

// "{z}/{x}/{y}.{extension}" for a tile, y in the given scheme's numbering.
std::filesystem::path tile_relative_path(const TileId& tile, TileScheme scheme, std::string_view extension);

class DirectoryTileSource : public EncodedTileSource {
 public:
  // Throws SourceError naming the folder: not a folder, no zoom folders in it, a metadata file
  // that cannot be read or has malformed values.
  explicit DirectoryTileSource(std::filesystem::path root, DirectorySourceOptions options = {});

  const SourceInfo& info() const override { return info_; }
  TileScheme scheme() const { return scheme_; }

  // ok with the file's bytes; no_data when no file exists for the tile (or it lies outside the
  // zoom levels); failed with "<folder> <z/x/y>: cannot read <file>: <reason>" for a file that
  // cannot be read, is empty or is too big to be a tile; cancelled when `stop` was requested.
  EncodedTile fetch(const TileId& tile, StopToken stop) override;

 private:
  std::filesystem::path root_;
  TileScheme scheme_ = TileScheme::xyz;
  SourceInfo info_;
  std::vector<std::string> extensions_;  // tried in this order
};

}  // namespace trailray::terrain
