// GdalHeightSource and GdalImagerySource on the real DEMs of shared/data and on small rasters
// written here with GDAL's GTiff driver.
#include "terrain/gdal/gdal_raster.hpp"

#include <gdal/cpl_conv.h>
#include <gdal/gdal.h>
#include <gdal/ogr_srs_api.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stop_token>
#include <thread>
#include <tuple>
#include <vector>

#include "test_support.hpp"

namespace trailray::terrain {
namespace {

using test::TempFile;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TileId tile_at(double lat, double lon, int zoom) { return *geo::tile_containing(lat, lon, zoom); }

// The sample of a warped tile that holds (lat, lon), which must lie in the tile.
std::size_t sample_index(const TileId& tile, double lat, double lon) {
  const std::optional<geo::TilePixel> p = geo::tile_pixel(lat, lon, tile.zoom, kGdalTileSize);
  EXPECT_TRUE(p && p->tile == tile) << lat << " " << lon << " is not in " << geo::to_string(tile);
  const auto col = std::min<std::uint32_t>(static_cast<std::uint32_t>(p->px), kGdalTileSize - 1);
  const auto row = std::min<std::uint32_t>(static_cast<std::uint32_t>(p->py), kGdalTileSize - 1);
  return std::size_t{row} * kGdalTileSize + col;
}

struct SampleCounts {
  std::size_t valid = 0, missing = 0;
  float min = std::numeric_limits<float>::infinity(), max = -std::numeric_limits<float>::infinity();
};
SampleCounts count_samples(const HeightTile& tile) {
  SampleCounts c;
  for (float h : tile.heights) {
    if (std::isnan(h)) {
      ++c.missing;
    } else {
      ++c.valid;
      c.min = std::min(c.min, h);
      c.max = std::max(c.max, h);
    }
  }
  return c;
}

// Equal, NaN included (the bit pattern of a NaN is not compared).
bool same_heights(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i]) != std::isnan(b[i])) return false;
    if (!std::isnan(a[i]) && a[i] != b[i]) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// A small GeoTIFF written with GDAL's C API (the test's own code, not the library's).

struct RasterSpec {
  int width = 0, height = 0;
  GDALDataType type = GDT_Float32;
  std::array<double, 6> geotransform{};
  int epsg = 4326;
  std::optional<double> nodata;  // set on every band
  std::optional<double> scale, offset;
};

void write_geotiff(const std::filesystem::path& path, const RasterSpec& spec,
                   const std::vector<std::vector<double>>& bands) {
  GDALAllRegister();
  GDALDriverH gtiff = GDALGetDriverByName("GTiff");
  ASSERT_NE(gtiff, nullptr);
  GDALDatasetH ds =
      GDALCreate(gtiff, path.c_str(), spec.width, spec.height, static_cast<int>(bands.size()), spec.type, nullptr);
  ASSERT_NE(ds, nullptr) << path;
  std::array<double, 6> gt = spec.geotransform;
  GDALSetGeoTransform(ds, gt.data());
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, spec.epsg);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  GDALSetProjection(ds, wkt);
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  for (std::size_t b = 0; b < bands.size(); ++b) {
    GDALRasterBandH band = GDALGetRasterBand(ds, static_cast<int>(b) + 1);
    if (spec.nodata) GDALSetRasterNoDataValue(band, *spec.nodata);
    if (spec.scale) GDALSetRasterScale(band, *spec.scale);
    if (spec.offset) GDALSetRasterOffset(band, *spec.offset);
    std::vector<double> values = bands[b];
    EXPECT_EQ(GDALRasterIO(band, GF_Write, 0, 0, spec.width, spec.height, values.data(), spec.width, spec.height,
                           GDT_Float64, 0, 0),
              CE_None);
  }
  GDALClose(ds);
}

// ---------------------------------------------------------------------------------------------
// The real DEMs: they open, and say where they are and how fine.

struct DemFacts {
  const char* file;
  const char* format;
  int max_zoom;  // round(log2(...)) of the native resolution, worked out by hand in the comment
  double min_lon, min_lat, max_lon, max_lat;
  float min_m, max_m;  // the raster's valid range (gdalinfo / MANIFEST)
};

// Zooms: pixel ground size r at the centre latitude, z = log2(40075017 cos(lat) / (256 r)):
// Austria 1027 m at 47.7 N -> 6.68; SRTM 78 m (66 x 93) at 44.5 N -> 10.48; Cape Horn 850 m at
// 54.4 S -> 6.75; Interlaken LV95 25 m at 46.7 N -> 12.07, its WGS84 copy 22.6 m -> 12.2.
const DemFacts kDems[] = {
    {"dem/austria_1km_wgs84.tif", "gdal:GTiff", 7, 9.0753, 46.0777, 17.5897, 49.2983, 100.0f, 3824.76f},
    {"dem/N44W072.hgt", "gdal:SRTMHGT", 10, -72.0004, 43.9996, -70.9996, 45.0004, 115.0f, 1908.0f},
    {"dem/capehorn_copernicus_small.tif", "gdal:GTiff", 7, -75.9375, -56.3429, -63.1717, -52.3646, -54.53f, 2439.2f},
    {"dem/interlaken_dhm25_25m_lv95.tif", "gdal:GTiff", 12, 7.8142, 46.6803, 7.9291, 46.7347, 559.49f, 2005.52f},
    {"dem/interlaken_dhm25_wgs84.tif", "gdal:GTiff", 12, 7.8142, 46.6803, 7.9291, 46.7347, 559.49f, 2004.24f},
};

