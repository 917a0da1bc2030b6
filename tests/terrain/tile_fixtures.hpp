#pragma once
// Test fixtures for tile pyramids: the same heights as a folder of Terrarium PNGs (XYZ or TMS
// rows) or as an MBTiles file, written from any HeightSource, so that tests can check that every
// kind of source serves the same heights. Header-only (tests/CMakeLists.txt compiles only
// *_test.cpp files). Helpers throw std::runtime_error when something cannot be written.
//
//   MemoryHeightSource heights;            // or any HeightSource (a GeoTIFF's, a synthetic one)
//   heights.add(make_height_tile({12, 2138, 1443}, 256, [](auto c, auto r) { return 500.0f + c; }));
//   write_terrarium_folder(heights, tiles, dir, TileScheme::tms);
//   write_terrarium_mbtiles(heights, tiles, dir / "t.mbtiles");
// Terrarium keeps heights to 1/256 m; NaN samples (holes) are written with alpha 0.

#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "terrain/sources/directory_source.hpp"
#include "terrain/codecs/height_decode.hpp"
#include "terrain/sources/tile_source.hpp"
#include "test_support.hpp"

namespace trailray::test {

// A fresh temporary folder, removed at scope end (it holds one hidden file, ".anchor").
class TempDir {
 public:
  TempDir() : anchor_(".anchor") {}
  std::filesystem::path path() const { return anchor_.path().parent_path(); }

 private:
  TempFile anchor_;
};

// A height tile of size x size samples from `height(col, row)` (NaN for holes), min/max set.
inline terrain::HeightTile make_height_tile(const terrain::TileId& id, std::uint32_t size,
                                            const std::function<float(std::uint32_t, std::uint32_t)>& height) {
  terrain::HeightTile tile;
  tile.id = id;
  tile.width = tile.height = size;
  tile.layout = terrain::layout_for_size(size);
  tile.heights.resize(std::size_t{size} * size);
  for (std::uint32_t r = 0; r < size; ++r)
    for (std::uint32_t c = 0; c < size; ++c) tile.heights[std::size_t{r} * size + c] = height(c, r);
  terrain::update_height_range(tile);
  return tile;
}

// A HeightSource over tiles held in memory: ok for those added, no_data for any other.
class MemoryHeightSource : public terrain::HeightSource {
 public:
  explicit MemoryHeightSource(std::string name = "memory") { info_.name = std::move(name); }
  void add(terrain::HeightTile tile) {
    const terrain::TileId id = tile.id;
    tiles_.insert_or_assign(key(id), std::move(tile));
  }
  const terrain::SourceInfo& info() const override { return info_; }
  terrain::TileResult<terrain::HeightTile> load(const terrain::TileId& id, std::stop_token) override {
    const auto it = tiles_.find(key(id));
    if (it == tiles_.end()) return {};
    return {terrain::TileStatus::ok, it->second, {}};
  }

