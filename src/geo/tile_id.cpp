#include "geo/tile_id.hpp"

#include <algorithm>
#include <cmath>

namespace trailray::geo {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kDegPerRad = 180.0 / std::numbers::pi;

bool valid_zoom(int zoom) { return zoom >= 0 && zoom <= kMaxTileZoom; }

// 2^zoom in 64 bits, for a valid zoom only.
std::uint64_t tiles_per_side(int zoom) { return std::uint64_t{1} << zoom; }

// Latitude of the northern edge of XYZ row `row` (row == 2^zoom: the southern edge of the world).
double row_edge_lat_deg(double row, double n) {
  return std::atan(std::sinh(std::numbers::pi * (1.0 - 2.0 * row / n))) * kDegPerRad;
}

// Longitude into [-180, 180): 180 and -180 are the same meridian, and column 0 starts there.
// std::remainder is exact (no rounding for any finite input, however large), giving [-180, 180].
double wrap_lon_deg(double lon_deg) {
  const double r = std::remainder(lon_deg, 360.0);
  return r >= 180.0 ? r - 360.0 : r;
}

// floor(f) kept in [0, n - 1]: positions on the southern or eastern edge of the world belong to
// the last row or column. f is in [0, n] here.
std::uint32_t tile_index(double f, std::uint64_t n) {
  const double i = std::clamp(std::floor(f), 0.0, static_cast<double>(n - 1));
  return static_cast<std::uint32_t>(i);
}

// splitmix64's finaliser: every key bit reaches every hash bit.
std::uint64_t mix64(std::uint64_t v) {
  v = (v ^ (v >> 30)) * 0xbf58476d1ce4e5b9ULL;
  v = (v ^ (v >> 27)) * 0x94d049bb133111ebULL;
  return v ^ (v >> 31);
}

}  // namespace

bool is_valid(const TileId& tile) {
  if (!valid_zoom(tile.zoom)) return false;
  const std::uint64_t n = tiles_per_side(tile.zoom);
  return tile.x < n && tile.y < n;
}

std::optional<TileId> make_tile_id(int zoom, std::uint32_t x, std::uint32_t y) {
  const TileId tile{zoom, x, y};
  if (!is_valid(tile)) return std::nullopt;
  return tile;
}

std::optional<TileId> tile_from_tms(int zoom, std::uint32_t x, std::uint32_t y_tms) {
  if (!make_tile_id(zoom, x, y_tms)) return std::nullopt;
  return TileId{zoom, x, static_cast<std::uint32_t>(tiles_per_side(zoom) - 1 - y_tms)};
}

std::optional<std::uint32_t> tms_y(const TileId& tile) {
  if (!is_valid(tile)) return std::nullopt;
  return static_cast<std::uint32_t>(tiles_per_side(tile.zoom) - 1 - tile.y);
}

std::optional<TileId> parent(const TileId& tile) {
  if (!is_valid(tile) || tile.zoom == 0) return std::nullopt;
  return TileId{tile.zoom - 1, tile.x >> 1, tile.y >> 1};
}

std::optional<std::array<TileId, 4>> children(const TileId& tile) {
  if (!is_valid(tile) || tile.zoom == kMaxTileZoom) return std::nullopt;
  // x, y < 2^29 here, so 2x + 1 < 2^30 fits.
  const int z = tile.zoom + 1;
  const std::uint32_t x = tile.x * 2, y = tile.y * 2;
  return std::array<TileId, 4>{TileId{z, x, y}, TileId{z, x + 1, y}, TileId{z, x, y + 1}, TileId{z, x + 1, y + 1}};
}

std::optional<LatLonBounds> tile_bounds_latlon(const TileId& tile) {
  if (!is_valid(tile)) return std::nullopt;
  const double n = static_cast<double>(tiles_per_side(tile.zoom));
  const double x = static_cast<double>(tile.x), y = static_cast<double>(tile.y);
  LatLonBounds b;
  // n is a power of two: the longitudes are exact.
  b.min_lon = x / n * 360.0 - 180.0;
  b.max_lon = (x + 1.0) / n * 360.0 - 180.0;
  b.max_lat = row_edge_lat_deg(y, n);
  b.min_lat = row_edge_lat_deg(y + 1.0, n);
  return b;
}