TEST(GdalHeightSource, EveryDemOpensWithItsZoomBoundsAndFormat) {
  for (const DemFacts& dem : kDems) {
    TRAILRAY_REQUIRE_DATA(path, dem.file);
    GdalHeightSource source(path.string());
    const SourceInfo& info = source.info();
    SCOPED_TRACE(dem.file);
    EXPECT_EQ(info.name, path.string());
    EXPECT_EQ(info.format, dem.format);
    EXPECT_EQ(info.encoding, HeightEncoding::float32);
    EXPECT_EQ(info.min_zoom, 0);
    EXPECT_EQ(info.max_zoom, dem.max_zoom);
    ASSERT_TRUE(info.bounds.has_value());
    EXPECT_NEAR(info.bounds->min_lon, dem.min_lon, 1e-4);
    EXPECT_NEAR(info.bounds->min_lat, dem.min_lat, 1e-4);
    EXPECT_NEAR(info.bounds->max_lon, dem.max_lon, 1e-4);
    EXPECT_NEAR(info.bounds->max_lat, dem.max_lat, 1e-4);
  }
}

TEST(GdalHeightSource, CentreTilesAtTheNativeZoomAreFullAndWithinTheRastersRange) {
  for (const DemFacts& dem : kDems) {
    TRAILRAY_REQUIRE_DATA(path, dem.file);
    SCOPED_TRACE(dem.file);
    GdalHeightSource source(path.string());
    const double lat = 0.5 * (dem.min_lat + dem.max_lat), lon = 0.5 * (dem.min_lon + dem.max_lon);
    const TileId id = tile_at(lat, lon, dem.max_zoom);
    TileResult<HeightTile> r = source.load(id, {});
    ASSERT_EQ(r.status, TileStatus::ok) << r.error;
    const HeightTile& tile = r.tile;
    EXPECT_EQ(tile.id, id);
    EXPECT_EQ(tile.width, kGdalTileSize);
    EXPECT_EQ(tile.height, kGdalTileSize);
    EXPECT_EQ(tile.layout, SampleLayout::pixel_is_area);
    ASSERT_EQ(tile.heights.size(), std::size_t{kGdalTileSize} * kGdalTileSize);
    const SampleCounts c = count_samples(tile);
    EXPECT_GT(c.valid, 0u);
    // Interpolation never leaves the range of the pixels it blends (bilinear weights are convex).
    EXPECT_GE(c.min, dem.min_m - 0.01f);
    EXPECT_LE(c.max, dem.max_m + 0.01f);
    EXPECT_FLOAT_EQ(tile.min_m, c.min);
    EXPECT_FLOAT_EQ(tile.max_m, c.max);
    // A real relief, not a constant or a ramp of garbage.
    EXPECT_GT(c.max - c.min, 20.0f);
    // The tile's centre agrees with the raster's own grid there (a few metres: the tile
    // resamples the raster once more).
    const TileId c_id = id;
    const auto centre = geo::latlon_from_tile_pixel(c_id, 128.5, 128.5, kGdalTileSize);
    ASSERT_TRUE(centre.has_value());
    const double native = *source.sample_native(centre->lat, centre->lon);
    EXPECT_NEAR(tile.heights[sample_index(id, centre->lat, centre->lon)], native, 60.0);
  }
}

TEST(GdalHeightSource, InterlakenHeightsMatchTheManifestsCheckOfTheFlight) {
  TRAILRAY_REQUIRE_DATA(path, "dem/interlaken_dhm25_25m_lv95.tif");
  GdalHeightSource source(path.string());
  // MANIFEST: at the first fix of goigc_0100_interlaken.igc (46 42.855 N, 7 49.449 E, take-off
  // at Amisbuehl) the DEM gives 1587 m; at the last (46 41.160 N, 7 51.479 E, landed) 570 m.
  EXPECT_NEAR(*source.sample_native(46.71425, 7.82415), 1587.0, 10.0);
  EXPECT_NEAR(*source.sample_native(46.686, 7.8579833), 570.0, 10.0);
  // The same places on the warped tiles at the native zoom.
  for (const auto& [lat, lon, expected] : {std::tuple{46.71425, 7.82415, 1587.0}, {46.686, 7.8579833, 570.0}}) {
    const TileId id = tile_at(lat, lon, source.info().max_zoom);
    TileResult<HeightTile> r = source.load(id, {});
    ASSERT_EQ(r.status, TileStatus::ok) << r.error;
    EXPECT_NEAR(r.tile.heights[sample_index(id, lat, lon)], expected, 30.0) << lat << " " << lon;
  }
}

// ---------------------------------------------------------------------------------------------
// Nodata and coverage.

TEST(GdalHeightSource, AustriasNodataBorderBecomesNaNNeverMinus999999) {
  TRAILRAY_REQUIRE_DATA(path, "dem/austria_1km_wgs84.tif");
  GdalHeightSource source(path.string());
  // All zoom-7 and zoom-8 tiles over the raster: they hold its nodata ring (the first row, the
  // first and last columns, the bottom band) and its outer edges.
  std::size_t tiles = 0, missing = 0, valid = 0;
  for (int zoom : {7, 8}) {
    const TileId nw = tile_at(49.2983, 9.0753, zoom), se = tile_at(46.0778, 17.5896, zoom);
    for (std::uint32_t y = nw.y; y <= se.y; ++y) {
      for (std::uint32_t x = nw.x; x <= se.x; ++x) {
        const TileId id{zoom, x, y};
        TileResult<HeightTile> r = source.load(id, {});
        ASSERT_EQ(r.status, TileStatus::ok) << geo::to_string(id) << " " << r.error;
        const SampleCounts c = count_samples(r.tile);
        EXPECT_GE(c.min, 99.0f) << geo::to_string(id) << ": nodata blended into the heights";
        EXPECT_LE(c.max, 3825.0f) << geo::to_string(id);
        missing += c.missing;
        valid += c.valid;
        ++tiles;
      }
    }
  }
  EXPECT_GT(tiles, 10u);
  EXPECT_GT(missing, 1000u);
  EXPECT_GT(valid, 100000u);
  // The first row is nodata west of about 12.4 E: a point in it has no height.
  const double in_top_row = *source.sample_native(49.2983 - 0.002, 10.0);
  EXPECT_TRUE(std::isnan(in_top_row)) << in_top_row;
  // The western columns are nodata (the first 12 at 47.2 N: 9.075 to 9.240 E): a zoom-15 tile at
  // 9.08 E (9.0747 to 9.0857) holds nothing but nodata.
  const TileId west = tile_at(47.2, 9.08, 15);
  TileResult<HeightTile> r = source.load(west, {});
  EXPECT_EQ(r.status, TileStatus::no_data) << geo::to_string(west) << " " << r.error;
  // East of them, heights.
  const TileId inside = tile_at(47.2, 9.30, 15);
  EXPECT_EQ(source.load(inside, {}).status, TileStatus::ok) << geo::to_string(inside);
}

