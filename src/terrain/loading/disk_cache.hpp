#pragma once
// The disk cache behind HTTP tile sources: one file per tile under
//   <folder>/<namespace>/<z>/<x>/<y>.tile
// where <folder> defaults to $XDG_CACHE_HOME/trailray/tiles (else ~/.cache/trailray/tiles) and
// the namespace, one per source, is a readable slug of the URL template plus a short hash of it
// (the unexpanded template: a new API key does not throw the cache away, and the key never
// reaches a path).
//
// Entry file (little-endian), 44 bytes + strings + payload:
//    0  magic "TRTC"             4  u16 format version (1)     6  u16 flags (bit 0: no data)
//    8  u32 payload length       12  u32 CRC32 of the payload (zlib)
//   16  i64 fetch time          24  i64 expiry time (Unix seconds)
//   32  u16 lengths of the ETag, the Last-Modified date and the content type, u16 0
//   40  u32 CRC32 of bytes 0..39 and the three strings
//   44  ETag, Last-Modified, content type (no terminators), then the payload
// A "no data" entry remembers a 404 until it expires, so an empty ocean tile is not asked for
// on every run.
//
// Safety: writes go to a temporary file in the same folder, are fsync'ed and renamed over the
// entry, so a reader (another thread or another trailray process) sees the old file or the new
// one, never half of one. A read that finds a bad magic, a wrong length (a crash mid-write by an
// older version, a full disk) or a wrong CRC treats the entry as absent and removes it.
//
// Size: the total over the whole folder (every source) is kept under max_bytes, least recently
// used out first: a hit touches the file's mtime; the folder is scanned once when the cache is
// opened, a running total is kept, and when it passes the limit the folder is scanned again and
// the oldest entries go until it is under 90 % of it (headroom, so that eviction is not run on
// every write). Another process's writes are only seen at those scans; files vanishing under a
// scan (the other process evicting too) are fine. Sizes are the files' lengths, not the disk
// blocks they occupy.

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "terrain/tile.hpp"

namespace trailray::terrain {

struct CacheEntryInfo {
  std::int64_t fetched_at = 0;  // Unix seconds
  std::int64_t expires_at = 0;  // fresh while now < expires_at
  std::string etag, last_modified, content_type;
  bool no_data = false;  // the server said it has nothing here (HTTP 404 or 204)

  bool fresh(std::int64_t now) const { return now < expires_at; }
};

struct CacheEntry {
  CacheEntryInfo info;
  std::vector<unsigned char> payload;  // empty for a no-data entry
};

struct DiskCacheOptions {
  std::filesystem::path folder;                      // empty: DiskCache::default_folder()
  std::uint64_t max_bytes = std::uint64_t{1} << 30;  // over every source in the folder
};

class DiskCache {
 public:
  static constexpr std::size_t kFixedHeaderBytes = 44;
  // ETags, dates and content types longer than this are not stored (the entry is kept without).
  static constexpr std::size_t kMaxStringBytes = 1024;
  // Larger payloads are not cached (no tile is anywhere near this).
  static constexpr std::uint32_t kMaxPayloadBytes = 256u << 20;

  // $XDG_CACHE_HOME/trailray/tiles when XDG_CACHE_HOME is an absolute path, else
  // $HOME/.cache/trailray/tiles (HOME from the password database when unset). Throws
  // SourceError when there is no home folder at all.
  static std::filesystem::path default_folder();

  // "<slug>-<12 hex digits>": the slug names the host and path for a human looking at the
  // folder; the hash (FNV-1a, stable across runs and machines) tells apart templates with the
  // same slug.
  static std::string namespace_for(std::string_view url_template);

  // The cache of one source (source_key: its URL template, unexpanded). Creates the folder and
  // scans it once for the running total (removing temporary files left over by a crash more
  // than an hour ago). Throws SourceError when the folder cannot be created.
  DiskCache(std::string_view source_key, DiskCacheOptions options = {});
  DiskCache(const DiskCache&) = delete;
  DiskCache& operator=(const DiskCache&) = delete;

  // The entry, or nullopt when there is none or it was damaged (then it is also removed).
  // A hit marks the entry as just used (LRU).
  std::optional<CacheEntry> read(const TileId& tile);

  // Stores an entry atomically (see above); may evict others. Returns an error message (naming
  // the file and the reason) when it could not be written; the cache is unchanged then.
  std::string write(const TileId& tile, const CacheEntryInfo& info, std::span<const unsigned char> payload);

  void remove(const TileId& tile);

  std::filesystem::path entry_path(const TileId& tile) const;
  const std::filesystem::path& folder() const { return folder_; }
  const std::filesystem::path& namespace_folder() const { return namespace_folder_; }
  std::uint64_t max_bytes() const { return max_bytes_; }
  // The running total over the whole folder, as this cache knows it.
  std::uint64_t total_bytes() const;
  // Entries found damaged and removed since the cache was opened.
  std::uint64_t damaged_entries_removed() const;

  // Bytes an entry takes on top of its payload (the header and the strings).
  static std::size_t overhead_bytes(const CacheEntryInfo& info);

 private:
  struct ScannedEntry {
    std::filesystem::file_time_type last_used;
    std::uint64_t size = 0;
    std::filesystem::path path;
  };
  std::vector<ScannedEntry> scan_folder(bool remove_stale_temporaries) const;
  void add_to_total(std::int64_t delta);
  void evict_if_over_limit();

  std::filesystem::path folder_, namespace_folder_;
  std::uint64_t max_bytes_ = 0;

  mutable std::mutex total_mutex_;
  std::uint64_t total_bytes_ = 0;
  std::uint64_t damaged_removed_ = 0;
  std::mutex eviction_mutex_;  // one eviction scan at a time; others skip theirs
};

}  // namespace trailray::terrain