std::optional<MercatorBounds> tile_bounds_mercator(const TileId& tile) {
  if (!is_valid(tile)) return std::nullopt;
  const double size = 2.0 * kMercatorHalfExtentM / static_cast<double>(tiles_per_side(tile.zoom));
  const double x = static_cast<double>(tile.x), y = static_cast<double>(tile.y);
  return MercatorBounds{-kMercatorHalfExtentM + x * size, kMercatorHalfExtentM - (y + 1.0) * size,
                        -kMercatorHalfExtentM + (x + 1.0) * size, kMercatorHalfExtentM - y * size};
}

std::optional<TileCoord> fractional_tile_coord(double lat_deg, double lon_deg, int zoom) {
  if (!valid_zoom(zoom) || !std::isfinite(lat_deg) || !std::isfinite(lon_deg)) return std::nullopt;
  const double n = static_cast<double>(tiles_per_side(zoom));
  const double lat = std::clamp(lat_deg, -kMercatorMaxLatDeg, kMercatorMaxLatDeg);
  // From the degrees directly rather than through mercator_from_latlon: one rounding fewer in x.
  const double fx = (wrap_lon_deg(lon_deg) + 180.0) / 360.0 * n;
  const double fy = (1.0 - std::asinh(std::tan(lat * kRadPerDeg)) / std::numbers::pi) * 0.5 * n;
  // Rounding at the clamped latitudes can step a hair outside [0, n].
  return TileCoord{fx, std::clamp(fy, 0.0, n)};
}

std::optional<TileId> tile_containing(double lat_deg, double lon_deg, int zoom) {
  const std::optional<TileCoord> f = fractional_tile_coord(lat_deg, lon_deg, zoom);
  if (!f) return std::nullopt;
  const std::uint64_t n = tiles_per_side(zoom);
  return TileId{zoom, tile_index(f->x, n), tile_index(f->y, n)};
}

std::optional<TilePixel> tile_pixel(double lat_deg, double lon_deg, int zoom, std::uint32_t tile_size_px) {
  if (tile_size_px == 0) return std::nullopt;
  const std::optional<TileCoord> f = fractional_tile_coord(lat_deg, lon_deg, zoom);
  if (!f) return std::nullopt;
  const std::uint64_t n = tiles_per_side(zoom);
  const TileId tile{zoom, tile_index(f->x, n), tile_index(f->y, n)};
  // The fraction first, then the scaling: the global pixel (up to 2^30 * 512 = 2^39) is never
  // formed, and the fraction keeps all the precision the tile coordinate has.
  const double size = static_cast<double>(tile_size_px);
  return TilePixel{tile, (f->x - static_cast<double>(tile.x)) * size, (f->y - static_cast<double>(tile.y)) * size};
}

std::optional<LatLon> latlon_from_tile_pixel(const TileId& tile, double px, double py, std::uint32_t tile_size_px) {
  if (!is_valid(tile) || tile_size_px == 0 || !std::isfinite(px) || !std::isfinite(py)) return std::nullopt;
  const double n = static_cast<double>(tiles_per_side(tile.zoom));
  const double size = static_cast<double>(tile_size_px);
  const double fx = static_cast<double>(tile.x) + px / size;
  const double fy = static_cast<double>(tile.y) + py / size;
  return LatLon{row_edge_lat_deg(fy, n), fx / n * 360.0 - 180.0};
}

std::string to_string(const TileId& tile) {
  return std::to_string(tile.zoom) + '/' + std::to_string(tile.x) + '/' + std::to_string(tile.y);
}

std::size_t TileIdHash::operator()(const TileId& tile) const noexcept {
  if (is_valid(tile)) {
    // A marker bit above x and y: 2^(2z) + y 2^z + x is distinct for every valid id (below 2^61),
    // and mix64 is a bijection, so distinct valid ids get distinct 64-bit hashes.
    const int z = tile.zoom;
    return static_cast<std::size_t>(
        mix64((std::uint64_t{1} << (2 * z)) | (std::uint64_t{tile.y} << z) | std::uint64_t{tile.x}));
  }
  // Invalid ids (they can still be stored): anything consistent with ==, no shift by the zoom.
  const std::uint64_t key = (std::uint64_t{tile.x} << 32) | tile.y;
  return static_cast<std::size_t>(mix64(key ^ mix64(static_cast<std::uint32_t>(tile.zoom))));
}

}  // namespace trailray::geo