TEST(GdalHeightSource, TilesAwayFromTheRasterHaveNoData) {
  TRAILRAY_REQUIRE_DATA(austria, "dem/austria_1km_wgs84.tif");
  TRAILRAY_REQUIRE_DATA(lv95, "dem/interlaken_dhm25_25m_lv95.tif");
  GdalHeightSource a(austria.string()), i(lv95.string());
  for (GdalHeightSource* source : {&a, &i}) {
    for (const TileId& id : {tile_at(48.8566, 2.3522, 10), tile_at(40.7128, -74.006, 12), tile_at(-33.9, 151.2, 8),
                             tile_at(46.70, 8.50, 14)}) {
      TileResult<HeightTile> r = source->load(id, {});
      EXPECT_EQ(r.status, TileStatus::no_data) << source->info().name << " " << geo::to_string(id) << " " << r.error;
      EXPECT_TRUE(r.tile.heights.empty());
    }
  }
  // At zoom 0 the 9 km wide Interlaken raster is a fraction of a cell (156 km): no cell centre
  // falls on it, so the world tile has nothing. At zoom 8 (cells of 0.0055 x 0.0038 degrees) it
  // spans about 21 x 14 cells of one tile.
  EXPECT_EQ(i.load(TileId{0, 0, 0}, {}).status, TileStatus::no_data);
  TileResult<HeightTile> z8 = i.load(tile_at(46.7075, 7.872, 8), {});
  ASSERT_EQ(z8.status, TileStatus::ok) << z8.error;
  const SampleCounts c = count_samples(z8.tile);
  EXPECT_GT(c.valid, 150u);
  EXPECT_LT(c.valid, 500u);
  EXPECT_GE(c.min, 559.0f);
}

TEST(GdalHeightSource, TileAcrossTheRastersEdgeHasHolesAndHeights) {
  TRAILRAY_REQUIRE_DATA(path, "dem/interlaken_dhm25_25m_lv95.tif");
  GdalHeightSource source(path.string());
  // The raster's western edge (LV95 E 2628737.5) lies at about 7.8157 E at 46.71 N; tiles at
  // zoom 12 are 0.088 degrees wide, so the one holding this point straddles the edge or has it
  // within a tile width: walk west until a tile has both.
  const double lat = 46.71;
  bool found = false;
  for (double lon = 7.8157; lon > 7.70 && !found; lon -= 0.01) {
    const TileId id = tile_at(lat, lon, 13);
    TileResult<HeightTile> r = source.load(id, {});
    if (r.status != TileStatus::ok) continue;
    const SampleCounts c = count_samples(r.tile);
    if (c.missing == 0 || c.valid == 0) continue;
    found = true;
    EXPECT_GT(c.valid, 1000u);
    EXPECT_GT(c.missing, 1000u);
    EXPECT_GE(c.min, 559.0f);  // no -32768 blended in at the edge
    EXPECT_LE(c.max, 2006.0f);
    // West of the edge: NaN; well inside: a height.
    const auto west = geo::latlon_from_tile_pixel(id, 0.5, 128.0, kGdalTileSize);
    EXPECT_TRUE(std::isnan(r.tile.heights[sample_index(id, west->lat, west->lon)]));
    const auto east = geo::latlon_from_tile_pixel(id, 255.5, 128.0, kGdalTileSize);
    EXPECT_FALSE(std::isnan(r.tile.heights[sample_index(id, east->lat, east->lon)]));
  }
  EXPECT_TRUE(found) << "no zoom-13 tile across the western edge";
}

TEST(GdalHeightSource, Lv95AndWgs84InterlakenAgreeOnTheSameTile) {
  TRAILRAY_REQUIRE_DATA(lv95, "dem/interlaken_dhm25_25m_lv95.tif");
  TRAILRAY_REQUIRE_DATA(wgs84, "dem/interlaken_dhm25_wgs84.tif");
  GdalHeightSource a(lv95.string()), b(wgs84.string());
  for (int zoom : {12, 13, 14}) {
    const TileId id = tile_at(46.7075, 7.872, zoom);
    TileResult<HeightTile> ra = a.load(id, {}), rb = b.load(id, {});
    ASSERT_EQ(ra.status, TileStatus::ok) << ra.error;
    ASSERT_EQ(rb.status, TileStatus::ok) << rb.error;
    std::vector<double> diffs;
    for (std::size_t k = 0; k < ra.tile.heights.size(); ++k) {
      const float ha = ra.tile.heights[k], hb = rb.tile.heights[k];
      if (!std::isnan(ha) && !std::isnan(hb)) diffs.push_back(std::abs(double{ha} - double{hb}));
    }
    ASSERT_GT(diffs.size(), 30000u) << geo::to_string(id);
    std::sort(diffs.begin(), diffs.end());
    const double median = diffs[diffs.size() / 2], p99 = diffs[diffs.size() * 99 / 100];
    // The WGS84 file is a bilinear reprojection of the LV95 one, so the two differ by the
    // smoothing of one more resampling: measured medians 0.3-0.5 m, 99th percentiles 3-4 m.
    EXPECT_LT(median, 1.0) << geo::to_string(id);
    EXPECT_LT(p99, 6.0) << geo::to_string(id);
    EXPECT_LT(diffs.back(), 25.0) << geo::to_string(id);
  }
}

