#pragma once
// Tiles from an http(s) URL template (url_template.hpp), through a disk cache (disk_cache.hpp).
//
//   fresh cache entry                -> served, no network
//   stale entry with ETag / date     -> conditional request; 304 refreshes the entry
//   200                              -> checked with `validate`; only valid bytes are stored
//                                       (not at all with Cache-Control: no-store)
//   404, 204, an empty 200           -> no data, remembered as a "no data" entry until it expires
//   other 4xx, invalid bytes         -> failed
//   5xx / 429 after the retries      -> the stale entry when there is one, else failed
//   server unreachable               -> the stale entry when there is one, else failed; ONE
//                                       warning for the source, and for retry_unreachable_after
//                                       no further connection attempts (each would wait for the
//                                       timeouts and retries again)
//   offline                          -> the cache only, stale or not; missing -> no data
//   cache folder not writable        -> fetched without caching (one warning)
//
// Freshness: Cache-Control max-age, else Expires (corrected by the server's Date for its
// clock), else default_max_age; no-cache stores the tile stale, so it is revalidated each time.
// Messages name the source by its template as written (${VAR} unexpanded), then the tile:
// "https://.../{z}/{x}/{y}.png?key=${KEY} 12/2137/1445: HTTP 503 after 3 retries".

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "terrain/loading/disk_cache.hpp"
#include "terrain/loading/http_client.hpp"
#include "terrain/loading/stop_token.hpp"
#include "terrain/sources/tile_source.hpp"
#include "terrain/sources/url_template.hpp"

namespace trailray::terrain {

struct HttpSourceOptions {
  std::string subdomains = "a,b,c";  // for {s}
  HttpClientOptions client;          // timeouts, retries, extra headers, the parallel-request limit

  bool use_disk_cache = true;
  DiskCacheOptions cache;  // folder (default: DiskCache::default_folder()) and size limit
  bool offline = false;    // never touch the network: the disk cache only

  // How long an answer stays fresh when the server says nothing (no Cache-Control max-age, no
  // Expires): a tile, and a "no data" answer (shorter: a 404 may also be a passing fault).
  std::chrono::seconds default_max_age = std::chrono::hours(24 * 7);
  std::chrono::seconds default_no_data_max_age = std::chrono::hours(24);
  std::chrono::seconds retry_unreachable_after{30};

  // An error message for bytes that are not a valid tile (the factory passes a decoder check);
  // nullopt when they are fine. Unset: every 200 body is accepted.
  std::function<std::optional<std::string>(std::span<const unsigned char>)> validate;
  // Where the source's warnings go (the server being unreachable, the cache not writable); each
  // kind is reported once per source. Unset: dropped.
  std::function<void(std::string)> warn;

  // Zoom range, bounds, encoding, format and attribution, when known from elsewhere (a
  // configuration file, TileJSON). `name` is replaced by the template's display form; an empty
  // `format` is guessed from the template's file extension.
  SourceInfo info;
};

class HttpTileSource : public EncodedTileSource {
 public:
  // Throws SourceError for a bad template. A cache folder that cannot be created is not fatal:
  // the source works without a disk cache, and says so through `warn`.
  explicit HttpTileSource(std::string_view url_template, HttpSourceOptions options = {});

  const SourceInfo& info() const override { return info_; }
  // Thread-safe; blocks on the disk and the network.
  EncodedTile fetch(const TileId& tile, StopToken stop) override;

  const UrlTemplate& url_template() const { return template_; }
  DiskCache* disk_cache() const { return cache_.get(); }

 private:
  EncodedTile from_entry(const CacheEntry& entry) const;
  EncodedTile failed(const TileId& tile, const std::string& what) const;
  std::int64_t expiry_of(const HttpResponse& response, std::int64_t now, std::chrono::seconds fallback) const;
  void store(const TileId& tile, const CacheEntryInfo& info, std::span<const unsigned char> payload);
  void warn_once(std::atomic<bool>& flag, const std::string& message) const;

  UrlTemplate template_;
  HttpSourceOptions options_;
  SourceInfo info_;
  HttpClient client_;
  std::unique_ptr<DiskCache> cache_;

  // Steady-clock milliseconds until which the server is taken as unreachable (0: reachable).
  std::atomic<std::int64_t> unreachable_until_ms_{0};
  mutable std::mutex unreachable_mutex_;
  std::string unreachable_reason_;
  mutable std::atomic<bool> warned_unreachable_{false}, warned_cache_{false};
};

}  // namespace trailray::terrain
