// Conformance of GdalHeightSource with GDAL's Python bindings (Debian python3-gdal), computed in
// the same run: every point of real tracks is sampled on the real DEMs under them by
// sample_native and by tests/conformance/gdal_heights.py, which implements the rule documented in
// gdal_raster.hpp independently (osr + its own bilinear). Then the tile path (load() at max_zoom,
// bilinear inside the warped tiles) is held against the native heights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "app/run_command.hpp"
#include "terrain/gdal/gdal_raster.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"

namespace trailray::terrain {
namespace {

using test::run_command;
using test::shell_quote;
using test::TempFile;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The same rule on both sides, the same PROJ: only float rounding (the raster is read as float
// here) may differ.
constexpr double kNativeToleranceM = 0.5;

std::vector<geo::LatLon> track_points(const std::filesystem::path& path) {
  const track::ReadResult read = track::load_track_file(path.string());
  EXPECT_TRUE(read.ok()) << path << ": " << (read.error ? read.error->to_string() : "");
  std::vector<geo::LatLon> points;
  for (const track::Track& t : read.file.tracks)
    for (const track::Segment& s : t.segments)
      for (const track::TrackPoint& p : s.points) points.push_back({p.lat, p.lon});
  return points;
}

// Heights by tests/conformance/gdal_heights.py; empty when the script failed.
std::vector<double> python_heights(const std::filesystem::path& dem, const std::vector<geo::LatLon>& points) {
  std::ostringstream lines;
  lines.precision(12);
  for (const geo::LatLon& p : points) lines << p.lat << ' ' << p.lon << '\n';
  TempFile input("points.txt", lines.str());
  const std::string script = std::string(TRAILRAY_SOURCE_DIR) + "/tests/conformance/gdal_heights.py";
  const auto result = run_command("/usr/bin/python3 " + shell_quote(script) + " " + shell_quote(dem.string()) + " " +
                                  shell_quote(input.str()));
  EXPECT_EQ(result.status, 0) << "gdal_heights.py failed (is python3-gdal installed? run scripts/setup.sh)";
  std::vector<double> heights;
  if (result.status != 0) return heights;
  std::istringstream out(result.out);
  for (std::string line; std::getline(out, line);) heights.push_back(line == "nan" ? kNaN : std::stod(line));
  return heights;
}

// Bilinear inside the warped tiles at `zoom` (tiles are pixel_is_area: sample (i, j) of the
// zoom's global grid sits at (i + 0.5, j + 0.5) samples), NaN samples left out and the weights
// renormalised, as sample_native does on the raster: the height a renderer would see.
class TileHeights {
 public:
  TileHeights(GdalHeightSource& source, int zoom) : source_(source), zoom_(zoom) {}

  double at(double lat, double lon) {
    const std::optional<geo::TileCoord> c = geo::fractional_tile_coord(lat, lon, zoom_);
    if (!c) return kNaN;
    const double u = c->x * kGdalTileSize - 0.5, v = c->y * kGdalTileSize - 0.5;
    const double u0 = std::floor(u), v0 = std::floor(v);
    const double fx = u - u0, fy = v - v0;
    double sum = 0.0, weights = 0.0;
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        const double h = sample(static_cast<std::int64_t>(u0) + dx, static_cast<std::int64_t>(v0) + dy);
        if (std::isnan(h)) continue;
        const double w = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy);
        sum += w * h;
        weights += w;
      }
    }
    return weights > 0.0 ? sum / weights : kNaN;
  }

 private:
  double sample(std::int64_t col, std::int64_t row) {
    const std::int64_t n = std::int64_t{kGdalTileSize} << zoom_;
    if (col < 0 || row < 0 || col >= n || row >= n) return kNaN;
    const TileId id{zoom_, static_cast<std::uint32_t>(col / kGdalTileSize),
                    static_cast<std::uint32_t>(row / kGdalTileSize)};
    auto found = tiles_.find(id);
    if (found == tiles_.end()) {
      TileResult<HeightTile> r = source_.load(id, {});
      EXPECT_NE(r.status, TileStatus::failed) << r.error;
      found = tiles_.emplace(id, r.status == TileStatus::ok ? std::move(r.tile) : HeightTile{}).first;
    }
    const HeightTile& tile = found->second;
    if (tile.heights.empty()) return kNaN;
    return tile.at(static_cast<std::uint32_t>(col % kGdalTileSize), static_cast<std::uint32_t>(row % kGdalTileSize));
  }

  struct IdLess {
    bool operator()(const TileId& a, const TileId& b) const {
      return std::tie(a.zoom, a.x, a.y) < std::tie(b.zoom, b.x, b.y);
    }
  };
  GdalHeightSource& source_;
  const int zoom_;
  std::map<TileId, HeightTile, IdLess> tiles_;
};

struct TileDiffs {
  std::vector<double> sorted;     // |tile path - native| where both have a height
  std::size_t one_path_only = 0;  // points with a height on one path and not the other

  double percentile(double p) const {
    return sorted.empty()
               ? kNaN
               : sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(p * static_cast<double>(sorted.size())))];
  }
  double worst() const { return sorted.empty() ? kNaN : sorted.back(); }
  std::string summary() const {
    std::ostringstream s;
    s.precision(3);
    s << "median " << percentile(0.5) << " m, p99 " << percentile(0.99) << " m, max " << worst() << " m";
    if (one_path_only > 0) s << ", " << one_path_only << " on one path only";
    return s.str();
  }
};

