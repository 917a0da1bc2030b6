#include "terrain/loading/disk_cache.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "terrain/local_tile_server.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {
namespace {

namespace fs = std::filesystem;
using test::http::files_containing;
using test::http::TempFolder;

constexpr std::string_view kTemplate = "https://tiles.example.org/terrain/{z}/{x}/{y}.png?key=${KEY}";

std::vector<unsigned char> bytes_of(std::size_t size, unsigned char fill) {
  return std::vector<unsigned char>(size, fill);
}

CacheEntryInfo info_expiring_in(std::int64_t seconds) {
  CacheEntryInfo info;
  info.fetched_at = 1'700'000'000;
  info.expires_at = info.fetched_at + seconds;
  return info;
}

std::vector<unsigned char> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

void write_file(const fs::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

DiskCacheOptions in(const TempFolder& folder, std::uint64_t max_bytes = std::uint64_t{1} << 30) {
  DiskCacheOptions options;
  options.folder = folder.path();
  options.max_bytes = max_bytes;
  return options;
}

TEST(DiskCache, RoundTripsPayloadAndHeader) {
  TempFolder folder;
  DiskCache cache(kTemplate, in(folder));
  CacheEntryInfo info = info_expiring_in(3600);
  info.etag = "\"abc-123\"";
  info.last_modified = "Wed, 21 Oct 2015 07:28:00 GMT";
  info.content_type = "image/png";
  const std::vector<unsigned char> payload = test::http::make_png(256, 256, 7);
  const TileId tile{12, 2137, 1445};
  ASSERT_EQ(cache.write(tile, info, payload), "");

  const std::optional<CacheEntry> entry = cache.read(tile);
  ASSERT_TRUE(entry);
  EXPECT_EQ(entry->payload, payload);
  EXPECT_EQ(entry->info.etag, info.etag);
  EXPECT_EQ(entry->info.last_modified, info.last_modified);
  EXPECT_EQ(entry->info.content_type, "image/png");
  EXPECT_EQ(entry->info.fetched_at, info.fetched_at);
  EXPECT_EQ(entry->info.expires_at, info.expires_at);
  EXPECT_FALSE(entry->info.no_data);
  EXPECT_TRUE(entry->info.fresh(info.fetched_at + 3599));
  EXPECT_FALSE(entry->info.fresh(info.fetched_at + 3600));

  EXPECT_EQ(cache.entry_path(tile), cache.namespace_folder() / "12" / "2137" / "1445.tile");
  // Bytes per cached tile: the 44-byte header, the three strings, the payload; nothing else.
  EXPECT_EQ(DiskCache::overhead_bytes(info), 44u + 9 + 29 + 9);
  EXPECT_EQ(fs::file_size(cache.entry_path(tile)), DiskCache::overhead_bytes(info) + payload.size());
  EXPECT_EQ(cache.total_bytes(), fs::file_size(cache.entry_path(tile)));
  EXPECT_FALSE(cache.read(TileId{12, 2137, 1446}));
}

TEST(DiskCache, RemembersNoDataAndOverwrites) {
  TempFolder folder;
  DiskCache cache(kTemplate, in(folder));
  const TileId tile{3, 1, 2};
  CacheEntryInfo none = info_expiring_in(60);
  none.no_data = true;
  ASSERT_EQ(cache.write(tile, none, {}), "");
  std::optional<CacheEntry> entry = cache.read(tile);
  ASSERT_TRUE(entry);
  EXPECT_TRUE(entry->info.no_data);
  EXPECT_TRUE(entry->payload.empty());

  ASSERT_EQ(cache.write(tile, info_expiring_in(60), bytes_of(500, 9)), "");
  entry = cache.read(tile);
  ASSERT_TRUE(entry);
  EXPECT_FALSE(entry->info.no_data);
  EXPECT_EQ(entry->payload, bytes_of(500, 9));
  EXPECT_EQ(cache.total_bytes(), 44u + 500);  // the overwritten entry is no longer counted

  cache.remove(tile);
  EXPECT_FALSE(cache.read(tile));
  EXPECT_EQ(cache.total_bytes(), 0u);
}

TEST(DiskCache, NamespaceIsReadableStableAndPerTemplate) {
  const std::string ns = DiskCache::namespace_for("https://{s}.tile.opentopomap.org/{z}/{x}/{y}.png");
  EXPECT_TRUE(ns.starts_with("tile-opentopomap-org-png-")) << ns;
  EXPECT_EQ(ns.size(), std::string("tile-opentopomap-org-png-").size() + 12);
  EXPECT_EQ(ns, DiskCache::namespace_for("https://{s}.tile.opentopomap.org/{z}/{x}/{y}.png"));
  EXPECT_NE(ns, DiskCache::namespace_for("https://{s}.tile.opentopomap.org/{z}/{x}/{-y}.png"));
  // FNV-1a of the template: the same on every run and machine (a std::hash would not be).
  // (Python: FNV-1a 64 of b"http://a/{z}/{x}/{y}" is 0x01817811367a0208; the first 12 hex digits.)
  EXPECT_EQ(DiskCache::namespace_for("http://a/{z}/{x}/{y}"), "a-01817811367a");
  // The query (where keys usually are) and ${VAR} names stay out of the folder name.
  const std::string keyed = DiskCache::namespace_for(kTemplate);
  EXPECT_EQ(keyed.find("key"), std::string::npos) << keyed;
  EXPECT_TRUE(keyed.starts_with("tiles-example-org-terrain-png-")) << keyed;
}

TEST(DiskCache, DefaultFolderFollowsXdgThenHome) {
  const char* saved_xdg = std::getenv("XDG_CACHE_HOME");
  const std::string xdg = saved_xdg ? saved_xdg : "";
  ::setenv("XDG_CACHE_HOME", "/var/tmp/xdg-cache", 1);
  EXPECT_EQ(DiskCache::default_folder(), fs::path("/var/tmp/xdg-cache/trailray/tiles"));
  ::setenv("XDG_CACHE_HOME", "relative/cache", 1);  // invalid by the XDG spec: ignored
  const char* home = std::getenv("HOME");
  if (home != nullptr) {
    EXPECT_EQ(DiskCache::default_folder(), fs::path(home) / ".cache/trailray/tiles");
  }
  ::unsetenv("XDG_CACHE_HOME");
  if (home != nullptr) {
    EXPECT_EQ(DiskCache::default_folder(), fs::path(home) / ".cache/trailray/tiles");
  }
  if (saved_xdg != nullptr) ::setenv("XDG_CACHE_HOME", xdg.c_str(), 1);
}

// Each way an entry can be damaged is read as absent, and the file removed.
TEST(DiskCache, DamagedEntriesAreRemoved) {
  TempFolder folder;
  DiskCache cache(kTemplate, in(folder));
  const std::vector<unsigned char> payload = bytes_of(1000, 0x5a);
  CacheEntryInfo info = info_expiring_in(3600);
  info.etag = "\"e\"";

  struct Damage {
    const char* what;
    void (*apply)(std::vector<unsigned char>&);
  };
  const Damage damages[] = {
      {"cut short (crash mid-write)", [](std::vector<unsigned char>& b) { b.resize(b.size() / 2); }},
      {"cut inside the header", [](std::vector<unsigned char>& b) { b.resize(20); }},
      {"empty file", [](std::vector<unsigned char>& b) { b.clear(); }},
      {"bad magic", [](std::vector<unsigned char>& b) { b[0] = 'X'; }},
      {"payload byte flipped", [](std::vector<unsigned char>& b) { b[b.size() - 10] ^= 0x01; }},
      {"expiry flipped", [](std::vector<unsigned char>& b) { b[24] ^= 0x40; }},
      {"etag flipped", [](std::vector<unsigned char>& b) { b[45] ^= 0x01; }},
      {"unknown version", [](std::vector<unsigned char>& b) { b[4] = 99; }},
      {"trailing bytes", [](std::vector<unsigned char>& b) { b.push_back(0); }},
  };
  std::uint64_t removed = 0;
  for (const Damage& damage : damages) {
    SCOPED_TRACE(damage.what);
    const TileId tile{10, 1, 1};
    ASSERT_EQ(cache.write(tile, info, payload), "");
    ASSERT_TRUE(cache.read(tile));
    std::vector<unsigned char> file = read_file(cache.entry_path(tile));
    damage.apply(file);
    write_file(cache.entry_path(tile), file);
    EXPECT_FALSE(cache.read(tile));
    EXPECT_FALSE(fs::exists(cache.entry_path(tile)));
    EXPECT_EQ(cache.damaged_entries_removed(), ++removed);
  }
}

TEST(DiskCache, WritesLeaveNoTemporaryFiles) {
  TempFolder folder;
  DiskCache cache(kTemplate, in(folder));
  for (std::uint32_t i = 0; i < 20; ++i) {
    ASSERT_EQ(cache.write(TileId{8, i, i % 3}, info_expiring_in(10), bytes_of(100 + i, 1)), "");
  }
  EXPECT_EQ(files_containing(folder.path(), ".tile").size(), 20u);
  EXPECT_TRUE(files_containing(folder.path(), ".tmp-").empty());
}

TEST(DiskCache, OpeningCountsExistingEntriesAndClearsOldTemporaries) {
  TempFolder folder;
  fs::path stale_temporary, recent_temporary;
  {
    DiskCache first(kTemplate, in(folder));
    ASSERT_EQ(first.write(TileId{5, 1, 1}, info_expiring_in(10), bytes_of(300, 1)), "");
    ASSERT_EQ(first.write(TileId{5, 1, 2}, info_expiring_in(10), bytes_of(700, 1)), "");
    stale_temporary = first.entry_path(TileId{5, 1, 3}).string() + ".tmp-1-1";
    recent_temporary = first.entry_path(TileId{5, 1, 4}).string() + ".tmp-2-2";
    write_file(stale_temporary, bytes_of(5000, 0));
    write_file(recent_temporary, bytes_of(5000, 0));
    fs::last_write_time(stale_temporary, fs::file_time_type::clock::now() - std::chrono::hours(2));
  }
  // Another source's entries in the same folder count towards the same limit.
  DiskCache other("https://other.example.org/{z}/{x}/{y}.png", in(folder));
  EXPECT_EQ(other.total_bytes(), 44u + 300 + 44 + 700);
  EXPECT_FALSE(fs::exists(stale_temporary));  // a crashed writer's leftover
  EXPECT_TRUE(fs::exists(recent_temporary));  // may be another process writing right now
}

TEST(DiskCache, EvictsLeastRecentlyUsedOverTheLimit) {
  TempFolder folder;
  constexpr std::size_t kEntry = 44 + 1000;
  DiskCache cache(kTemplate, in(folder, kEntry * 7 / 2));  // room for 3.5 entries
  const TileId a{9, 1, 1}, b{9, 1, 2}, c{9, 1, 3}, d{9, 1, 4};
  for (const TileId& t : {a, b, c}) ASSERT_EQ(cache.write(t, info_expiring_in(10), bytes_of(1000, 3)), "");
  EXPECT_EQ(cache.total_bytes(), 3 * kEntry);
  // Written long ago in the order a, b, c (mtime resolution is too coarse to rely on the writes).
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(cache.entry_path(a), now - std::chrono::minutes(30));
  fs::last_write_time(cache.entry_path(b), now - std::chrono::minutes(20));
  fs::last_write_time(cache.entry_path(c), now - std::chrono::minutes(10));
  ASSERT_TRUE(cache.read(a));  // a is used: now the most recent

  ASSERT_EQ(cache.write(d, info_expiring_in(10), bytes_of(1000, 4)), "");
  EXPECT_FALSE(fs::exists(cache.entry_path(b)));  // the least recently used
  EXPECT_TRUE(fs::exists(cache.entry_path(a)));
  EXPECT_TRUE(fs::exists(cache.entry_path(c)));
  EXPECT_TRUE(fs::exists(cache.entry_path(d)));
  EXPECT_EQ(cache.total_bytes(), 3 * kEntry);
  EXPECT_LE(cache.total_bytes(), cache.max_bytes());
}

TEST(DiskCache, EvictionToleratesFilesVanishing) {
  TempFolder folder;
  constexpr std::size_t kEntry = 44 + 1000;
  DiskCache cache(kTemplate, in(folder, kEntry * 5));
  for (std::uint32_t i = 0; i < 5; ++i)
    ASSERT_EQ(cache.write(TileId{9, 2, i}, info_expiring_in(10), bytes_of(1000, 1)), "");
  // Another process evicts behind this one's back: the running total is now too high.
  for (std::uint32_t i = 0; i < 4; ++i) fs::remove(cache.entry_path(TileId{9, 2, i}));
  ASSERT_EQ(cache.write(TileId{9, 3, 0}, info_expiring_in(10), bytes_of(1000, 1)), "");
  // Over the limit as far as the total knows: the rescan finds what is really there.
  EXPECT_EQ(cache.total_bytes(), 2 * kEntry);
  EXPECT_TRUE(cache.read(TileId{9, 2, 4}));
  EXPECT_TRUE(cache.read(TileId{9, 3, 0}));
}

TEST(DiskCache, ConcurrentWritersAndReadersNeverSeeHalfAnEntry) {
  TempFolder folder;
  DiskCache writer_cache(kTemplate, in(folder));
  DiskCache reader_cache(kTemplate, in(folder));  // as a second process would
  const TileId tile{11, 5, 5};
  std::atomic<bool> done{false};
  std::atomic<int> reads_ok{0}, bad_reads{0};
  std::vector<std::thread> threads;
  for (int w = 0; w < 4; ++w) {
    threads.emplace_back([&, w] {
      for (int i = 0; i < 50; ++i) {
        const auto fill = static_cast<unsigned char>(w * 50 + i);
        EXPECT_EQ(
            writer_cache.write(tile, info_expiring_in(10), bytes_of(20000 + static_cast<std::size_t>(fill), fill)), "");
      }
    });
  }
  for (int r = 0; r < 4; ++r) {
    threads.emplace_back([&] {
      while (!done) {
        if (std::optional<CacheEntry> entry = reader_cache.read(tile)) {
          const auto fill = entry->payload.empty() ? 0 : entry->payload.front();
          const bool consistent =
              entry->payload.size() == 20000u + fill &&
              std::all_of(entry->payload.begin(), entry->payload.end(), [fill](unsigned char v) { return v == fill; });
          (consistent ? reads_ok : bad_reads)++;
        }
      }
    });
  }
  for (int i = 0; i < 4; ++i) threads[static_cast<std::size_t>(i)].join();
  done = true;
  for (std::size_t i = 4; i < threads.size(); ++i) threads[i].join();
  EXPECT_EQ(bad_reads, 0);
  EXPECT_GT(reads_ok, 0);
  EXPECT_EQ(reader_cache.damaged_entries_removed(), 0u);
  EXPECT_TRUE(files_containing(folder.path(), ".tmp-").empty());
}

TEST(DiskCache, UnwritableFolderIsAnErrorNotACrash) {
  TempFolder folder;
  DiskCache cache(kTemplate, in(folder));
  // A file where the zoom folder should be: the entry cannot be written.
  write_file(cache.namespace_folder() / "4", bytes_of(1, 0));
  const std::string error = cache.write(TileId{4, 1, 1}, info_expiring_in(10), bytes_of(10, 1));
  EXPECT_NE(error.find("tile cache " + cache.entry_path(TileId{4, 1, 1}).string()), std::string::npos) << error;
  EXPECT_FALSE(cache.read(TileId{4, 1, 1}));

  TempFolder other;
  write_file(other.path() / "blocked", bytes_of(1, 0));
  DiskCacheOptions options;
  options.folder = other.path() / "blocked" / "tiles";
  EXPECT_THROW({ DiskCache blocked(kTemplate, options); }, SourceError);
}

}  // namespace
}  // namespace trailray::terrain
