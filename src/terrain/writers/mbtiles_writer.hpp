#pragma once
// Writes an MBTiles file (the tile pyramid in one SQLite file: `metadata` name/value pairs and a
// `tiles` table, rows numbered from the south as the spec's TMS scheme has them), and reads back
// the extra tables a writer added beside them. The caller writes into a temporary path and renames
// it into place (app/common/output_file): an MBTiles file is never seen half written.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "terrain/tile.hpp"

namespace trailray::terrain {

class MbtilesWriter {
 public:
  // Creates `file` (it must not exist) with the spec's tables. Throws SourceError naming it.
  explicit MbtilesWriter(const std::filesystem::path& file);
  ~MbtilesWriter();
  MbtilesWriter(const MbtilesWriter&) = delete;
  MbtilesWriter& operator=(const MbtilesWriter&) = delete;

  void put_metadata(std::string_view name, std::string_view value);
  // `tile` in XYZ numbering (rows from the north): stored as TMS.
  void put_tile(const TileId& tile, std::span<const unsigned char> bytes);
  // A row of an extra table `table` (key TEXT PRIMARY KEY, data BLOB), made on first use.
  void put_extra(std::string_view table, std::string_view key, std::span<const unsigned char> bytes);
  // Commits everything (one transaction from the start) and closes the file.
  void finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// An MBTiles file's metadata (empty when it has no such table). Throws SourceError naming it
// when it cannot be opened.
std::map<std::string, std::string> read_mbtiles_metadata(const std::filesystem::path& file);

// The rows of an extra table (empty when it has none), key -> data. Throws SourceError.
std::map<std::string, std::vector<unsigned char>> read_mbtiles_extra(const std::filesystem::path& file,
                                                                     std::string_view table);

}  // namespace trailray::terrain