TileDiffs compare_tiles(GdalHeightSource& source, int zoom, const std::vector<geo::LatLon>& points,
                        const std::vector<double>& native) {
  TileHeights tiles(source, zoom);
  TileDiffs d;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double t = tiles.at(points[k].lat, points[k].lon);
    if (std::isnan(native[k]) || std::isnan(t)) {
      // Only at the very edge of the data may one path have a height and the other not.
      d.one_path_only += std::isnan(native[k]) != std::isnan(t) ? 1 : 0;
      continue;
    }
    d.sorted.push_back(std::abs(t - native[k]));
  }
  std::sort(d.sorted.begin(), d.sorted.end());
  return d;
}

struct Pair {
  const char* track;
  const char* dem;
  std::size_t min_valid;  // points that land on valid pixels (all of them, or as counted once)
  bool some_nodata;       // the track also leaves the data (outside the raster or on nodata)
  // |tile path - native| bound in metres, measured on this pair (see the test's comment).
  double tile_tolerance_m;
};

// Tile tolerances at max_zoom: the measured maxima (GDAL 3.6.2) rounded up by about 30 %.
// Measured, tiles vs native (median / p99 / max, metres):
//   Interlaken 25 m, z12:          LV95 0.30 / 5.8 / 9.0;  WGS84 copy 0.38 / 5.8 / 13.8
//   Austria 1 km, z7 (824 m cells): Moedling 3.4 / 44 / 44;  Kitzbuehel 18 / 49 / 62;
//                                  Renato Spaeni 16 / 173 / 262 (alpine ridges, nodata edge);
//                                  MTK logger 3.8 / 19 / 22;  Trifai 452 km 15 / 111 / 202
// and two zooms finer the p99 drops about tenfold (Interlaken z14: 0.9 m; Austria z9: 5-22 m).
const Pair kPairs[] = {
    {"igc/goigc_0100_interlaken.igc", "dem/interlaken_dhm25_25m_lv95.tif", 1149, false, 12.0},
    {"igc/goigc_0100_interlaken.igc", "dem/interlaken_dhm25_wgs84.tif", 1149, false, 18.0},
    {"gpx/alpinemaps_husarentempel.gpx", "dem/austria_1km_wgs84.tif", 891, false, 60.0},
    {"igc/goigc_0192_kitzbuehel.igc", "dem/austria_1km_wgs84.tif", 3399, false, 80.0},
    {"igc/goigc_2024-06-18_Renato_Spaeni_420032.igc", "dem/austria_1km_wgs84.tif", 5500, true, 340.0},
    {"gpx/gpsbabel_mtk_logger_m241_multiple_tracks.gpx", "dem/austria_1km_wgs84.tif", 3300, true, 30.0},
    {"igc/xcscore_trifai-xcontest-452.21.igc", "dem/austria_1km_wgs84.tif", 35041, false, 260.0},
};

TEST(GdalConformance, NativeHeightsMatchGdalPythonOnRealTracksAndTilesStayClose) {
  for (const Pair& pair : kPairs) {
    TRAILRAY_REQUIRE_DATA(track_path, pair.track);
    TRAILRAY_REQUIRE_DATA(dem_path, pair.dem);
    SCOPED_TRACE(std::string(pair.track) + " on " + pair.dem);
    const std::vector<geo::LatLon> points = track_points(track_path);
    ASSERT_FALSE(points.empty());

    GdalHeightSource source(dem_path.string());
    std::vector<double> native(points.size(), kNaN);
    source.sample_native(points, native);
    EXPECT_EQ(source.native_read_error(), "");
    const std::vector<double> reference = python_heights(dem_path, points);
    ASSERT_EQ(reference.size(), points.size());

    std::size_t valid = 0, missing = 0;
    double worst_native = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      ASSERT_EQ(std::isnan(native[k]), std::isnan(reference[k]))
          << "point " << k << " (" << points[k].lat << ", " << points[k].lon << "): trailray " << native[k]
          << ", GDAL python " << reference[k];
      if (std::isnan(native[k])) {
        ++missing;
        continue;
      }
      ++valid;
      const double diff = std::abs(native[k] - reference[k]);
      worst_native = std::max(worst_native, diff);
      ASSERT_LE(diff, kNativeToleranceM) << "point " << k << " (" << points[k].lat << ", " << points[k].lon
                                         << "): trailray " << native[k] << ", GDAL python " << reference[k];
    }
    EXPECT_GE(valid, pair.min_valid);
    EXPECT_EQ(missing > 0, pair.some_nodata) << missing << " points without a height";

    // The tile path resamples twice (raster -> Mercator grid -> the point), each time bilinearly,
    // so it cuts ridges and fills valleys by a share of a pixel's relief; on finer tiles the
    // Mercator grid follows the raster's bilinear surface more closely.
    const int native_zoom = source.info().max_zoom;
    const TileDiffs at_native = compare_tiles(source, native_zoom, points, native);
    const TileDiffs finer = compare_tiles(source, native_zoom + 2, points, native);
    std::cout << "[ INFO ] " << pair.track << " on " << pair.dem << ": " << valid << " points with heights, " << missing
              << " without; native vs GDAL python: max " << worst_native << " m; tiles vs native at z" << native_zoom
              << ": " << at_native.summary() << "; at z" << native_zoom + 2 << ": " << finer.summary() << "\n";
    EXPECT_LE(at_native.worst(), pair.tile_tolerance_m);
    EXPECT_LT(finer.percentile(0.99), at_native.percentile(0.99));
    EXPECT_LE(at_native.one_path_only, points.size() / 50) << "points with a height on one path only";
  }
}

}  // namespace
}  // namespace trailray::terrain
