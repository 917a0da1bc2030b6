#include "terrain/writers/mbtiles_writer.hpp"

#include <sqlite3.h>

#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {
namespace fs = std::filesystem;

namespace {

struct Database {
  sqlite3* db = nullptr;
  ~Database() { sqlite3_close(db); }
};

struct Statement {
  sqlite3_stmt* stmt = nullptr;
  Statement() = default;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  ~Statement() { finalize(); }
  void finalize() {
    sqlite3_finalize(stmt);
    stmt = nullptr;
  }
};

// A table name safe to put into SQL: letters, digits and underscores only.
std::string checked_table(std::string_view table) {
  if (table.empty()) throw SourceError("an empty MBTiles table name");
  for (char c : table)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
      throw SourceError("MBTiles table name '" + std::string(table) + "' is not letters, digits and _");
  return std::string(table);
}

void open_read_only(const fs::path& file, Database& d) {
  // sqlite3_open_v2 without SQLITE_OPEN_URI takes the path as it is: no percent-escaping needed.
  const int rc = sqlite3_open_v2(file.c_str(), &d.db, SQLITE_OPEN_READONLY, nullptr);
  if (rc != SQLITE_OK)
    throw SourceError(file.string() + ": cannot open: " + (d.db ? sqlite3_errmsg(d.db) : sqlite3_errstr(rc)));
}

bool has_table(sqlite3* db, std::string_view table) {
  Statement s;
  if (sqlite3_prepare_v2(db, "SELECT 1 FROM sqlite_master WHERE type IN ('table', 'view') AND name = ?1", -1, &s.stmt,
                         nullptr) != SQLITE_OK)
    return false;
  sqlite3_bind_text(s.stmt, 1, table.data(), static_cast<int>(table.size()), SQLITE_TRANSIENT);
  return sqlite3_step(s.stmt) == SQLITE_ROW;
}

}  // namespace

struct MbtilesWriter::Impl {
  fs::path file;
  Database d;
  Statement metadata, tile;
  std::map<std::string, Statement> extras;