// Warping puts every tile cell where it belongs: on a raster whose heights are a plane in its own
// CRS, bilinear interpolation is exact, so each cell must hold the plane's value at the cell's
// centre, mapped into the raster's CRS by the test's own OSR transformation. A half-pixel shift,
// a flipped row order or swapped axes would show as metres (the plane rises 0.3-0.4 m a metre).
struct PlaneRaster {
  int epsg;
  double x0, y0, pixel;     // north-west corner and pixel size in CRS units
  double slope_x, slope_y;  // metres of height per CRS unit
  double height(double x, double y) const { return 1000.0 + slope_x * (x - x0) + slope_y * (y0 - y); }
};

TEST(GdalHeightSource, WarpedCellsHoldAPlanesValueAtTheirCentres) {
  const PlaneRaster planes[] = {
      {4326, 7.80, 46.74, 0.0005, 4000.0, 5000.0},   // degrees: 300 x 200 pixels of ~35 x 55 m
      {2056, 2628000.0, 1176000.0, 25.0, 0.4, 0.3},  // LV95 metres: 300 x 200 pixels of 25 m
  };
  for (const PlaneRaster& plane : planes) {
    SCOPED_TRACE(plane.epsg);
    TempFile file("plane.tif");
    RasterSpec spec;
    spec.width = 300;
    spec.height = 200;
    spec.epsg = plane.epsg;
    spec.geotransform = {plane.x0, plane.pixel, 0.0, plane.y0, 0.0, -plane.pixel};
    std::vector<double> heights;
    for (int row = 0; row < spec.height; ++row)
      for (int col = 0; col < spec.width; ++col)
        heights.push_back(plane.height(plane.x0 + (col + 0.5) * plane.pixel, plane.y0 - (row + 0.5) * plane.pixel));
    write_geotiff(file.path(), spec, {heights});
    GdalHeightSource source(file.str());

    OGRSpatialReferenceH wgs84 = OSRNewSpatialReference(nullptr), crs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(wgs84, 4326);
    OSRImportFromEPSG(crs, plane.epsg);
    OSRSetAxisMappingStrategy(wgs84, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(crs, OAMS_TRADITIONAL_GIS_ORDER);
    OGRCoordinateTransformationH to_crs = OCTNewCoordinateTransformation(wgs84, crs);
    ASSERT_NE(to_crs, nullptr);
    // Where the bilinear kernel stays inside the raster, the plane is exact.
    auto expected_at = [&](double lat, double lon) {
      double x = lon, y = lat;
      if (!OCTTransform(to_crs, 1, &x, &y, nullptr)) return kNaN;
      const double col = (x - plane.x0) / plane.pixel, row = (plane.y0 - y) / plane.pixel;
      if (col < 1.0 || row < 1.0 || col > spec.width - 1.0 || row > spec.height - 1.0) return kNaN;
      return plane.height(x, y);
    };

    for (int zoom : {13, 15}) {
      const TileId id = tile_at(46.71, 7.86, zoom);
      TileResult<HeightTile> r = source.load(id, {});
      ASSERT_EQ(r.status, TileStatus::ok) << r.error;
      std::size_t compared = 0;
      double worst = 0.0;
      for (std::uint32_t row = 0; row < kGdalTileSize; ++row) {
        for (std::uint32_t col = 0; col < kGdalTileSize; ++col) {
          const auto centre = geo::latlon_from_tile_pixel(id, col + 0.5, row + 0.5, kGdalTileSize);
          const double expected = expected_at(centre->lat, centre->lon);
          if (std::isnan(expected)) continue;
          ++compared;
          worst = std::max(worst, std::abs(r.tile.at(col, row) - expected));
        }
      }
      EXPECT_GT(compared, 10000u) << geo::to_string(id);
      // The transformer's approximation (1/100 source pixel) and float storage.
      EXPECT_LT(worst, 0.2) << geo::to_string(id);
    }
    // sample_native on the plane: exact.
    for (int k = 0; k < 100; ++k) {
      const double lat = 46.70 + 0.0003 * k, lon = 7.83 + 0.0009 * k;
      const double expected = expected_at(lat, lon);
      if (std::isnan(expected)) continue;
      EXPECT_NEAR(*source.sample_native(lat, lon), expected, 1e-3) << lat << " " << lon;
    }
    OCTDestroyCoordinateTransformation(to_crs);
    OSRDestroySpatialReference(wgs84);
    OSRDestroySpatialReference(crs);
  }
}

// A raster with overviews: tiles coarser than its pixels come from the coarsest overview that is
// still at least as fine as their cells; native samples always from the full raster.
TEST(GdalHeightSource, CoarseTilesAreWarpedFromTheRastersOverviews) {
  // 1024 x 1024 pixels of 0.0001 degrees (7.6 m x 11.1 m at 47.05 N: 9.18 m), all 500 m; its
  // overviews (2x, 4x, 8x) are then overwritten with 1000, 2000 and 3000 m, so that a tile tells
  // which level it was warped from.
  TempFile file("pyramid.tif");
  RasterSpec spec;
  spec.width = spec.height = 1024;
  spec.geotransform = {10.0, 0.0001, 0.0, 47.1, 0.0, -0.0001};
  write_geotiff(file.path(), spec, {std::vector<double>(1024 * 1024, 500.0)});
  {
    GDALDatasetH ds = GDALOpen(file.str().c_str(), GA_Update);
    ASSERT_NE(ds, nullptr);
    int factors[] = {2, 4, 8};
    ASSERT_EQ(GDALBuildOverviews(ds, "AVERAGE", 3, factors, 0, nullptr, nullptr, nullptr), CE_None);
    for (int level = 0; level < 3; ++level) {
      GDALRasterBandH overview = GDALGetOverview(GDALGetRasterBand(ds, 1), level);
      ASSERT_NE(overview, nullptr);
      const int w = GDALGetRasterBandXSize(overview), h = GDALGetRasterBandYSize(overview);
      ASSERT_EQ(w, 1024 / factors[level]);
      std::vector<float> values(std::size_t(w) * std::size_t(h), 1000.0f * static_cast<float>(level + 1));
      ASSERT_EQ(GDALRasterIO(overview, GF_Write, 0, 0, w, h, values.data(), w, h, GDT_Float32, 0, 0), CE_None);
    }
    GDALClose(ds);
  }
  GdalHeightSource source(file.str());
  // A zoom-z cell spans 40075017 cos(47.05) / (256 2^z) m = 11618 / 2^z raster pixels:
  // z14 0.7 and z13 1.4 (the raster), z12 2.8 (2x), z11 5.7 (4x), z10 11.3 and z9 22.7 (8x).
  const std::pair<int, float> expected[] = {{14, 500.0f},  {13, 500.0f},  {12, 1000.0f},
                                            {11, 2000.0f}, {10, 3000.0f}, {9, 3000.0f}};
  for (const auto& [zoom, height] : expected) {
    TileResult<HeightTile> r = source.load(tile_at(47.05, 10.05, zoom), {});
    ASSERT_EQ(r.status, TileStatus::ok) << zoom << " " << r.error;
    EXPECT_NEAR(r.tile.min_m, height, 1e-3) << "zoom " << zoom;
    EXPECT_NEAR(r.tile.max_m, height, 1e-3) << "zoom " << zoom;
  }
  EXPECT_NEAR(*source.sample_native(47.05, 10.05), 500.0, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// Threads, options, cancellation, bad input.

TEST(GdalHeightSource, ConcurrentLoadsGiveTheSameTilesAsSequentialOnes) {
  TRAILRAY_REQUIRE_DATA(path, "dem/interlaken_dhm25_25m_lv95.tif");
  std::vector<TileId> ids;
  for (int zoom : {12, 13, 14}) {
    const TileId nw = tile_at(46.7347, 7.8142, zoom), se = tile_at(46.6803, 7.9291, zoom);
    for (std::uint32_t y = nw.y; y <= se.y; ++y)
      for (std::uint32_t x = nw.x; x <= se.x; ++x) ids.push_back(TileId{zoom, x, y});
  }
  ASSERT_GT(ids.size(), 20u);
  GdalOptions no_cache;
  no_cache.tile_cache_bytes = 0;  // every load warps
  GdalHeightSource sequential(path.string(), no_cache), shared(path.string(), no_cache);
  std::vector<TileResult<HeightTile>> expected;
  for (const TileId& id : ids) expected.push_back(sequential.load(id, {}));

  constexpr int kThreads = 4, kRounds = 2;
  std::vector<std::vector<TileResult<HeightTile>>> got(kThreads);
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([&, t] {
        // Each thread walks the list from a different place, so they warp different tiles at once.
        for (int round = 0; round < kRounds; ++round)
          for (std::size_t k = 0; k < ids.size(); ++k)
            got[t].push_back(shared.load(ids[(k + static_cast<std::size_t>(t) * 7) % ids.size()], {}));
      });
    }
  }
  for (int t = 0; t < kThreads; ++t) {
    ASSERT_EQ(got[t].size(), ids.size() * kRounds);
    for (std::size_t k = 0; k < got[t].size(); ++k) {
      const std::size_t which = (k % ids.size() + static_cast<std::size_t>(t) * 7) % ids.size();
      const TileResult<HeightTile>& e = expected[which];
      const TileResult<HeightTile>& g = got[t][k];
      ASSERT_EQ(g.status, e.status) << geo::to_string(ids[which]) << " " << g.error;
      EXPECT_TRUE(same_heights(g.tile.heights, e.tile.heights)) << geo::to_string(ids[which]);
    }
  }
}

TEST(GdalHeightSource, ConcurrentNativeSamplesGiveTheSameHeightsAsSequentialOnes) {
  TRAILRAY_REQUIRE_DATA(path, "dem/interlaken_dhm25_25m_lv95.tif");
  std::vector<geo::LatLon> points;
  for (int k = 0; k < 4000; ++k)
    points.push_back({46.681 + 0.053 * ((k * 37) % 4000) / 4000.0, 7.815 + 0.113 * k / 4000.0});
  GdalHeightSource sequential(path.string());
  std::vector<double> expected(points.size());
  sequential.sample_native(points, expected);
  GdalOptions tiny;
  tiny.native_cache_bytes = 1;  // one 256 x 256 block at a time: threads keep evicting each other's
  GdalHeightSource shared(path.string(), tiny);
  std::vector<std::vector<double>> got(4, std::vector<double>(points.size(), kNaN));
  {
    std::vector<std::jthread> threads;
    for (std::size_t t = 0; t < got.size(); ++t) {
      threads.emplace_back([&, t] {
        for (std::size_t k = 0; k < points.size(); ++k) got[t][k] = *shared.sample_native(points[k].lat, points[k].lon);
      });
    }
  }
  for (const auto& heights : got) {
    for (std::size_t k = 0; k < points.size(); ++k) {
      ASSERT_FALSE(std::isnan(expected[k])) << k;
      ASSERT_EQ(heights[k], expected[k]) << k;
    }
  }
  EXPECT_EQ(shared.native_read_error(), "");
}

TEST(GdalHeightSource, CubicResamplingIsAnOptionAndDiffersSlightlyFromBilinear) {
  TRAILRAY_REQUIRE_DATA(path, "dem/interlaken_dhm25_25m_lv95.tif");
  GdalOptions cubic;
  cubic.resampling = GdalResampling::cubic;
  GdalHeightSource b(path.string()), c(path.string(), cubic);
  const TileId id = tile_at(46.7075, 7.872, 13);
  TileResult<HeightTile> rb = b.load(id, {}), rc = c.load(id, {});
  ASSERT_EQ(rb.status, TileStatus::ok);
  ASSERT_EQ(rc.status, TileStatus::ok);
  double max_diff = 0.0;
  std::size_t differing = 0;
  for (std::size_t k = 0; k < rb.tile.heights.size(); ++k) {
    const double d = std::abs(double{rb.tile.heights[k]} - double{rc.tile.heights[k]});
    max_diff = std::max(max_diff, d);
    differing += d > 1e-3 ? 1 : 0;
  }
  EXPECT_GT(differing, 10000u);  // a different kernel
  EXPECT_LT(max_diff, 15.0);     // on the same terrain
}

TEST(GdalHeightSource, CachedTilesAreReturnedUnchanged) {
  TRAILRAY_REQUIRE_DATA(path, "dem/interlaken_dhm25_wgs84.tif");
  GdalHeightSource source(path.string());
  const TileId id = tile_at(46.7075, 7.872, 13);
  TileResult<HeightTile> first = source.load(id, {});
  TileResult<HeightTile> second = source.load(id, {});
  ASSERT_EQ(first.status, TileStatus::ok);
  ASSERT_EQ(second.status, TileStatus::ok);
  EXPECT_TRUE(same_heights(first.tile.heights, second.tile.heights));
  EXPECT_EQ(first.tile.min_m, second.tile.min_m);
}

TEST(GdalHeightSource, StoppedRequestsAreCancelledAndBadIdsFail) {
  TRAILRAY_REQUIRE_DATA(path, "dem/interlaken_dhm25_25m_lv95.tif");
  GdalHeightSource source(path.string());
  std::stop_source stop;
  stop.request_stop();
  EXPECT_EQ(source.load(tile_at(46.7075, 7.872, 13), stop.get_token()).status, TileStatus::cancelled);
  TileResult<HeightTile> bad = source.load(TileId{3, 9, 1}, {});
  EXPECT_EQ(bad.status, TileStatus::failed);
  EXPECT_NE(bad.error.find(path.string()), std::string::npos) << bad.error;
  EXPECT_NE(bad.error.find("3/9/1"), std::string::npos) << bad.error;
}

TEST(GdalHeightSource, MissingFileIsASourceErrorNamingThePath) {
  const std::string path = "/nonexistent/trailray/nowhere.tif";
  try {
    GdalHeightSource source(path);
    FAIL() << "opened a file that does not exist";
  } catch (const SourceError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(GdalImagerySource imagery(path), SourceError);
}

TEST(GdalHeightSource, TextFileIsASourceErrorNamingThePathAndGdalsMessage) {
  TempFile text("notes.tif", "These are notes about a hike, not a raster.\n");
  try {
    GdalHeightSource source(text.str());
    FAIL() << "opened a text file as a raster";
  } catch (const SourceError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(text.str()), std::string::npos) << message;
    EXPECT_NE(message.find("cannot open as a raster"), std::string::npos) << message;
    // GDAL's own words follow ours.
    EXPECT_GT(message.size(), text.str().size() + std::string(": cannot open as a raster: ").size()) << message;
  }
}

TEST(GdalHeightSource, RasterWithoutGeoreferencingIsASourceError) {
  TempFile file("plain.tif");
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), file.str().c_str(), 4, 4, 1, GDT_Float32, nullptr);
  ASSERT_NE(ds, nullptr);
  GDALClose(ds);
  try {
    GdalHeightSource source(file.str());
    FAIL() << "opened a raster without georeferencing";
  } catch (const SourceError& e) {
    EXPECT_NE(std::string(e.what()).find(file.str()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("geotransform"), std::string::npos) << e.what();
  }
}

