// libFuzzer target for the small text and binary formats of the terrain layer that come from
// outside: the configuration file (TOML), URL templates, Cache-Control headers, and disk cache
// entries (a cache file may be cut short or damaged by a crash, a full disk or another program).
// The first byte picks the parser; each must answer or throw its documented error, never crash.
//   config   parse_terrain_config -> TerrainConfig or ConfigError
//   url      UrlTemplate -> ok (then url_for on a few tiles) or SourceError
//   header   parse_cache_control
//   cache    bytes written as a cache entry file, then DiskCache::read -> entry or nullopt (and
//            the damaged file removed)

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "terrain/loading/disk_cache.hpp"
#include "terrain/loading/http_client.hpp"
#include "terrain/sources/terrain_config.hpp"
#include "terrain/sources/url_template.hpp"

namespace {

using namespace trailray::terrain;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz: contract violated: %s\n", what);
    std::abort();
  }
}

const std::filesystem::path& cache_folder() {
  static const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("trailray-fuzz-cache-" + std::to_string(::getpid()));
  return folder;
}

void fuzz_cache_entry(std::string_view bytes) {
  static DiskCache cache("fuzz", DiskCacheOptions{cache_folder(), std::uint64_t{1} << 30});
  const TileId tile{3, 1, 2};
  const auto path = cache.entry_path(tile);
  std::filesystem::create_directories(path.parent_path());
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  const auto entry = cache.read(tile);
  if (!entry) {
    check(!std::filesystem::exists(path), "a damaged entry was left in the cache");
    return;
  }
  check(!entry->info.no_data || entry->payload.empty(), "a no-data entry with a payload");
  check(entry->payload.size() <= bytes.size(), "a payload longer than the file");
  cache.remove(tile);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 4) {
    case 0:
      try {
        const TerrainConfig c = parse_terrain_config(text, "fuzz.toml");
        check(c.network.max_parallel >= 1 && c.network.retries >= 0, "network settings out of range");
        check(c.network.timeout_s > 0.0 && c.network.connect_timeout_s > 0.0, "a non-positive timeout");
      } catch (const ConfigError& e) {
        check(std::string_view(e.what()).starts_with("fuzz.toml"), "a config error not naming the file");
      }
      break;
    case 1:
      try {
        const UrlTemplate t(text);
        for (const TileId& id : {TileId{0, 0, 0}, TileId{12, 2137, 1445}, TileId{30, (1u << 30) - 1, 0}})
          (void)t.url_for(id);
      } catch (const SourceError&) {
      }
      break;
    case 2:
      (void)parse_cache_control(text);
      break;
    default:
      fuzz_cache_entry(text);
  }
  return 0;
}
