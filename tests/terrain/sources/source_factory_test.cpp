#include "terrain/sources/source_factory.hpp"

#include <gtest/gtest.h>

#include "terrain/sources/encoded_sources.hpp"
#include "terrain/gdal/gdal_raster.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"

namespace trailray::terrain {
namespace {

SourceSettings settings(std::string source) {
  SourceSettings s;
  s.source = std::move(source);
  return s;
}

TEST(SourceFactory, ClassifiesBySpellingAndByWhatIsOnDisk) {
  test::TempDir dir;
  test::write_file(dir.path() / "t.mbtiles", std::string("x"));
  test::write_file(dir.path() / "dem.tif", std::string("x"));
  EXPECT_EQ(classify_source("none"), SourceKind::none);
  EXPECT_EQ(classify_source("https://a.example/{z}/{x}/{y}.png"), SourceKind::http);
  EXPECT_EQ(classify_source("HTTP://a.example/{z}/{x}/{y}.png"), SourceKind::http);
  EXPECT_EQ(classify_source(dir.path().string()), SourceKind::directory);
  EXPECT_EQ(classify_source((dir.path() / "t.mbtiles").string()), SourceKind::mbtiles);
  EXPECT_EQ(classify_source((dir.path() / "dem.tif").string()), SourceKind::raster);
  EXPECT_THROW(classify_source(""), SourceError);
  // One remote file: a URL without placeholders, or GDAL's network file systems (nothing on disk
  // to check); a local archive through /vsizip/ is a raster GDAL opens.
  EXPECT_EQ(classify_source("https://data.example/copernicus/dem.tif"), SourceKind::remote_raster);
  EXPECT_EQ(classify_source("/vsicurl/https://data.example/dem.tif"), SourceKind::remote_raster);
  EXPECT_EQ(classify_source("/vsis3/bucket/dem.tif"), SourceKind::remote_raster);
  EXPECT_EQ(classify_source("/vsizip//vsicurl/https://data.example/dems.zip/dem.tif"), SourceKind::remote_raster);
  EXPECT_EQ(classify_source("/vsizip/dems.zip/dem.tif"), SourceKind::raster);
  EXPECT_EQ(remote_raster_path("https://data.example/dem.tif"), "/vsicurl/https://data.example/dem.tif");
  EXPECT_EQ(remote_raster_path("/vsis3/bucket/dem.tif"), "/vsis3/bucket/dem.tif");
  try {
    classify_source("/no/such/dem.tif");
    FAIL();
  } catch (const SourceError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/dem.tif: no such file or folder"), std::string::npos);
  }
}

TEST(SourceFactory, EncodingFromTheSourcesName) {
  EXPECT_EQ(encoding_from_name("https://s3.amazonaws.com/elevation-tiles-prod/terrarium/{z}/{x}/{y}.png"),
            HeightEncoding::terrarium);
  EXPECT_EQ(encoding_from_name("https://api.maptiler.com/tiles/terrain-rgb-v2/{z}/{x}/{y}.webp"),
            HeightEncoding::mapbox);
  EXPECT_EQ(encoding_from_name("/data/AlpineMaps/at"), HeightEncoding::alpinemaps);
  EXPECT_EQ(encoding_from_name("/data/tiles"), std::nullopt);
}

TEST(SourceFactory, OpensEachKind) {
  SourceContext context;
  EXPECT_EQ(open_height_source(settings("none"), context), nullptr);
  EXPECT_EQ(open_imagery_source(settings("none"), context), nullptr);

  test::TempDir cache;
  context.cache.folder = cache.path();
  SourceSettings online = settings("https://tiles.example/{z}/{x}/{y}.png");
  online.max_zoom = 12;
  online.encoding = HeightEncoding::mapbox;
  auto http = open_height_source(online, context);
  ASSERT_TRUE(http);
  EXPECT_EQ(http->info().max_zoom, 12);
  EXPECT_EQ(http->info().encoding, HeightEncoding::mapbox);
  EXPECT_THROW(open_height_source(settings("https://tiles.example/{z}/{x}.png"), context), SourceError);

  test::MemoryHeightSource heights;
  heights.add(test::make_height_tile({3, 4, 2}, 256, [](std::uint32_t c, std::uint32_t) { return 100.0f + static_cast<float>(c); }));
  const std::vector<TileId> ids{{3, 4, 2}};
  test::write_terrarium_folder(heights, ids, cache.path() / "folder", TileScheme::tms);
  auto folder = open_height_source(settings((cache.path() / "folder").string()), context);
  const auto tile = folder->load({3, 4, 2}, {});  // TMS from metadata.json
  ASSERT_EQ(tile.status, TileStatus::ok) << tile.error;
  EXPECT_NEAR(tile.tile.at(10, 0), 110.0f, 0.01f);
}

TEST(SourceFactory, RasterFilesGoThroughGdal) {
  TRAILRAY_REQUIRE_DATA(hgt, "dem/N44W072.hgt");
  auto source = open_height_source(settings(hgt.string()), {});
  ASSERT_TRUE(source);
  EXPECT_EQ(source->info().format, "gdal:SRTMHGT");
  EXPECT_TRUE(source->sample_native(44.27, -71.30).has_value());  // Mount Washington
  EXPECT_NEAR(*source->sample_native(44.2706, -71.3033), 1900.0, 40.0);
}

}  // namespace
}  // namespace trailray::terrain

namespace trailray::terrain {
namespace {

TEST(SourceFactory, ImageryFromATmsFolderOfJpegs) {
  TRAILRAY_REQUIRE_DATA(ortho, "tiles/alpinemaps_ortho");
  SourceSettings s;
  s.source = ortho.string();
  s.scheme = TileScheme::tms;
  auto imagery = open_imagery_source(s, {});
  ASSERT_TRUE(imagery);
  // TMS 7/69/83 is XYZ 7/69/44: north-east of the four, over Vienna and the Danube.
  const auto tile = imagery->load(TileId{7, 69, 44}, {});
  ASSERT_EQ(tile.status, TileStatus::ok) << tile.error;
  EXPECT_EQ(tile.tile.width, 256u);
  ASSERT_EQ(tile.tile.rgba.size(), 256u * 256u * 4u);
  std::size_t opaque = 0;
  for (std::size_t i = 3; i < tile.tile.rgba.size(); i += 4) opaque += tile.tile.rgba[i] == 255 ? 1 : 0;
  EXPECT_EQ(opaque, 256u * 256u);
  EXPECT_EQ(imagery->load(TileId{7, 10, 10}, {}).status, TileStatus::no_data);
}

}  // namespace
}  // namespace trailray::terrain
