#include "app/serve/tile_answers.hpp"

#include <fmt/format.h>

#include "app/serve/request_path.hpp"
#include "terrain/codecs/height_decode.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/sources/encoded_sources.hpp"

namespace trailray::app::serve {
namespace {

// The source's tiles do not change while it is served; an hour lets a browser keep them across
// reloads without pinning a source the user replaces at the next start for long.
constexpr const char* kTileCacheControl = "public, max-age=3600";

// Tiles are public data (a DEM, a map): any page may draw them, so they carry CORS.
HttpResponse tile_bytes(std::vector<unsigned char> bytes, std::string content_type) {
  HttpResponse r;
  r.content_type = std::move(content_type);
  r.body.assign(bytes.begin(), bytes.end());
  r.headers.emplace_back("Cache-Control", kTileCacheControl);
  r.headers.emplace_back("Access-Control-Allow-Origin", "*");
  return r;
}

HttpResponse no_tile(terrain::TileStatus status, const std::string& error, const terrain::TileId& tile) {
  switch (status) {
    case terrain::TileStatus::no_data: {
      HttpResponse r = text_response(404, fmt::format("no data for tile {}/{}/{}", tile.zoom, tile.x, tile.y));
      r.headers = {{"Cache-Control", kTileCacheControl}, {"Access-Control-Allow-Origin", "*"}};
      return r;
    }
    case terrain::TileStatus::cancelled:
      return text_response(503, "the server is stopping");
    default:
      return text_response(502, error.empty() ? std::string("the source failed") : error);
  }
}

std::string image_content_type(terrain::ImageFormat format) {
  switch (format) {
    case terrain::ImageFormat::png:
      return "image/png";
    case terrain::ImageFormat::jpeg:
      return "image/jpeg";
    case terrain::ImageFormat::webp:
      return "image/webp";
  }
  return "application/octet-stream";
}

}  // namespace

std::optional<terrain::TileId> parse_tile_segments(const std::vector<std::string>& segments, std::size_t first,
                                                   const std::string& suffix, int max_zoom) {
  if (segments.size() != first + 3) return std::nullopt;
  const std::string& last = segments[first + 2];
  if (last.size() <= suffix.size() || last.compare(last.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  const auto z = parse_segment_number(segments[first]), x = parse_segment_number(segments[first + 1]),
             y = parse_segment_number(last.substr(0, last.size() - suffix.size()));
  if (!z || !x || !y || static_cast<int>(*z) > max_zoom) return std::nullopt;
  return geo::make_tile_id(static_cast<int>(*z), *x, *y);
}

HttpResponse terrain_tile_response(terrain::HeightSource& source, const terrain::TileId& tile,
                                   terrain::StopToken stop) {
  terrain::TileResult<terrain::HeightTile> result = source.load(tile, stop);
  if (result.status != terrain::TileStatus::ok) return no_tile(result.status, result.error, tile);
  if (!result.tile.has_data()) return no_tile(terrain::TileStatus::no_data, {}, tile);
  try {
    return tile_bytes(terrain::encode_terrarium_png(result.tile), "image/png");
  } catch (const std::exception& e) {
    return text_response(500, fmt::format("tile {}/{}/{}: {}", tile.zoom, tile.x, tile.y, e.what()));
  }
}

HttpResponse imagery_tile_response(terrain::ImagerySource& source, const terrain::TileId& tile,
                                   terrain::StopToken stop) {
  // Tiles stored as images go out as they are: no decoding, no loss, the source's format.
  if (auto* encoded = dynamic_cast<terrain::EncodedImagerySource*>(&source)) {
    terrain::EncodedTile fetched = encoded->tiles().fetch(tile, stop);
    if (fetched.status != terrain::TileStatus::ok) return no_tile(fetched.status, fetched.error, tile);
    const auto format = terrain::sniff_image_format(fetched.bytes);
    if (!format)
      return text_response(502, fmt::format("{} {}/{}/{}: not a PNG, JPEG or WebP image", source.info().name, tile.zoom,
                                            tile.x, tile.y));
    return tile_bytes(std::move(fetched.bytes), image_content_type(*format));
  }
  terrain::TileResult<terrain::ImageTile> result = source.load(tile, stop);
  if (result.status != terrain::TileStatus::ok) return no_tile(result.status, result.error, tile);
  terrain::DecodedImage image;
  image.width = result.tile.width;
  image.height = result.tile.height;
  image.channels = 4;
  image.samples8 = std::move(result.tile.rgba);
  try {
    return tile_bytes(terrain::encode_png(image), "image/png");
  } catch (const std::exception& e) {
    return text_response(500, fmt::format("tile {}/{}/{}: {}", tile.zoom, tile.x, tile.y, e.what()));
  }
}

}  // namespace trailray::app::serve
