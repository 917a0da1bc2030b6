#pragma once
// Tile ids of the Web Mercator pyramid (web_mercator.hpp): at zoom z the square world is cut
// into 2^z x 2^z tiles. XYZ convention, as OpenStreetMap and Terrarium use it: x grows east from
// -180, y grows south from the northern edge (kMercatorMaxLatDeg). TMS (AlpineMaps, MBTiles)
// numbers the rows from the south instead; the conversion is y_tms = 2^z - 1 - y.
//
// An id is valid for zoom 0..kMaxTileZoom and x, y < 2^zoom. Every function here checks that
// (and its other inputs) and answers std::nullopt for anything invalid, so a bad id read from a
// file or URL cannot overflow a shift or an index: no undefined behaviour on any input.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "geo/bounds.hpp"
#include "geo/web_mercator.hpp"

namespace trailray::geo {

// 30 keeps x and y (and 2x + 1 for the children of zoom 29) within 32 bits, and is far past any
// served level (about 4 cm per tile at the equator).
inline constexpr int kMaxTileZoom = 30;

struct TileId {
  int zoom = 0;
  std::uint32_t x = 0, y = 0;  // XYZ: y from the north

  friend bool operator==(const TileId&, const TileId&) = default;
};

bool is_valid(const TileId& tile);

// The id if valid.
std::optional<TileId> make_tile_id(int zoom, std::uint32_t x, std::uint32_t y);

// XYZ <-> TMS. The row flip is its own inverse; these only say which way the numbers go.
std::optional<TileId> tile_from_tms(int zoom, std::uint32_t x, std::uint32_t y_tms);
std::optional<std::uint32_t> tms_y(const TileId& tile);

// The tile one zoom level up that contains this one; none at zoom 0.
std::optional<TileId> parent(const TileId& tile);

// The four tiles one level down, in XYZ order: north-west, north-east, south-west, south-east;
// none at kMaxTileZoom.
std::optional<std::array<TileId, 4>> children(const TileId& tile);

// Extent of a tile in degrees (the latitudes are those of the Mercator rows, not a linear split).
std::optional<LatLonBounds> tile_bounds_latlon(const TileId& tile);

// Extent of a tile in projected metres.
struct MercatorBounds {
  double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0;
};
std::optional<MercatorBounds> tile_bounds_mercator(const TileId& tile);

// Position in tile units at a zoom: the integer parts are the tile's x and y, the fractions the
// place inside it. Latitude is clamped to +-kMercatorMaxLatDeg; longitude is wrapped into
// [-180, 180) (180 is the antimeridian, the western edge of column 0). Both lie in [0, 2^zoom]
// (2^zoom only on the southern edge of the world, or by rounding just west of the antimeridian).
// None for an invalid zoom or a non-finite latitude or longitude.
struct TileCoord {
  double x = 0.0, y = 0.0;
};
std::optional<TileCoord> fractional_tile_coord(double lat_deg, double lon_deg, int zoom);

// The tile containing a position (fractional_tile_coord's integer parts, the southern and eastern
// edges of the world kept in the last row and column).
std::optional<TileId> tile_containing(double lat_deg, double lon_deg, int zoom);

// A position as a tile and a pixel inside it, for tiles of tile_size_px x tile_size_px pixels
// (256, 512, 65, ...). Pixel (0, 0) is the north-west corner of the tile; px and py are
// continuous, in [0, tile_size_px] (tile_size_px only on the world's southern or eastern edge).
// None for tile_size_px == 0 and whatever fractional_tile_coord rejects.
struct TilePixel {
  TileId tile;
  double px = 0.0, py = 0.0;
};
std::optional<TilePixel> tile_pixel(double lat_deg, double lon_deg, int zoom, std::uint32_t tile_size_px);

// The inverse: the position of a (continuous) pixel of a tile. px and py may lie outside the tile
// (a neighbour's pixels, skirts): longitude is then not wrapped, latitude follows the Mercator
// rows (within +-90). None for an invalid tile, tile_size_px == 0 or a non-finite pixel.
std::optional<LatLon> latlon_from_tile_pixel(const TileId& tile, double px, double py, std::uint32_t tile_size_px);

// "z/x/y" (XYZ numbers), e.g. "12/2137/1445"; printed as stored, valid or not.
std::string to_string(const TileId& tile);

// For unordered containers (std::hash<TileId> below uses it). Distinct valid ids never share a
// 64-bit hash; they meet only in the reduction to a bucket count.
struct TileIdHash {
  std::size_t operator()(const TileId& tile) const noexcept;
};

}  // namespace trailray::geo

template <>
struct std::hash<trailray::geo::TileId> {
  std::size_t operator()(const trailray::geo::TileId& tile) const noexcept { return trailray::geo::TileIdHash{}(tile); }
};