  [[noreturn]] void fail(const std::string& what) const {
    throw SourceError(file.string() + ": " + what + ": " + sqlite3_errmsg(d.db));
  }
  void exec(const std::string& sql) const {
    if (sqlite3_exec(d.db, sql.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) fail("cannot write");
  }
  void step(sqlite3_stmt* s) const {
    if (sqlite3_step(s) != SQLITE_DONE) fail("cannot write");
    sqlite3_reset(s);
    sqlite3_clear_bindings(s);
  }
};

MbtilesWriter::MbtilesWriter(const fs::path& file) : impl_(std::make_unique<Impl>()) {
  impl_->file = file;
  if (fs::exists(file)) throw SourceError(file.string() + ": exists already (an MBTiles file is written new)");
  const int rc = sqlite3_open_v2(file.c_str(), &impl_->d.db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  if (rc != SQLITE_OK)
    throw SourceError(file.string() + ": cannot create: " +
                      (impl_->d.db ? sqlite3_errmsg(impl_->d.db) : sqlite3_errstr(rc)));
  // One transaction, no journal file beside it: the file is a temporary until it is renamed.
  impl_->exec("PRAGMA journal_mode = OFF; PRAGMA synchronous = OFF; BEGIN;"
              "CREATE TABLE metadata (name TEXT PRIMARY KEY, value TEXT);"
              "CREATE TABLE tiles (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_data BLOB,"
              " PRIMARY KEY (zoom_level, tile_column, tile_row));");
  if (sqlite3_prepare_v2(impl_->d.db, "INSERT OR REPLACE INTO metadata VALUES (?1, ?2)", -1, &impl_->metadata.stmt,
                         nullptr) != SQLITE_OK ||
      sqlite3_prepare_v2(impl_->d.db, "INSERT OR REPLACE INTO tiles VALUES (?1, ?2, ?3, ?4)", -1, &impl_->tile.stmt,
                         nullptr) != SQLITE_OK)
    impl_->fail("cannot prepare");
}

MbtilesWriter::~MbtilesWriter() = default;

void MbtilesWriter::put_metadata(std::string_view name, std::string_view value) {
  sqlite3_bind_text(impl_->metadata.stmt, 1, name.data(), static_cast<int>(name.size()), SQLITE_TRANSIENT);
  sqlite3_bind_text(impl_->metadata.stmt, 2, value.data(), static_cast<int>(value.size()), SQLITE_TRANSIENT);
  impl_->step(impl_->metadata.stmt);
}

void MbtilesWriter::put_tile(const TileId& tile, std::span<const unsigned char> bytes) {
  const std::int64_t tms_row = (std::int64_t{1} << tile.zoom) - 1 - tile.y;
  sqlite3_bind_int(impl_->tile.stmt, 1, tile.zoom);
  sqlite3_bind_int64(impl_->tile.stmt, 2, tile.x);
  sqlite3_bind_int64(impl_->tile.stmt, 3, tms_row);
  sqlite3_bind_blob64(impl_->tile.stmt, 4, bytes.data(), bytes.size(), SQLITE_TRANSIENT);
  impl_->step(impl_->tile.stmt);
}

void MbtilesWriter::put_extra(std::string_view table, std::string_view key, std::span<const unsigned char> bytes) {
  const std::string name = checked_table(table);
  auto it = impl_->extras.find(name);
  if (it == impl_->extras.end()) {
    impl_->exec("CREATE TABLE " + name + " (key TEXT PRIMARY KEY, data BLOB);");
    it = impl_->extras.try_emplace(name).first;
    if (sqlite3_prepare_v2(impl_->d.db, ("INSERT OR REPLACE INTO " + name + " VALUES (?1, ?2)").c_str(), -1,
                           &it->second.stmt, nullptr) != SQLITE_OK)
      impl_->fail("cannot prepare");
  }
  sqlite3_bind_text(it->second.stmt, 1, key.data(), static_cast<int>(key.size()), SQLITE_TRANSIENT);
  sqlite3_bind_blob64(it->second.stmt, 2, bytes.data(), bytes.size(), SQLITE_TRANSIENT);
  impl_->step(it->second.stmt);
}

void MbtilesWriter::finish() {
  impl_->exec("COMMIT;");
  impl_->metadata.finalize();
  impl_->tile.finalize();
  impl_->extras.clear();
  if (sqlite3_close(impl_->d.db) != SQLITE_OK) impl_->fail("cannot close");
  impl_->d.db = nullptr;
}

std::map<std::string, std::string> read_mbtiles_metadata(const fs::path& file) {
  Database d;
  open_read_only(file, d);
  std::map<std::string, std::string> out;
  if (!has_table(d.db, "metadata")) return out;
  Statement s;
  if (sqlite3_prepare_v2(d.db, "SELECT name, value FROM metadata", -1, &s.stmt, nullptr) != SQLITE_OK)
    throw SourceError(file.string() + ": cannot read the metadata: " + sqlite3_errmsg(d.db));
  while (sqlite3_step(s.stmt) == SQLITE_ROW) {
    const auto* name = reinterpret_cast<const char*>(sqlite3_column_text(s.stmt, 0));
    const auto* value = reinterpret_cast<const char*>(sqlite3_column_text(s.stmt, 1));
    if (name) out[name] = value ? value : "";
  }
  return out;
}

std::map<std::string, std::vector<unsigned char>> read_mbtiles_extra(const fs::path& file, std::string_view table) {
  const std::string name = checked_table(table);
  Database d;
  open_read_only(file, d);
  std::map<std::string, std::vector<unsigned char>> out;
  if (!has_table(d.db, name)) return out;
  Statement s;
  if (sqlite3_prepare_v2(d.db, ("SELECT key, data FROM " + name).c_str(), -1, &s.stmt, nullptr) != SQLITE_OK)
    throw SourceError(file.string() + ": cannot read " + name + ": " + sqlite3_errmsg(d.db));
  int rc;
  while ((rc = sqlite3_step(s.stmt)) == SQLITE_ROW) {
    const auto* key = reinterpret_cast<const char*>(sqlite3_column_text(s.stmt, 0));
    const auto* data = static_cast<const unsigned char*>(sqlite3_column_blob(s.stmt, 1));
    const int size = sqlite3_column_bytes(s.stmt, 1);
    if (key) out[key] = std::vector<unsigned char>(data, data + size);
  }
  if (rc != SQLITE_DONE) throw SourceError(file.string() + ": cannot read " + name + ": " + sqlite3_errmsg(d.db));
  return out;
}

}  // namespace trailray::terrain