TEST(GdalHeightSource, OpeningNeverModifiesTheRasterFile) {
  TRAILRAY_REQUIRE_DATA(path, "dem/interlaken_dhm25_25m_lv95.tif");
  const auto before = std::filesystem::last_write_time(path);
  const auto size = std::filesystem::file_size(path);
  {
    GdalHeightSource source(path.string());
    (void)source.load(tile_at(46.7075, 7.872, 12), {});
    (void)source.sample_native(46.7075, 7.872);
  }
  EXPECT_EQ(std::filesystem::last_write_time(path), before);
  EXPECT_EQ(std::filesystem::file_size(path), size);
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".aux.xml"));
}

// ---------------------------------------------------------------------------------------------
// sample_native's rule, on a raster small enough to work out by hand.
//
// 4 x 3 Float32 pixels of 0.01 degrees from (10.00 E, 47.03 N):
//     row 0:  100  110  120  130
//     row 1:  200  nd   220  230        nd = nodata -9999
//     row 2:  300  310  320  330
// Pixel (col, row) has its centre at lon 10.005 + 0.01 col, lat 47.025 - 0.01 row.

class GdalNativeRule : public ::testing::Test {
 protected:
  void SetUp() override {
    RasterSpec spec;
    spec.width = 4;
    spec.height = 3;
    spec.geotransform = {10.0, 0.01, 0.0, 47.03, 0.0, -0.01};
    spec.nodata = -9999.0;
    write_geotiff(file_.path(), spec, {{100, 110, 120, 130, 200, -9999, 220, 230, 300, 310, 320, 330}});
    source_ = std::make_unique<GdalHeightSource>(file_.str());
  }
  double at(double lat, double lon) { return *source_->sample_native(lat, lon); }
  static double lon_of(double col) { return 10.0 + 0.01 * col; }  // continuous pixel x -> lon
  static double lat_of(double row) { return 47.03 - 0.01 * row; }

