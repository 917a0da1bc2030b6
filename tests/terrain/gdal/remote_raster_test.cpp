// Remote rasters through GDAL's range requests (issue "surface model, remote COGs"): a
// Cloud-Optimized GeoTIFF made from a real DEM at test time, served from 127.0.0.1 with and
// without HTTP ranges. Heights equal the local file's at every point asked, for a small part of
// the file's bytes; a server without ranges, and --offline, are errors that say what to do.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <filesystem>
#include <vector>

#include "terrain/local_tile_server.hpp"
#include "terrain/gdal/gdal_raster.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/sources/source_factory.hpp"
#include "test_support.hpp"

namespace trailray::terrain {
namespace {

namespace fs = std::filesystem;

// A COG eight times finer than the Interlaken DEM (about 25 MB, tiles of 256 and overviews).
struct Cog {
  test::http::TempFolder folder;
  fs::path path = folder.path() / "interlaken_cog.tif";
  bool made = false;
  explicit Cog(const fs::path& dem) {
    const std::string command = "gdal_translate -q -of COG -outsize 800% 800% -r bilinear -co COMPRESS=DEFLATE "
                                "-co BLOCKSIZE=256 '" + dem.string() + "' '" + path.string() + "'";
    made = std::system(command.c_str()) == 0 && fs::exists(path);
  }
};

std::vector<geo::LatLon> walk() {  // 200 points over about 750 m
  std::vector<geo::LatLon> points;
  for (int i = 0; i < 200; ++i) points.push_back({46.70 + 0.00002 * i, 7.85 + 0.00004 * i});
  return points;
}

SourceContext context(bool offline = false) {
  SourceContext c;
  c.network.offline = offline;
  c.network.timeout_s = 10;
  c.network.retries = 0;
  return c;
}

TEST(RemoteRaster, HeightsOfACogOverRangeRequestsEqualTheLocalFilesForAFewOfItsBytes) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  const Cog cog(dem);
  ASSERT_TRUE(cog.made) << "gdal_translate (Debian gdal-bin, scripts/setup.sh) could not write the COG";
  test::http::LocalTileServer server;
  server.serve_file("dem.tif", cog.path);

  SourceSettings s;
  s.source = server.url("/files/dem.tif");
  EXPECT_EQ(classify_source(s.source), SourceKind::remote_raster);
  std::unique_ptr<HeightSource> remote = open_height_source(s, context());
  ASSERT_NE(remote, nullptr);
  GdalHeightSource local(cog.path.string());
  const std::vector<geo::LatLon> points = walk();
  const std::vector<double> far = HeightSampler(*remote).sample(points);
  const std::vector<double> near = HeightSampler(local).sample(points);
  ASSERT_EQ(far.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_TRUE(std::isfinite(far[i])) << i;
    EXPECT_DOUBLE_EQ(far[i], near[i]) << i;
  }
  const std::size_t file_bytes = fs::file_size(cog.path), asked = server.body_bytes_sent();
  std::cout << "remote COG: " << asked << " of " << file_bytes << " bytes read for 200 heights\n";
  EXPECT_GT(asked, 0u);
  EXPECT_LT(asked * 10, file_bytes) << asked << " of " << file_bytes << " bytes read for a 750 m walk";
  // The same through GDAL's own spelling.
  s.source = "/vsicurl/" + server.url("/files/dem.tif");
  EXPECT_DOUBLE_EQ(HeightSampler(*open_height_source(s, context())).sample(points)[17], near[17]);
}

TEST(RemoteRaster, AServerWithoutRangesAndOfflineAreErrorsSayingWhatToDo) {
  TRAILRAY_REQUIRE_DATA(dem, "dem/interlaken_dhm25_wgs84.tif");
  test::http::LocalTileServer server;
  server.serve_file("dem.tif", dem);
  SourceSettings s;
  s.source = server.url("/norange/dem.tif");
  try {
    open_height_source(s, context());
    FAIL() << "opened without range requests";
  } catch (const SourceError& e) {
    EXPECT_NE(std::string(e.what()).find("does not support range requests"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(s.source), std::string::npos) << e.what();
  }
  s.source = server.url("/files/dem.tif");
  const int before = server.request_count();
  try {
    open_height_source(s, context(true));
    FAIL() << "opened offline";
  } catch (const SourceError& e) {
    EXPECT_NE(std::string(e.what()).find("--offline"), std::string::npos) << e.what();
  }
  EXPECT_EQ(server.request_count(), before);  // offline asks nothing
  s.source = server.url("/files/missing.tif");
  EXPECT_THROW(open_height_source(s, context()), SourceError);
}

}  // namespace
}  // namespace trailray::terrain
