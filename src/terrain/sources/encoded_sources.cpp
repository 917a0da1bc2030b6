#include "terrain/sources/encoded_sources.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <exception>
#include <utility>
#include <vector>

#include <fast_float/fast_float.h>

#include "terrain/codecs/height_decode.hpp"

namespace trailray::terrain {

namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

[[noreturn]] void bad_value(const std::string& where, std::string_view key, std::string_view value,
                            std::string_view expected) {
  throw SourceError(where + ": metadata " + std::string(key) + " \"" + std::string(value) + "\" is not " +
                    std::string(expected));
}

int parse_zoom(std::string_view key, std::string_view value, const std::string& where) {
  const std::string_view v = trimmed(value);
  int zoom = -1;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), zoom);
  if (ec != std::errc{} || end != v.data() + v.size() || zoom < 0 || zoom > geo::kMaxTileZoom)
    bad_value(where, key, value, "a zoom level 0..30");
  return zoom;
}

geo::LatLonBounds parse_bounds(std::string_view value, const std::string& where) {
  static constexpr std::string_view kExpected = "\"west,south,east,north\" in degrees";
  double v[4];
  std::string_view rest = value;
  for (int i = 0; i < 4; ++i) {
    const std::size_t comma = rest.find(',');
    if ((i < 3) == (comma == std::string_view::npos)) bad_value(where, "bounds", value, kExpected);
    const std::string_view part = trimmed(rest.substr(0, comma));
    const auto [end, ec] = fast_float::from_chars(part.data(), part.data() + part.size(), v[i]);  // libc++ 13: no double
    if (ec != std::errc{} || end != part.data() + part.size() || !std::isfinite(v[i]))
      bad_value(where, "bounds", value, kExpected);
    if (comma != std::string_view::npos) rest.remove_prefix(comma + 1);
  }
  const double west = v[0], south = v[1], east = v[2], north = v[3];
  if (west < -180.0 || east > 180.0 || west > east || south < -90.0 || north > 90.0 || south > north)
    bad_value(where, "bounds", value, "west <= east within -180..180 and south <= north within -90..90");
  geo::LatLonBounds bounds;
  bounds.add(south, west);
  bounds.add(north, east);
  return bounds;
}

// Prefixes "<source> <z/x/y>: " unless the message already names the source.
std::string tile_message(const SourceInfo& info, const TileId& tile, const std::string& message) {
  if (!info.name.empty() && message.starts_with(info.name + " ")) return message;
  return info.name + " " + geo::to_string(tile) + ": " + message;
}

template <class Tile>
TileResult<Tile> from_fetch_failure(const SourceInfo& info, const TileId& tile, EncodedTile&& fetched) {
  TileResult<Tile> result;
  result.status = fetched.status;
  if (fetched.status == TileStatus::failed) result.error = tile_message(info, tile, fetched.error);
  return result;
}

// Fetches and decodes one tile; `decode(bytes)` may throw.
template <class Tile, class Decode>
TileResult<Tile> fetch_and_decode(EncodedTileSource& tiles, const SourceInfo& info, const TileId& tile, StopToken stop,
                                  Decode decode) {
  EncodedTile fetched = tiles.fetch(tile, stop);
  if (fetched.status != TileStatus::ok) return from_fetch_failure<Tile>(info, tile, std::move(fetched));
  TileResult<Tile> result;
  if (stop.stop_requested()) {
    result.status = TileStatus::cancelled;
    return result;
  }
  // A loader worker must survive any bad tile: everything a decoder throws becomes this tile's
  // failure (TileDecodeError for bad bytes; bad_alloc for a tile too big for the memory left).
  try {
    result.tile = decode(fetched.bytes);
    result.status = TileStatus::ok;
  } catch (const std::exception& e) {
    result.status = TileStatus::failed;
    result.error = tile_message(info, tile, e.what());
  }
  return result;
}

}  // namespace

void TileMetadata::set(std::string_view key, std::string_view value, const std::string& where) {
  if (key == "minzoom") {
    min_zoom = parse_zoom(key, value, where);
  } else if (key == "maxzoom") {
    max_zoom = parse_zoom(key, value, where);
  } else if (key == "bounds") {
    bounds = parse_bounds(value, where);
  } else if (key == "encoding") {
    encoding = parse_height_encoding(value);
    if (!encoding) bad_value(where, key, value, "one of terrarium, mapbox, alpinemaps, float");
  } else if (key == "scheme") {
    scheme = parse_tile_scheme(lower(trimmed(value)));
    if (!scheme) bad_value(where, key, value, "xyz or tms");
  } else if (key == "format") {
    format = lower(trimmed(value));
    if (format == "jpeg") format = "jpg";
  } else if (key == "attribution") {
    attribution = std::string(trimmed(value));
  }
}

void TileMetadata::check(const std::string& where) const {
  if (min_zoom && max_zoom && *min_zoom > *max_zoom)
    throw SourceError(where + ": metadata minzoom " + std::to_string(*min_zoom) + " is above maxzoom " +
                      std::to_string(*max_zoom));
}

void TileMetadata::apply_to(SourceInfo& info) const {
  if (min_zoom) info.min_zoom = *min_zoom;
  if (max_zoom) info.max_zoom = *max_zoom;
  if (bounds) info.bounds = bounds;
  if (encoding) info.encoding = encoding;
  if (!format.empty()) info.format = format;
  if (!attribution.empty()) info.attribution = attribution;
}

EncodedHeightSource::EncodedHeightSource(std::shared_ptr<EncodedTileSource> tiles,
                                         std::optional<HeightEncoding> encoding)
    : tiles_(std::move(tiles)) {
  if (!tiles_) throw SourceError("height source without a tile source");
  info_ = tiles_->info();
  if (encoding) info_.encoding = encoding;
  if (!info_.encoding)
    throw SourceError(info_.name +
                      ": its metadata names no height encoding; choose one (terrarium, mapbox, alpinemaps, float)");
}

TileResult<HeightTile> EncodedHeightSource::load(const TileId& tile, StopToken stop) {
  const HeightEncoding encoding = *info_.encoding;
  return fetch_and_decode<HeightTile>(*tiles_, info_, tile, std::move(stop), [&](const std::vector<unsigned char>& b) {
    return decode_height_tile(b, encoding, tile);
  });
}

EncodedImagerySource::EncodedImagerySource(std::shared_ptr<EncodedTileSource> tiles) : tiles_(std::move(tiles)) {
  if (!tiles_) throw SourceError("imagery source without a tile source");
}

TileResult<ImageTile> EncodedImagerySource::load(const TileId& tile, StopToken stop) {
  return fetch_and_decode<ImageTile>(*tiles_, tiles_->info(), tile, std::move(stop),
                                     [&](const std::vector<unsigned char>& b) { return decode_image_tile(b, tile); });
}

}  // namespace trailray::terrain