  TempFile file_{"rule.tif"};
  std::unique_ptr<GdalHeightSource> source_;
};

TEST_F(GdalNativeRule, PixelCentresGiveThePixel) {
  EXPECT_NEAR(at(lat_of(0.5), lon_of(0.5)), 100.0, 1e-6);
  EXPECT_NEAR(at(lat_of(2.5), lon_of(3.5)), 330.0, 1e-6);
  EXPECT_NEAR(at(lat_of(1.5), lon_of(2.5)), 220.0, 1e-6);
}

TEST_F(GdalNativeRule, BilinearBetweenFourValidCentres) {
  // Between (2,0)=120, (3,0)=130, (2,1)=220, (3,1)=230 at fx = 0.25, fy = 0.5.
  const double expected = 0.75 * 0.5 * 120 + 0.25 * 0.5 * 130 + 0.75 * 0.5 * 220 + 0.25 * 0.5 * 230;
  EXPECT_NEAR(at(lat_of(1.0), lon_of(2.75)), expected, 1e-4);
}

TEST_F(GdalNativeRule, NodataNeighboursAreLeftOutAndTheWeightsRenormalised) {
  // Midway between (0,0)=100, (1,0)=110, (0,1)=200 and the nodata (1,1): the mean of the three.
  EXPECT_NEAR(at(lat_of(1.0), lon_of(1.0)), (100.0 + 110.0 + 200.0) / 3.0, 1e-4);
  // fx = 0.25, fy = 0.75 among (0,1)=200, nd, (0,2)=300, (1,2)=310.
  const double w200 = 0.75 * 0.25, w300 = 0.75 * 0.75, w310 = 0.25 * 0.75;
  EXPECT_NEAR(at(lat_of(2.25), lon_of(0.75)), (w200 * 200 + w300 * 300 + w310 * 310) / (w200 + w300 + w310), 1e-4);
  // On the nodata pixel's centre only it weighs: no height.
  EXPECT_TRUE(std::isnan(at(lat_of(1.5), lon_of(1.5))));
}

