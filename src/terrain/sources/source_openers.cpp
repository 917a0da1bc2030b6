// open_height_source and open_imagery_source of the native program: every kind of source
// (source_factory.hpp). The browser's build has its own (source_openers_web.cpp).
#include <chrono>
#include <map>
#include <mutex>

#include "terrain/sources/directory_source.hpp"
#include "terrain/sources/encoded_sources.hpp"
#include "terrain/gdal/gdal_raster.hpp"
#include "terrain/gdal/gdal_remote.hpp"
#include "terrain/codecs/height_decode.hpp"
#include "terrain/sources/http_source.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/sources/mbtiles_source.hpp"
#include "terrain/sources/quantized_mesh_source.hpp"
#include "terrain/sources/source_factory.hpp"
#include "terrain/writers/count_geotiff.hpp"

namespace trailray::terrain {
namespace {

std::chrono::milliseconds millis(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(seconds * 1000.0));
}

// One limiter for every source of the process that asks for the same limit (all of them, in
// practice: the limit comes from the one configuration), so terrain and imagery share it.
std::shared_ptr<RequestLimiter> limiter_for(int max_parallel) {
  static std::mutex mutex;
  static std::map<int, std::shared_ptr<RequestLimiter>> limiters;
  std::lock_guard lock(mutex);
  auto& limiter = limiters[max_parallel];
  if (!limiter) limiter = std::make_shared<RequestLimiter>(max_parallel);
  return limiter;
}

HttpSourceOptions http_options(const SourceSettings& s, const SourceContext& c) {
  HttpSourceOptions o;
  o.subdomains = s.subdomains;
  o.client.connect_timeout = millis(c.network.connect_timeout_s);
  o.client.total_timeout = millis(c.network.timeout_s);
  o.client.retry.max_retries = c.network.retries;
  o.client.headers = s.headers;
  o.client.limiter = limiter_for(c.network.max_parallel);
  o.cache.folder = c.cache.folder;
  o.cache.max_bytes = c.cache.max_bytes;
  o.offline = c.network.offline;
  o.warn = c.warn;
  if (s.min_zoom) o.info.min_zoom = *s.min_zoom;
  o.info.max_zoom = s.max_zoom.value_or(15);
  o.info.attribution = s.attribution;
  return o;
}

// The tiles behind an encoded source, for the three tile-pyramid kinds.
std::shared_ptr<EncodedTileSource> open_tiles(SourceKind kind, const SourceSettings& s, const SourceContext& c,
                                              HttpSourceOptions http) {
  switch (kind) {
    case SourceKind::http:
      return std::make_shared<HttpTileSource>(s.source, std::move(http));
    case SourceKind::mbtiles:
      return std::make_shared<MbtilesTileSource>(s.source);
    case SourceKind::directory: {
      DirectorySourceOptions o;
      o.scheme = s.scheme;
      return std::make_shared<DirectoryTileSource>(s.source, o);
    }
    default:
      (void)c;
      return nullptr;
  }
}

}  // namespace

std::unique_ptr<HeightSource> open_height_source(const SourceSettings& s, const SourceContext& c) {
  const SourceKind kind = classify_source(s.source);
  if (kind == SourceKind::none) return nullptr;
  if (kind == SourceKind::raster) return std::make_unique<GdalHeightSource>(s.source);
  if (kind == SourceKind::remote_raster) return open_remote_height_source(s, c.network);
  if (kind == SourceKind::quantized_mesh) return std::make_unique<QuantizedMeshSource>(s.source, c.network);

  // The encoding: said by the user, else by the source's metadata, else by its name, else
  // Terrarium (the most common); a wrong guess shows as implausible heights, and the decoder's
  // error names the encodings that would fit.
  std::optional<HeightEncoding> encoding = s.encoding;
  HttpSourceOptions http = http_options(s, c);
  if (kind == SourceKind::http) {
    const HeightEncoding e = encoding.value_or(encoding_from_name(s.source).value_or(HeightEncoding::terrarium));
    encoding = e;
    http.info.encoding = e;
    // Only tiles that decode to plausible heights are cached.
    http.validate = [e](std::span<const unsigned char> bytes) -> std::optional<std::string> {
      try {
        decode_height_tile(bytes, e, TileId{});
        return std::nullopt;
      } catch (const std::exception& error) {
        return std::string(error.what());
      }
    };
  }
  auto tiles = open_tiles(kind, s, c, std::move(http));
  if (!encoding && !tiles->info().encoding) encoding = encoding_from_name(s.source).value_or(HeightEncoding::terrarium);
  return std::make_unique<EncodedHeightSource>(std::move(tiles), encoding);
}

std::unique_ptr<ImagerySource> open_imagery_source(const SourceSettings& s, const SourceContext& c) {
  const SourceKind kind = classify_source(s.source);
  if (kind == SourceKind::none) return nullptr;
  if (kind == SourceKind::raster) return std::make_unique<GdalImagerySource>(s.source);
  if (kind == SourceKind::remote_raster) return open_remote_imagery_source(s, c.network);
  if (kind == SourceKind::quantized_mesh)
    throw SourceError(s.source + ": a quantized-mesh layer holds heights, not imagery (give it as --terrain)");
  HttpSourceOptions http = http_options(s, c);
  if (kind == SourceKind::http) {
    http.validate = [](std::span<const unsigned char> bytes) -> std::optional<std::string> {
      try {
        decode_image_tile(bytes, TileId{});
        return std::nullopt;
      } catch (const std::exception& error) {
        return std::string(error.what());
      }
    };
  }
  return std::make_unique<EncodedImagerySource>(open_tiles(kind, s, c, std::move(http)));
}

}  // namespace trailray::terrain

namespace trailray::terrain {

CountSource open_count_source(const std::string& path) {
  if (classify_source(path) != SourceKind::raster) return {};
  const std::optional<CountRaster> raster = describe_count_raster(path);
  if (!raster) return {};
  GdalOptions options;
  options.resampling = GdalResampling::max;
  return {std::make_unique<GdalHeightSource>(path, options), raster->maximum, raster->what, raster->cell_m};
}

}  // namespace trailray::terrain
