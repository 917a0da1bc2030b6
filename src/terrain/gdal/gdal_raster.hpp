#pragma once
// Terrain and imagery from any raster GDAL reads (GeoTIFF, SRTM .hgt, VRT, ERDAS .img, ...; any
// CRS), opened read-only and warped on demand into Web Mercator tiles:
//   GdalHeightSource   - band 1 as heights in metres (float tiles, 256 x 256, pixel_is_area),
//                        plus exact point heights from the raster's own grid (sample_native);
//   GdalImagerySource  - 8-bit gray, gray+alpha, RGB or RGBA rasters as RGBA tiles.
//
// Warping (load): the tile's EPSG:3857 extent is cut into 256 x 256 cells and each cell centre is
// mapped into the raster (GDAL's warper, its transformer approximated to 1/100 of a source pixel),
// then resampled bilinearly (or with the cubic kernel, GdalOptions::resampling; both widen to
// average when the tile is coarser than the raster). The raster's nodata value (and NaN) marks
// missing pixels: the resampler leaves them out and renormalises over the valid ones, so a tile
// never blends -32768 or -999999 into its heights; a tile cell with no valid pixel under the
// kernel is NaN. A tile that does not meet the raster, or meets only nodata, is
// TileStatus::no_data; a partly covered one is ok with NaN holes. A tile coarser than the raster
// is warped from the coarsest of the raster's overviews (if it has any) whose pixels are still no
// larger than the tile's cells, as gdalwarp does, so that zoomed-out tiles of a big raster do not
// read all of it.
//
// Every method is thread-safe (the async loader calls load() from several workers): a dataset
// handle is borrowed per call from a small pool. GDAL's messages never reach stderr: they are
// captured per thread and end up in SourceError / TileResult::error, prefixed with the path and
// the tile.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "geo/web_mercator.hpp"
#include "terrain/loading/stop_token.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

// max: the largest source pixel under each tile pixel (counts, where an average would blur them).
enum class GdalResampling { bilinear, cubic, max };

struct GdalOptions {
  GdalResampling resampling = GdalResampling::bilinear;
  // Warped tiles kept in memory, least recently used dropped first (a height tile is 256 KiB,
  // an image tile 256 KiB). 0 keeps none.
  std::size_t tile_cache_bytes = std::size_t{64} << 20;
  // Raster pixels kept in memory for sample_native, in blocks of 256 x 256 (a raster that fits
  // is read whole, once). At least one block is always kept.
  std::size_t native_cache_bytes = std::size_t{256} << 20;
  // A raster smaller than native_cache_bytes is read whole for sample_native; false reads it by
  // blocks always (a remote raster: the blocks a track needs, not the file).
  bool read_whole_raster = true;
  // Dataset handles kept open between calls (one is needed per concurrent caller; more callers
  // open extra handles and close them afterwards).
  std::size_t max_idle_datasets = 8;
};

// Side of the warped tiles, in samples (and pixels).
inline constexpr std::uint32_t kGdalTileSize = 256;

class GdalHeightSource final : public HeightSource {
 public:
  // Opens the raster read-only and reads its georeferencing. Throws SourceError naming the path
  // and GDAL's message when it cannot be opened, has no band, no geotransform or no CRS.
  explicit GdalHeightSource(const std::string& path, GdalOptions options = {});
  ~GdalHeightSource() override;
  GdalHeightSource(const GdalHeightSource&) = delete;
  GdalHeightSource& operator=(const GdalHeightSource&) = delete;

  // name: the path; min_zoom 0; max_zoom: the zoom whose 256-px tile pixels are about as fine as
  // the raster's pixels at its centre: round(log2(C cos(lat) / (256 r))), C the equator's length
  // on the Mercator sphere, r the geometric mean of a pixel's ground width and height (clamped to
  // 0..24; 15 when the centre cannot be transformed); bounds: the raster's extent in WGS84 (edges
  // densified; the whole longitude range for a raster across the antimeridian); format
  // "gdal:<driver>" ("gdal:GTiff", "gdal:SRTMHGT"); encoding float32.
  const SourceInfo& info() const override;

  TileResult<HeightTile> load(const TileId& tile, StopToken stop) override;

  // Height from the raster's own grid, never resampled to Mercator. The rule (which
  // tests/conformance/gdal_heights.py implements independently):
  //   1. (lat, lon) in WGS84 is transformed into the raster's CRS (OGR, EPSG:4326 with
  //      OAMS_TRADITIONAL_GIS_ORDER, i.e. x = lon, y = lat), then into continuous pixel
  //      coordinates (px, py) by the inverse geotransform; pixel (i, j) covers [i, i+1) x [j, j+1),
  //      its centre is (i + 0.5, j + 0.5).
  //   2. Outside [0, width] x [0, height] (or a failed transform): NaN.
  //   3. u = px - 0.5, v = py - 0.5, i0 = floor(u), j0 = floor(v), fx = u - i0, fy = v - j0; the
  //      four pixels (i0, j0), (i0+1, j0), (i0, j0+1), (i0+1, j0+1) weigh (1-fx)(1-fy),
  //      fx(1-fy), (1-fx)fy, fx fy.
  //   4. A pixel outside the raster, equal to the band's nodata value, or NaN is invalid. The
  //      height is sum(w h) / sum(w) over the valid pixels (renormalised: near nodata and in the
  //      half-pixel rim of the raster the valid neighbours carry the point), NaN when sum(w) = 0.
  //   5. Heights are raw * scale + offset (the band's scale and offset; 1 and 0 when unset).
  // Raster pixels are read as float (exact for Int16 and Float32 rasters). Never nullopt. A read
  // error gives NaN (native_read_error() keeps the message).
  std::optional<double> sample_native(double lat, double lon) override;

  // The same for many points at once (one coordinate transformation call for all of them: use it
  // for whole tracks). heights.size() must equal points.size(); extra entries are left alone.
  void sample_native(std::span<const geo::LatLon> points, std::span<double> heights);

  // The last error met while reading raster pixels for sample_native; empty when none.
  std::string native_read_error() const;

  // The raster's size in pixels.
  int raster_width() const;
  int raster_height() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class GdalImagerySource final : public ImagerySource {
 public:
  // Opens an 8-bit raster of 1 (gray), 2 (gray + alpha), 3 (RGB) or 4 (RGBA) bands read-only.
  // Throws SourceError naming the path when it cannot be opened, has another layout, or lacks
  // georeferencing.
  explicit GdalImagerySource(const std::string& path, GdalOptions options = {});
  ~GdalImagerySource() override;
  GdalImagerySource(const GdalImagerySource&) = delete;
  GdalImagerySource& operator=(const GdalImagerySource&) = delete;

  // As GdalHeightSource::info(), without an encoding.
  const SourceInfo& info() const override;

  // RGBA, 256 x 256; alpha is 0 where the raster has no data (outside it, its nodata value, its
  // own alpha 0), else 255 or the raster's alpha. no_data when no pixel has data.
  TileResult<ImageTile> load(const TileId& tile, StopToken stop) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace trailray::terrain