TEST_F(GdalNativeRule, TheHalfPixelRimUsesTheEdgePixelsAndOutsideIsNaN) {
  // North of the first row's centres: only row 0 is inside, so linear along it.
  EXPECT_NEAR(at(lat_of(0.2), lon_of(1.0)), 105.0, 1e-4);
  // The north-west corner itself.
  EXPECT_NEAR(at(lat_of(0.0) - 1e-9, lon_of(0.0) + 1e-9), 100.0, 1e-4);
  EXPECT_TRUE(std::isnan(at(lat_of(-0.01), lon_of(1.0))));
  EXPECT_TRUE(std::isnan(at(lat_of(1.0), lon_of(4.01))));
  EXPECT_TRUE(std::isnan(at(0.0, 0.0)));
  EXPECT_TRUE(std::isnan(at(kNaN, 10.02)));
}

TEST_F(GdalNativeRule, ManyPointsAtOnceMatchOneByOne) {
  std::vector<geo::LatLon> points;
  for (int k = 0; k < 200; ++k) points.push_back({lat_of(-0.2 + 3.4 * k / 200.0), lon_of(4.2 - 4.4 * k / 200.0)});
  std::vector<double> batch(points.size());
  source_->sample_native(points, batch);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double one = at(points[k].lat, points[k].lon);
    EXPECT_TRUE((std::isnan(one) && std::isnan(batch[k])) || one == batch[k]) << k;
  }
}

TEST(GdalHeightSource, ScaleAndOffsetTurnRawValuesIntoMetres) {
  TempFile file("scaled.tif");
  RasterSpec spec;
  spec.width = 2;
  spec.height = 2;
  spec.type = GDT_Int16;
  spec.geotransform = {10.0, 0.01, 0.0, 47.02, 0.0, -0.01};
  spec.nodata = -32768;
  spec.scale = 0.5;
  spec.offset = 100.0;
  write_geotiff(file.path(), spec, {{1000, 2000, 3000, -32768}});
  GdalHeightSource source(file.str());
  EXPECT_NEAR(*source.sample_native(47.015, 10.005), 600.0, 1e-4);   // 1000 * 0.5 + 100
  EXPECT_NEAR(*source.sample_native(47.005, 10.005), 1600.0, 1e-4);  // 3000 * 0.5 + 100
  TileResult<HeightTile> r = source.load(tile_at(47.01, 10.01, 12), {});
  ASSERT_EQ(r.status, TileStatus::ok) << r.error;
  const SampleCounts c = count_samples(r.tile);
  EXPECT_GE(c.min, 600.0f - 0.01f);
  EXPECT_LE(c.max, 1600.0f + 0.01f);
  EXPECT_GT(c.missing, 0u);
}

// ---------------------------------------------------------------------------------------------
// Imagery.

