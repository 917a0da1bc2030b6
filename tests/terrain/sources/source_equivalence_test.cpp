// One area through every kind of source: a GeoTIFF, a tile folder (XYZ and TMS), an MBTiles file
// and an HTTP server must give the same heights along a real flight. The tile sources serve the
// very same Terrarium bytes, so they agree exactly; the GeoTIFF is sampled on its own 25 m grid
// while the tiles were warped from it to a 3.3 m Mercator grid and are interpolated again, which
// costs a little in steep terrain (measured and bounded below).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "terrain/dem_pyramid.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/local_tile_server.hpp"
#include "terrain/sources/source_factory.hpp"
#include "test_support.hpp"
#include "track/io/load.hpp"

namespace trailray::terrain {
namespace {

std::vector<geo::LatLon> track_points(const std::filesystem::path& file, geo::LatLonBounds& box) {
  const auto r = track::load_track_file(file.string());
  EXPECT_TRUE(r.ok());
  std::vector<geo::LatLon> points;
  for (const auto& t : r.file.tracks)
    for (const auto& s : t.segments)
      for (const auto& p : s.points) {
        points.push_back({p.lat, p.lon});
        box.add(p.lat, p.lon);
      }
  return points;
}

std::vector<double> heights_from(const SourceSettings& settings, const SourceContext& context,
                                 const std::vector<geo::LatLon>& points, SamplingReport* report = nullptr) {
  auto source = open_height_source(settings, context);
  EXPECT_TRUE(source);
  HeightSampler sampler(*source);
  auto h = sampler.sample(points);
  if (report) *report = sampler.report();
  return h;
}

TEST(SourceEquivalence, GeoTiffFolderMbtilesAndHttpGiveTheSameHeights) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  TRAILRAY_REQUIRE_DATA(flight, "igc/goigc_0100_interlaken.igc");
  geo::LatLonBounds box;
  const auto points = track_points(flight, box);
  ASSERT_GT(points.size(), 1000u);

  test::DemPyramid pyramid;
  test::build_dem_pyramid(pyramid, dem, box, 15);
  test::http::LocalTileServer server(pyramid.xyz_folder);
  test::TempDir cache;
  SourceContext context;
  context.cache.folder = cache.path();

  auto settings = [](std::string source) {
    SourceSettings s;
    s.source = std::move(source);
    return s;
  };
  SourceSettings http = settings(server.url("/tiles/{z}/{x}/{y}.png"));
  http.max_zoom = 15;

  const auto tiff = heights_from(settings(dem.string()), context, points);
  const auto xyz = heights_from(settings(pyramid.xyz_folder.string()), context, points);
  const auto tms = heights_from(settings(pyramid.tms_folder.string()), context, points);
  const auto mbtiles = heights_from(settings(pyramid.mbtiles.string()), context, points);
  SamplingReport http_report;
  const auto online = heights_from(http, context, points, &http_report);
  EXPECT_EQ(http_report.tiles_failed, 0u);
  EXPECT_GT(server.request_count(), 0);

  double worst = 0.0, sum = 0.0;
  std::size_t worst_i = 0, over_half = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_FALSE(std::isnan(tiff[i])) << i;
    // The same bytes through three containers: bit-identical heights.
    ASSERT_EQ(xyz[i], tms[i]) << i;
    ASSERT_EQ(xyz[i], mbtiles[i]) << i;
    ASSERT_EQ(xyz[i], online[i]) << i;
    const double d = std::abs(xyz[i] - tiff[i]);
    if (d > worst) worst_i = i;
    worst = std::max(worst, d);
    over_half += d > 0.5 ? 1 : 0;
    sum += d;
  }
  const double mean = sum / static_cast<double>(points.size());
  RecordProperty("max_tile_vs_geotiff_m", std::to_string(worst));
  RecordProperty("mean_tile_vs_geotiff_m", std::to_string(mean));
  std::printf("tiles vs GeoTIFF along the flight: mean %.3f m, max %.3f m at %.6f %.6f (%.2f vs %.2f), %zu over 0.5 m\n",
              mean, worst, points[worst_i].lat, points[worst_i].lon, xyz[worst_i], tiff[worst_i], over_half);
  // Warping to the 3.3 m grid and interpolating again rounds the kinks of the 25 m grid's
  // bilinear surface: at most (change of slope) x (tile sample spacing) / 4, about 1.2 m where
  // the slope turns by 1.4 (a cliff foot); a few centimetres on average.
  EXPECT_LT(mean, 0.05);
  EXPECT_LT(worst, 1.5);
  EXPECT_LT(over_half, points.size() / 100);

  // A second pass through HTTP is served from the disk cache: no new requests.
  const int requests = server.request_count();
  const auto again = heights_from(http, context, points);
  EXPECT_EQ(server.request_count(), requests);
  EXPECT_EQ(again, online);
}

}  // namespace
}  // namespace trailray::terrain