 private:
  static std::tuple<int, std::uint32_t, std::uint32_t> key(const terrain::TileId& id) { return {id.zoom, id.x, id.y}; }
  terrain::SourceInfo info_;
  std::map<std::tuple<int, std::uint32_t, std::uint32_t>, terrain::HeightTile> tiles_;
};

// The tiles of `source` among `ids`, loaded (no_data ones left out; anything else throws).
inline std::vector<terrain::HeightTile> load_tiles(terrain::HeightSource& source,
                                                   std::span<const terrain::TileId> ids) {
  std::vector<terrain::HeightTile> tiles;
  for (const terrain::TileId& id : ids) {
    terrain::TileResult<terrain::HeightTile> r = source.load(id, {});
    if (r.status == terrain::TileStatus::no_data) continue;
    if (r.status != terrain::TileStatus::ok)
      throw std::runtime_error("fixture: cannot load " + geo::to_string(id) + " from " + source.info().name + ": " +
                               std::string(terrain::to_string(r.status)) + " " + r.error);
    tiles.push_back(std::move(r.tile));
  }
  if (tiles.empty()) throw std::runtime_error("fixture: " + source.info().name + " has none of the tiles asked for");
  return tiles;
}

// The metadata both writers store: format, encoding, zoom levels and bounds of what was written.
inline std::vector<std::pair<std::string, std::string>> terrarium_metadata(
    const std::vector<terrain::HeightTile>& tiles) {
  int min_zoom = geo::kMaxTileZoom, max_zoom = 0;
  geo::LatLonBounds bounds;
  for (const terrain::HeightTile& t : tiles) {
    min_zoom = std::min(min_zoom, t.id.zoom);
    max_zoom = std::max(max_zoom, t.id.zoom);
    const auto b = geo::tile_bounds_latlon(t.id);
    if (!b) throw std::runtime_error("fixture: invalid tile id " + geo::to_string(t.id));
    bounds.add(b->min_lat, b->min_lon);
    bounds.add(b->max_lat, b->max_lon);
  }
  char text[160];
  std::snprintf(text, sizeof text, "%.9f,%.9f,%.9f,%.9f", bounds.min_lon, bounds.min_lat, bounds.max_lon,
                bounds.max_lat);
  return {{"name", "trailray test fixture"},
          {"format", "png"},
          {"encoding", "terrarium"},
          {"minzoom", std::to_string(min_zoom)},
          {"maxzoom", std::to_string(max_zoom)},
          {"bounds", text},
          {"type", "baselayer"}};
}

inline void write_file(const std::filesystem::path& path, std::span<const unsigned char> bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("fixture: cannot write " + path.string());
}

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  write_file(path, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
}

// root/{z}/{x}/{y}.png, y numbered by `scheme`, and root/metadata.json (format png, encoding
// terrarium, scheme, minzoom, maxzoom, bounds, all as text like tippecanoe writes them).
// Returns how many tiles were written.
inline std::size_t write_terrarium_folder(terrain::HeightSource& source, std::span<const terrain::TileId> ids,
                                          const std::filesystem::path& root,
                                          terrain::TileScheme scheme = terrain::TileScheme::xyz) {
  const std::vector<terrain::HeightTile> tiles = load_tiles(source, ids);
  for (const terrain::HeightTile& t : tiles)
    write_file(root / terrain::tile_relative_path(t.id, scheme, "png"),
               terrain::encode_height_tile(t, terrain::HeightEncoding::terrarium, /*zlib_level=*/1));
  std::string json = "{\n  \"scheme\": \"";
  json += scheme == terrain::TileScheme::tms ? "tms" : "xyz";
  json += "\"";
  for (const auto& [key, value] : terrarium_metadata(tiles)) json += ",\n  \"" + key + "\": \"" + value + "\"";
  write_file(root / "metadata.json", json + "\n}\n");
  return tiles.size();
}

// Writes an MBTiles file with the sqlite3 C API: the spec's tables and index, rows in TMS
// order. Tests use it directly for odd files (add_raw_tile, exec).
class MbtilesWriter {
 public:
  explicit MbtilesWriter(const std::filesystem::path& file) : path_(file.string()) {
    std::filesystem::create_directories(file.parent_path());
    std::filesystem::remove(file);
    if (sqlite3_open_v2(path_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK)
      fail("open");
    exec("BEGIN");
  }
  // Without the tiles and metadata tables (for files that are SQLite but not MBTiles).
  struct NoSchema {};
  MbtilesWriter(const std::filesystem::path& file, NoSchema) : MbtilesWriter(file) { schema_ = false; }
  ~MbtilesWriter() {
    if (db_) {
      try {
        finish();
      } catch (...) {
      }
    }
  }
  MbtilesWriter(const MbtilesWriter&) = delete;
  MbtilesWriter& operator=(const MbtilesWriter&) = delete;

  void exec(const std::string& sql) {
    char* message = nullptr;
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
      const std::string text = message ? message : "?";
      sqlite3_free(message);
      throw std::runtime_error("fixture: " + path_ + ": " + sql + ": " + text);
    }
  }
  void add_metadata(const std::string& name, const std::string& value) {
    ensure_schema();
    run("INSERT INTO metadata (name, value) VALUES (?1, ?2)", [&](sqlite3_stmt* s) {
      sqlite3_bind_text(s, 1, name.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(s, 2, value.c_str(), -1, SQLITE_TRANSIENT);
    });
  }
  // Stores `bytes` for an XYZ tile id (converted to the TMS row).
  void add_tile(const terrain::TileId& id, std::span<const unsigned char> bytes) {
    add_raw_tile(id.zoom, id.x, *geo::tms_y(id), bytes);
  }
  void add_raw_tile(int zoom, std::uint32_t column, std::uint32_t tms_row, std::span<const unsigned char> bytes) {
    ensure_schema();
    run("INSERT INTO tiles (zoom_level, tile_column, tile_row, tile_data) VALUES (?1, ?2, ?3, ?4)",
        [&](sqlite3_stmt* s) {
          sqlite3_bind_int(s, 1, zoom);
          sqlite3_bind_int64(s, 2, column);
          sqlite3_bind_int64(s, 3, tms_row);
          sqlite3_bind_blob(s, 4, bytes.data(), static_cast<int>(bytes.size()), SQLITE_TRANSIENT);
        });
  }
  // Commits and closes (the destructor does it too, without reporting errors).
  void finish() {
    if (!db_) return;
    if (schema_) ensure_schema();
    exec("COMMIT");
    sqlite3_close(db_);
    db_ = nullptr;
  }

 private:
  void ensure_schema() {
    if (created_ || !schema_) return;
    created_ = true;
    exec("CREATE TABLE metadata (name TEXT, value TEXT)");
    exec("CREATE TABLE tiles (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_data BLOB)");
    exec("CREATE UNIQUE INDEX tile_index ON tiles (zoom_level, tile_column, tile_row)");
  }
  template <class Bind>
  void run(const char* sql, Bind bind) {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db_, sql, -1, &s, nullptr) != SQLITE_OK) fail(sql);
    bind(s);
    const int rc = sqlite3_step(s);
    sqlite3_finalize(s);
    if (rc != SQLITE_DONE) fail(sql);
  }
  [[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("fixture: " + path_ + ": " + what + ": " + (db_ ? sqlite3_errmsg(db_) : "no database"));
  }

  std::string path_;
  sqlite3* db_ = nullptr;
  bool schema_ = true, created_ = false;
};

// An MBTiles file of Terrarium PNGs with metadata format=png, encoding=terrarium, minzoom,
// maxzoom and bounds. Returns how many tiles were written.
inline std::size_t write_terrarium_mbtiles(terrain::HeightSource& source, std::span<const terrain::TileId> ids,
                                           const std::filesystem::path& file) {
  const std::vector<terrain::HeightTile> tiles = load_tiles(source, ids);
  MbtilesWriter writer(file);
  for (const auto& [key, value] : terrarium_metadata(tiles)) writer.add_metadata(key, value);
  for (const terrain::HeightTile& t : tiles)
    writer.add_tile(t.id, terrain::encode_height_tile(t, terrain::HeightEncoding::terrarium, /*zlib_level=*/1));
  writer.finish();
  return tiles.size();
}

}  // namespace trailray::test
