#include "terrain/sources/mbtiles_source.hpp"

#include <sqlite3.h>

#include <cstdio>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "terrain/sources/encoded_sources.hpp"

namespace trailray::terrain {

namespace fs = std::filesystem;

namespace {

// Idle connections kept for reuse; more concurrent fetches open more and close them after.
constexpr std::size_t kMaxIdleConnections = 16;
// Another process writing the file holds a lock for a moment; wait rather than fail.
constexpr int kBusyTimeoutMs = 5000;

// "file:" URI for sqlite3_open_v2: everything but unreserved characters percent-encoded, so a
// '?' or '#' or '%' in a path stays part of it.
std::string read_only_uri(const fs::path& file) {
  std::string uri = "file:";
  for (const unsigned char c : file.string()) {
    const bool unreserved = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '/' ||
                            c == '.' || c == '_' || c == '-' || c == '~';
    if (unreserved) {
      uri += static_cast<char>(c);
    } else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", c);
      uri += buf;
    }
  }
  return uri + "?mode=ro";
}

struct Statement {
  sqlite3_stmt* stmt = nullptr;
  ~Statement() { sqlite3_finalize(stmt); }
};

// One connection and its prepared tile query; used by one thread at a time.
struct MbtilesConnection {
  sqlite3* db = nullptr;
  sqlite3_stmt* select_tile = nullptr;

  MbtilesConnection() = default;
  MbtilesConnection(const MbtilesConnection&) = delete;
  MbtilesConnection& operator=(const MbtilesConnection&) = delete;
  ~MbtilesConnection() {
    sqlite3_finalize(select_tile);
    sqlite3_close(db);
  }
};

}  // namespace

class MbtilesTileSource::ConnectionPool {
 public:
  explicit ConnectionPool(fs::path file) : file_(std::move(file)), name_(file_.string()) {}

  // Throws SourceError naming the file.
  std::unique_ptr<MbtilesConnection> open() const {
    auto c = std::make_unique<MbtilesConnection>();
    const int rc = sqlite3_open_v2(read_only_uri(file_).c_str(), &c->db,
                                   SQLITE_OPEN_READONLY | SQLITE_OPEN_URI | SQLITE_OPEN_NOMUTEX, nullptr);
    if (rc != SQLITE_OK) throw SourceError(name_ + ": cannot open: " + error_text(c->db, rc));
    sqlite3_busy_timeout(c->db, kBusyTimeoutMs);
    const char* sql = "SELECT tile_data FROM tiles WHERE zoom_level = ?1 AND tile_column = ?2 AND tile_row = ?3";
    if (sqlite3_prepare_v2(c->db, sql, -1, &c->select_tile, nullptr) != SQLITE_OK)
      throw SourceError(name_ + ": not an MBTiles file: " + sqlite3_errmsg(c->db));
    return c;
  }

  std::unique_ptr<MbtilesConnection> take() {
    {
      std::lock_guard lock(mutex_);
      if (!idle_.empty()) {
        std::unique_ptr<MbtilesConnection> c = std::move(idle_.back());
        idle_.pop_back();
        return c;
      }
    }
    return open();
  }

  void give_back(std::unique_ptr<MbtilesConnection> c) {
    sqlite3_reset(c->select_tile);
    sqlite3_clear_bindings(c->select_tile);
    std::lock_guard lock(mutex_);
    if (idle_.size() < kMaxIdleConnections) idle_.push_back(std::move(c));
  }

  static std::string error_text(sqlite3* db, int rc) { return db ? sqlite3_errmsg(db) : sqlite3_errstr(rc); }

 private:
  fs::path file_;
  std::string name_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<MbtilesConnection>> idle_;
};

