#pragma once
// An MBTiles file (https://github.com/mapbox/mbtiles-spec): an SQLite database with a `tiles`
// table (or view) of zoom_level, tile_column, tile_row (TMS: rows from the south) and
// tile_data, and a `metadata` table of name/value pairs (format, bounds, minzoom, maxzoom,
// attribution, and the non-standard "encoding" of height tiles). Opened read-only through an
// SQLite URI (mode=ro): nothing is ever written, not even a journal.

#include <filesystem>
#include <memory>

#include "terrain/loading/stop_token.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

class MbtilesTileSource : public EncodedTileSource {
 public:
  // Throws SourceError naming the file: missing, not an SQLite database, no tiles table,
  // malformed metadata values, vector tiles (format pbf).
  explicit MbtilesTileSource(std::filesystem::path file);
  ~MbtilesTileSource() override;
  MbtilesTileSource(const MbtilesTileSource&) = delete;
  MbtilesTileSource& operator=(const MbtilesTileSource&) = delete;

  const SourceInfo& info() const override { return info_; }

  // ok with the stored bytes; no_data for a tile not in the file (or outside its zoom levels);
  // failed for an SQLite error, an empty blob or gzip-compressed data (vector tiles, not a
  // raster image); cancelled when `stop` was requested. Thread-safe: concurrent fetches each
  // use a connection of their own, from a pool that grows to the number of concurrent callers.
  EncodedTile fetch(const TileId& tile, StopToken stop) override;

 private:
  class ConnectionPool;
  std::unique_ptr<ConnectionPool> pool_;
  SourceInfo info_;
};

}  // namespace trailray::terrain