// 200 x 100 pixels over 10..12 E, 46..47 N: the western half red, the eastern half blue; with
// nodata 0, a black block in the south-east corner (11.5..12 E, 46..46.25 N) is no data.
class GdalImagery : public ::testing::Test {
 protected:
  static std::vector<std::vector<double>> rgb_halves() {
    std::vector<std::vector<double>> bands(3, std::vector<double>(200 * 100, 0.0));
    for (int row = 0; row < 100; ++row) {
      for (int col = 0; col < 200; ++col) {
        const std::size_t k = std::size_t(row) * 200 + std::size_t(col);
        if (col >= 150 && row >= 75) continue;  // the black, nodata block
        bands[0][k] = col < 100 ? 255 : 0;
        bands[2][k] = col < 100 ? 0 : 255;
        bands[1][k] = 16;
      }
    }
    return bands;
  }
  static RasterSpec spec() {
    RasterSpec s;
    s.width = 200;
    s.height = 100;
    s.type = GDT_Byte;
    s.geotransform = {10.0, 0.01, 0.0, 47.0, 0.0, -0.01};
    s.nodata = 0;
    return s;
  }
  static std::array<std::uint8_t, 4> rgba_at(const ImageTile& tile, double lat, double lon) {
    const std::size_t k = sample_index(tile.id, lat, lon) * 4;
    return {tile.rgba[k], tile.rgba[k + 1], tile.rgba[k + 2], tile.rgba[k + 3]};
  }
};

using Rgba = std::array<std::uint8_t, 4>;

TEST_F(GdalImagery, RgbTilesAreOpaqueWhereTheRasterIsAndTransparentElsewhere) {
  TempFile file("rgb.tif");
  write_geotiff(file.path(), spec(), rgb_halves());
  GdalImagerySource source(file.str());
  EXPECT_EQ(source.info().format, "gdal:GTiff");
  EXPECT_NEAR(source.info().bounds->min_lon, 10.0, 1e-9);
  EXPECT_NEAR(source.info().bounds->max_lat, 47.0, 1e-9);
  EXPECT_EQ(source.info().max_zoom, 7);  // 0.01 degrees: 763 m x 1112 m at 46.5 N -> log2(116) = 6.9

  // Zoom 7 tile 67/45 spans 8.44..11.25 E, 45.09..47.04 N: the raster covers its north-east.
  const TileId id{7, 67, 45};
  TileResult<ImageTile> r = source.load(id, {});
  ASSERT_EQ(r.status, TileStatus::ok) << r.error;
  ASSERT_EQ(r.tile.width, kGdalTileSize);
  ASSERT_EQ(r.tile.rgba.size(), std::size_t{kGdalTileSize} * kGdalTileSize * 4);
  EXPECT_EQ(rgba_at(r.tile, 46.5, 10.5), (Rgba{255, 16, 0, 255}));
  EXPECT_EQ(rgba_at(r.tile, 46.5, 11.1)[2], 255);  // blue half
  EXPECT_EQ(rgba_at(r.tile, 46.5, 11.1)[3], 255);
  EXPECT_EQ(rgba_at(r.tile, 45.5, 9.0)[3], 0);  // outside the raster
  EXPECT_EQ(rgba_at(r.tile, 46.5, 9.5)[3], 0);

  // Inside, at zoom 10: the colours exactly, opaque; the nodata block transparent.
  TileResult<ImageTile> red = source.load(tile_at(46.6, 10.4, 10), {});
  ASSERT_EQ(red.status, TileStatus::ok) << red.error;
  for (std::size_t k = 0; k < red.tile.rgba.size(); k += 4) {
    ASSERT_EQ((Rgba{red.tile.rgba[k], red.tile.rgba[k + 1], red.tile.rgba[k + 2], red.tile.rgba[k + 3]}),
              (Rgba{255, 16, 0, 255}))
        << k / 4;
  }
  TileResult<ImageTile> corner = source.load(tile_at(46.1, 11.9, 10), {});
  ASSERT_EQ(corner.status, TileStatus::ok) << corner.error;
  EXPECT_EQ(rgba_at(corner.tile, 46.1, 11.9)[3], 0);                     // in the nodata block
  EXPECT_EQ(rgba_at(corner.tile, 46.3, 11.9), (Rgba{0, 16, 255, 255}));  // just north of it

  EXPECT_EQ(source.load(tile_at(48.85, 2.35, 10), {}).status, TileStatus::no_data);
}

TEST_F(GdalImagery, GrayAndRgbaRastersBecomeRgba) {
  TempFile gray_file("gray.tif"), rgba_file("rgba.tif");
  RasterSpec s = spec();
  s.nodata.reset();
  write_geotiff(gray_file.path(), s, {std::vector<double>(200 * 100, 77.0)});
  std::vector<std::vector<double>> rgba = rgb_halves();
  std::vector<double> alpha(200 * 100, 255.0);
  for (int row = 0; row < 50; ++row)
    for (int col = 0; col < 200; ++col) alpha[std::size_t(row) * 200 + std::size_t(col)] = 0.0;  // north half clear
  for (auto& band : rgba) std::replace(band.begin(), band.end(), 0.0, 1.0);                      // no black
  rgba.push_back(alpha);
  write_geotiff(rgba_file.path(), s, rgba);

  GdalImagerySource gray(gray_file.str()), with_alpha(rgba_file.str());
  const TileId id = tile_at(46.6, 10.4, 10);
  TileResult<ImageTile> g = gray.load(id, {});
  ASSERT_EQ(g.status, TileStatus::ok) << g.error;
  EXPECT_EQ(rgba_at(g.tile, 46.6, 10.4), (Rgba{77, 77, 77, 255}));

  TileResult<ImageTile> south = with_alpha.load(tile_at(46.2, 10.4, 10), {});
  ASSERT_EQ(south.status, TileStatus::ok) << south.error;
  EXPECT_EQ(rgba_at(south.tile, 46.2, 10.4), (Rgba{255, 16, 1, 255}));
  // The north half is clear: a tile there has nothing to show.
  EXPECT_EQ(with_alpha.load(tile_at(46.8, 10.4, 10), {}).status, TileStatus::no_data);
}

TEST_F(GdalImagery, NonEightBitRastersAreRefused) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  try {
    GdalImagerySource source(dem.string());
    FAIL() << "a Float32 DEM opened as imagery";
  } catch (const SourceError& e) {
    EXPECT_NE(std::string(e.what()).find(dem.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("8-bit"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace trailray::terrain