namespace {

// Whether the database has a table or view of that name. Throws SourceError when the file is
// not an SQLite database at all (the first query is where SQLite finds out).
bool has_table(sqlite3* db, const char* name, const std::string& where) {
  Statement s;
  if (sqlite3_prepare_v2(db, "SELECT 1 FROM sqlite_master WHERE name = ?1 AND type IN ('table', 'view')", -1, &s.stmt,
                         nullptr) != SQLITE_OK)
    throw SourceError(where + ": not an MBTiles file (not an SQLite database: " + sqlite3_errmsg(db) + ")");
  sqlite3_bind_text(s.stmt, 1, name, -1, SQLITE_STATIC);
  const int rc = sqlite3_step(s.stmt);
  if (rc != SQLITE_ROW && rc != SQLITE_DONE)
    throw SourceError(where + ": not an MBTiles file (not an SQLite database: " + sqlite3_errmsg(db) + ")");
  return rc == SQLITE_ROW;
}

void read_metadata_table(sqlite3* db, const std::string& where, TileMetadata& metadata) {
  Statement s;
  if (sqlite3_prepare_v2(db, "SELECT name, value FROM metadata", -1, &s.stmt, nullptr) != SQLITE_OK)
    throw SourceError(where + ": cannot read the metadata table: " + sqlite3_errmsg(db));
  int rc;
  while ((rc = sqlite3_step(s.stmt)) == SQLITE_ROW) {
    const auto* key = reinterpret_cast<const char*>(sqlite3_column_text(s.stmt, 0));
    const auto* value = reinterpret_cast<const char*>(sqlite3_column_text(s.stmt, 1));
    // Rows are TMS by the spec whatever a "scheme" row says (GDAL reads them so too): the key is
    // not ours to parse, nor a reason to refuse the file.
    if (key && value && std::string_view(key) != "scheme") metadata.set(key, value, where);
  }
  if (rc != SQLITE_DONE) throw SourceError(where + ": cannot read the metadata table: " + sqlite3_errmsg(db));
  metadata.check(where);
}

// The zoom levels present, for files whose metadata does not say (an index lookup, not a scan,
// with the spec's unique index on the tiles).
std::pair<int, int> zoom_range_of_tiles(sqlite3* db, const std::string& where) {
  Statement s;
  if (sqlite3_prepare_v2(db, "SELECT min(zoom_level), max(zoom_level) FROM tiles", -1, &s.stmt, nullptr) != SQLITE_OK ||
      sqlite3_step(s.stmt) != SQLITE_ROW)
    throw SourceError(where + ": cannot read the tiles table: " + sqlite3_errmsg(db));
  if (sqlite3_column_type(s.stmt, 0) == SQLITE_NULL) throw SourceError(where + ": the tiles table is empty");
  const sqlite3_int64 lo = sqlite3_column_int64(s.stmt, 0), hi = sqlite3_column_int64(s.stmt, 1);
  if (lo < 0 || hi > geo::kMaxTileZoom)
    throw SourceError(where + ": tiles with zoom levels " + std::to_string(lo) + ".." + std::to_string(hi) +
                      " (valid: 0.." + std::to_string(geo::kMaxTileZoom) + ")");
  return {static_cast<int>(lo), static_cast<int>(hi)};
}

}  // namespace

MbtilesTileSource::MbtilesTileSource(fs::path file) {
  info_.name = file.string();
  std::error_code ec;
  if (!fs::exists(file, ec)) throw SourceError(info_.name + ": no such file");
  if (fs::is_directory(file, ec)) throw SourceError(info_.name + ": a folder, not an MBTiles file");
  pool_ = std::make_unique<ConnectionPool>(file);

  // The first connection checks the file before preparing the tile query, for clear errors.
  auto c = std::make_unique<MbtilesConnection>();
  const int rc = sqlite3_open_v2(read_only_uri(file).c_str(), &c->db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr);
  if (rc != SQLITE_OK) throw SourceError(info_.name + ": cannot open: " + ConnectionPool::error_text(c->db, rc));
  sqlite3_busy_timeout(c->db, kBusyTimeoutMs);
  if (!has_table(c->db, "tiles", info_.name)) throw SourceError(info_.name + ": not an MBTiles file (no tiles table)");

  TileMetadata metadata;
  if (has_table(c->db, "metadata", info_.name)) read_metadata_table(c->db, info_.name, metadata);
  if (metadata.format == "pbf" || metadata.format == "mvt")
    throw SourceError(info_.name + ": holds vector tiles (format " + metadata.format + "), not raster tiles");
  if (!metadata.min_zoom || !metadata.max_zoom) {
    const auto [lo, hi] = zoom_range_of_tiles(c->db, info_.name);
    if (!metadata.min_zoom) metadata.min_zoom = lo;
    if (!metadata.max_zoom) metadata.max_zoom = hi;
    metadata.check(info_.name);
  }
  metadata.apply_to(info_);
  c.reset();
  pool_->give_back(pool_->open());
}

MbtilesTileSource::~MbtilesTileSource() = default;

EncodedTile MbtilesTileSource::fetch(const TileId& tile, StopToken stop) {
  EncodedTile result;
  const auto fail = [&](const std::string& message) {
    result.status = TileStatus::failed;
    result.error = info_.name + " " + geo::to_string(tile) + ": " + message;
    return result;
  };
  if (stop.stop_requested()) {
    result.status = TileStatus::cancelled;
    return result;
  }
  const std::optional<std::uint32_t> row = geo::tms_y(tile);
  if (!row) return fail("not a valid tile id");
  if (tile.zoom < info_.min_zoom || tile.zoom > info_.max_zoom) return result;  // no_data

  std::unique_ptr<MbtilesConnection> c;
  try {
    c = pool_->take();
  } catch (const SourceError& e) {
    return fail(e.what());
  }
  sqlite3_stmt* s = c->select_tile;
  sqlite3_bind_int(s, 1, tile.zoom);
  sqlite3_bind_int64(s, 2, tile.x);
  sqlite3_bind_int64(s, 3, *row);
  const int rc = sqlite3_step(s);
  if (rc == SQLITE_ROW) {
    const auto* data = static_cast<const unsigned char*>(sqlite3_column_blob(s, 0));
    const int size = sqlite3_column_bytes(s, 0);
    if (!data || size <= 0) {
      fail("empty tile data");
    } else if (size >= 2 && data[0] == 0x1f && data[1] == 0x8b) {
      fail("gzip-compressed tile data (a vector tile?), not a raster image");
    } else {
      result.status = TileStatus::ok;
      result.bytes.assign(data, data + size);
    }
  } else if (rc != SQLITE_DONE) {
    fail(std::string("SQLite error: ") + sqlite3_errmsg(c->db));
  }  // SQLITE_DONE: no such tile, no_data
  pool_->give_back(std::move(c));
  return result;
}

}  // namespace trailray::terrain
