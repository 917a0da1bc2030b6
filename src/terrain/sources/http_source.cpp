#include "terrain/sources/http_source.hpp"

#include <cctype>

namespace trailray::terrain {
namespace {

std::int64_t unix_now() {
  return std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::int64_t steady_now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// "png" for ".../{y}.png?key=...", "" when the template has no recognisable extension.
std::string format_from_template(std::string_view text) {
  text = text.substr(0, text.find('?'));
  const std::size_t dot = text.rfind('.'), slash = text.rfind('/');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return {};
  std::string extension;
  for (char c : text.substr(dot + 1))
    extension.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  if (extension == "jpeg") extension = "jpg";
  if (extension == "tiff") extension = "tif";
  for (const char* known : {"png", "jpg", "webp", "tif"}) {
    if (extension == known) return extension;
  }
  return {};
}

EncodedTile with_status(TileStatus status) {
  EncodedTile tile;
  tile.status = status;
  return tile;
}

EncodedTile ok_tile(std::vector<unsigned char> bytes) {
  EncodedTile tile;
  tile.status = TileStatus::ok;
  tile.bytes = std::move(bytes);
  return tile;
}

EncodedTile failed_tile(std::string error) {
  EncodedTile tile;
  tile.status = TileStatus::failed;
  tile.error = std::move(error);
  return tile;
}

std::string after_retries(int retries) {
  if (retries == 0) return {};
  return " after " + std::to_string(retries) + (retries == 1 ? " retry" : " retries");
}

}  // namespace

HttpTileSource::HttpTileSource(std::string_view url_template, HttpSourceOptions options)
    : template_(url_template, options.subdomains),
      options_(std::move(options)),
      info_(options_.info),
      client_(options_.client) {
  info_.name = template_.display();
  if (info_.format.empty()) info_.format = format_from_template(template_.display());
  if (options_.use_disk_cache) {
    try {
      cache_ = std::make_unique<DiskCache>(template_.display(), options_.cache);
    } catch (const SourceError& e) {
      warn_once(warned_cache_, template_.display() + ": tiles are not cached (" + e.what() + ")");
    }
  }
}

EncodedTile HttpTileSource::from_entry(const CacheEntry& entry) const {
  if (entry.info.no_data) return with_status(TileStatus::no_data);
  return ok_tile(entry.payload);
}

EncodedTile HttpTileSource::failed(const TileId& tile, const std::string& what) const {
  return failed_tile(template_.display() + " " + to_string(tile) + ": " + what);
}

void HttpTileSource::warn_once(std::atomic<bool>& flag, const std::string& message) const {
  if (flag.exchange(true) || !options_.warn) return;
  options_.warn(message);
}

std::int64_t HttpTileSource::expiry_of(const HttpResponse& response, std::int64_t now,
                                       std::chrono::seconds fallback) const {
  if (response.cache_control.no_cache) return now;  // stored, but stale at once: revalidated before each use
  if (response.cache_control.max_age_s) return now + *response.cache_control.max_age_s;
  if (response.expires) {
    // Expires is the server's clock: its distance from the server's Date is the lifetime.
    return response.date ? now + (*response.expires - *response.date) : *response.expires;
  }
  return now + fallback.count();
}

void HttpTileSource::store(const TileId& tile, const CacheEntryInfo& info, std::span<const unsigned char> payload) {
  if (!cache_) return;
  const std::string error = cache_->write(tile, info, payload);
  if (!error.empty()) {
    // The tile itself is fine: it is served, just not kept.
    warn_once(warned_cache_, template_.display() + ": tiles are not cached (" + error + ")");
  }
}

EncodedTile HttpTileSource::fetch(const TileId& tile, StopToken stop) {
  if (!is_valid(tile)) return failed(tile, "not a valid tile id");
  if (tile.zoom < info_.min_zoom || tile.zoom > info_.max_zoom) return with_status(TileStatus::no_data);
  if (stop.stop_requested()) return with_status(TileStatus::cancelled);

  std::optional<CacheEntry> cached = cache_ ? cache_->read(tile) : std::nullopt;
  if (options_.offline) return cached ? from_entry(*cached) : with_status(TileStatus::no_data);
  std::int64_t now = unix_now();
  if (cached && cached->info.fresh(now)) return from_entry(*cached);

  ExpandedText url = template_.url_for(tile);
  if (!url.error.empty()) return failed_tile(std::move(url.error));
  if (steady_now_ms() < unreachable_until_ms_.load()) {
    if (cached) return from_entry(*cached);
    std::lock_guard lock(unreachable_mutex_);
    return failed(tile, "server unreachable (" + unreachable_reason_ + "), not asked again for a while");
  }
  HttpRequest request;
  request.url = std::move(url.text);
  request.secrets = std::move(url.secrets);
  const bool revalidating = cached && !cached->info.no_data;
  if (revalidating) {
    request.if_none_match = cached->info.etag;
    request.if_modified_since = cached->info.last_modified;
  }
  HttpResponse response = client_.get(request, stop);
  now = unix_now();
  if (response.cancelled) return with_status(TileStatus::cancelled);

  if (response.status == 0) {
    if (response.network_error) {
      const std::int64_t pause_ms = std::chrono::milliseconds(options_.retry_unreachable_after).count();
      if (pause_ms > 0) {
        std::lock_guard lock(unreachable_mutex_);
        unreachable_reason_ = response.error;
        unreachable_until_ms_ = steady_now_ms() + pause_ms;
      }
      warn_once(warned_unreachable_, template_.display() + ": server unreachable (" + response.error +
                                         "); using cached tiles where there are any");
      if (cached) return from_entry(*cached);
    }
    return failed(tile, response.error + after_retries(response.retries));
  }
  unreachable_until_ms_ = 0;

  const int status = response.status;
  if (status == 304) {
    if (!revalidating) return failed(tile, "HTTP 304 to a request that was not conditional");
    CacheEntryInfo info = cached->info;
    info.fetched_at = now;
    info.expires_at = expiry_of(response, now, options_.default_max_age);
    if (!response.etag.empty()) info.etag = response.etag;
    if (!response.last_modified.empty()) info.last_modified = response.last_modified;
    if (response.cache_control.no_store) {
      cache_->remove(tile);
    } else {
      store(tile, info, cached->payload);
    }
    return from_entry(*cached);
  }
  if (status == 404 || status == 204 || (status == 200 && response.body.empty())) {
    if (response.cache_control.no_store) {
      if (cache_) cache_->remove(tile);
    } else {
      CacheEntryInfo info;
      info.fetched_at = now;
      info.expires_at = expiry_of(response, now, options_.default_no_data_max_age);
      info.no_data = true;
      store(tile, info, {});
    }
    return with_status(TileStatus::no_data);
  }
  if (status == 200) {
    if (options_.validate) {
      if (std::optional<std::string> problem = options_.validate(response.body)) {
        return failed(tile, "not a valid tile: " + *problem);
      }
    }
    if (response.cache_control.no_store) {
      if (cache_) cache_->remove(tile);  // an older copy must not be served either
    } else {
      CacheEntryInfo info;
      info.fetched_at = now;
      info.expires_at = expiry_of(response, now, options_.default_max_age);
      info.etag = response.etag;
      info.last_modified = response.last_modified;
      info.content_type = response.content_type;
      store(tile, info, response.body);
    }
    return ok_tile(std::move(response.body));
  }
  if ((status == 429 || status >= 500) && cached) return from_entry(*cached);  // stale beats nothing
  return failed(tile, "HTTP " + std::to_string(status) + after_retries(response.retries));
}

}  // namespace trailray::terrain
