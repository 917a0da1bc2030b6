#include "terrain/sources/directory_source.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "terrain/sources/encoded_sources.hpp"
#include "terrain/codecs/height_decode.hpp"
#include "test_support.hpp"
#include "terrain/tile_fixtures.hpp"

namespace trailray::terrain {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;
using test::TempDir;
using test::write_file;

Bytes read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string source_error(const fs::path& root, DirectorySourceOptions options = {}) {
  try {
    DirectoryTileSource source(root, options);
  } catch (const SourceError& e) {
    return e.what();
  }
  return "(no error)";
}

// Every file under a folder with its size and modification time, to show nothing was touched.
std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>> snapshot(const fs::path& root) {
  std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    files[e.path().string()] = {e.is_regular_file() ? e.file_size() : 0, e.last_write_time()};
  return files;
}

Bytes small_png() {
  DecodedImage image;
  image.width = image.height = 2;
  image.channels = 3;
  image.samples8 = {128, 1, 0, 128, 2, 0, 128, 3, 0, 128, 4, 0};
  return encode_png(image);
}

TEST(DirectorySource, ReadsTheRealAlpineMapsOrthoFolderAsTms) {
  TRAILRAY_REQUIRE_DATA(root, "tiles/alpinemaps_ortho");
  const auto before = snapshot(root);
  DirectoryTileSource source(root, {.scheme = TileScheme::tms});
  EXPECT_EQ(source.scheme(), TileScheme::tms);
  EXPECT_EQ(source.info().name, root.string());
  EXPECT_EQ(source.info().min_zoom, 7);
  EXPECT_EQ(source.info().max_zoom, 7);
  EXPECT_EQ(source.info().format, "jpg");
  // The four tiles cover Austria (MANIFEST: lon 11.25..16.875, lat 45.089..48.9225).
  ASSERT_TRUE(source.info().bounds);
  EXPECT_NEAR(source.info().bounds->min_lon, 11.25, 1e-9);
  EXPECT_NEAR(source.info().bounds->max_lon, 16.875, 1e-9);
  EXPECT_NEAR(source.info().bounds->min_lat, 45.0890, 1e-3);
  EXPECT_NEAR(source.info().bounds->max_lat, 48.9225, 1e-3);

  // File 7/68/82.jpg is TMS row 82: XYZ row 127 - 82 = 45.
  const EncodedTile tile = source.fetch(TileId{7, 68, 45}, {});
  ASSERT_EQ(tile.status, TileStatus::ok) << tile.error;
  EXPECT_EQ(tile.bytes, read_bytes(root / "7/68/82.jpg"));
  EXPECT_EQ(source.fetch(TileId{7, 68, 82}, {}).status, TileStatus::no_data);  // the TMS number as XYZ: nothing
  EXPECT_EQ(source.fetch(TileId{7, 70, 45}, {}).status, TileStatus::no_data);
  EXPECT_EQ(source.fetch(TileId{8, 136, 90}, {}).status, TileStatus::no_data);  // beyond the zoom levels

  EncodedImagerySource imagery(std::make_shared<DirectoryTileSource>(root, DirectorySourceOptions{TileScheme::tms}));
  const TileResult<ImageTile> picture = imagery.load(TileId{7, 69, 44}, {});
  ASSERT_EQ(picture.status, TileStatus::ok) << picture.error;
  EXPECT_EQ(picture.tile.width, 256u);
  EXPECT_EQ(picture.tile.rgba.size(), 256u * 256u * 4u);

  EXPECT_EQ(snapshot(root), before);
}

TEST(DirectorySource, DefaultsToXyzWithoutMetadata) {
  TRAILRAY_REQUIRE_DATA(root, "tiles/alpinemaps_ortho");
  DirectoryTileSource source(root);
  EXPECT_EQ(source.scheme(), TileScheme::xyz);
  EXPECT_EQ(source.fetch(TileId{7, 68, 82}, {}).status, TileStatus::ok);
  // Read as XYZ the same files lie in the southern hemisphere.
  ASSERT_TRUE(source.info().bounds);
  EXPECT_LT(source.info().bounds->max_lat, -45.0);
}

TEST(DirectorySource, TakesSchemeZoomsBoundsEncodingAndFormatFromMetadataJson) {
  TempDir dir;
  write_file(dir.path() / "3/4/2.png", small_png());
  write_file(dir.path() / "metadata.json", std::string(R"({
    "name": "test", "scheme": "tms", "format": "PNG", "minzoom": "2", "maxzoom": 5,
    "bounds": "5.5, 45.25, 10.5, 48", "encoding": "terrarium", "attribution": "(c) somebody",
    "center": "7,46,3", "json": "{\"vector_layers\": []}"})"));
  DirectoryTileSource source(dir.path());
  EXPECT_EQ(source.scheme(), TileScheme::tms);
  EXPECT_EQ(source.info().min_zoom, 2);
  EXPECT_EQ(source.info().max_zoom, 5);
  EXPECT_EQ(source.info().format, "png");
  EXPECT_EQ(source.info().encoding, HeightEncoding::terrarium);
  EXPECT_EQ(source.info().attribution, "(c) somebody");
  ASSERT_TRUE(source.info().bounds);
  EXPECT_DOUBLE_EQ(source.info().bounds->min_lon, 5.5);
  EXPECT_DOUBLE_EQ(source.info().bounds->min_lat, 45.25);
  EXPECT_DOUBLE_EQ(source.info().bounds->max_lon, 10.5);
  EXPECT_DOUBLE_EQ(source.info().bounds->max_lat, 48.0);
  EXPECT_EQ(source.fetch(TileId{3, 4, 5}, {}).status, TileStatus::ok);  // TMS row 2 of 8

  // The options override the metadata.
  DirectoryTileSource xyz(dir.path(), {.scheme = TileScheme::xyz});
  EXPECT_EQ(xyz.fetch(TileId{3, 4, 2}, {}).status, TileStatus::ok);
  EXPECT_EQ(xyz.fetch(TileId{3, 4, 5}, {}).status, TileStatus::no_data);

  // Bounds as an array, numbers as numbers.
  write_file(dir.path() / "metadata.json", std::string(R"({"bounds": [-10, -20.5, 30, 40], "maxzoom": 3})"));
  DirectoryTileSource arrays(dir.path());
  ASSERT_TRUE(arrays.info().bounds);
  EXPECT_DOUBLE_EQ(arrays.info().bounds->min_lat, -20.5);
  EXPECT_EQ(arrays.info().max_zoom, 3);
  EXPECT_EQ(arrays.info().min_zoom, 3);  // from the folders
}

TEST(DirectorySource, Gdal2tilesFoldersAreTms) {
  TempDir dir;
  write_file(dir.path() / "1/0/0.png", small_png());
  write_file(dir.path() / "tilemapresource.xml", std::string("<?xml version=\"1.0\"?><TileMap version=\"1.0.0\"/>"));
  DirectoryTileSource source(dir.path());
  EXPECT_EQ(source.scheme(), TileScheme::tms);
  EXPECT_EQ(source.fetch(TileId{1, 0, 1}, {}).status, TileStatus::ok);
  EXPECT_EQ(source.fetch(TileId{1, 0, 0}, {}).status, TileStatus::no_data);
}

TEST(DirectorySource, FindsTilesOfAnyImageExtensionAndListsZoomFolders) {
  TempDir dir;
  const Bytes png = small_png();
  write_file(dir.path() / "4/1/2.webp", png);  // content does not matter to the folder
  write_file(dir.path() / "6/3/3.jpeg", png);
  write_file(dir.path() / "9/300/200.png", png);
  fs::create_directories(dir.path() / "notes");
  fs::create_directories(dir.path() / "99");  // beyond any zoom level: not one
  DirectoryTileSource source(dir.path());
  EXPECT_EQ(source.info().min_zoom, 4);
  EXPECT_EQ(source.info().max_zoom, 9);
  EXPECT_EQ(source.info().format, "webp");  // from the coarsest level's files
  EXPECT_EQ(source.fetch(TileId{4, 1, 2}, {}).bytes, png);
  EXPECT_EQ(source.fetch(TileId{6, 3, 3}, {}).status, TileStatus::ok);
  EXPECT_EQ(source.fetch(TileId{9, 300, 200}, {}).status, TileStatus::ok);
  EXPECT_EQ(source.fetch(TileId{9, 300, 201}, {}).status, TileStatus::no_data);
  EXPECT_EQ(source.fetch(TileId{5, 0, 0}, {}).status, TileStatus::no_data);  // no folder for the level
}

TEST(DirectorySource, ReportsUnreadableTilesAsFailedNamingTheFile) {
  TempDir dir;
  write_file(dir.path() / "2/1/1.png", small_png());
  write_file(dir.path() / "2/1/2.png", Bytes{});
  fs::create_directories(dir.path() / "2/1/3.png");  // a folder where a tile should be
  DirectoryTileSource source(dir.path());

  const EncodedTile empty = source.fetch(TileId{2, 1, 2}, {});
  EXPECT_EQ(empty.status, TileStatus::failed);
  EXPECT_NE(empty.error.find(dir.path().string() + " 2/1/2: cannot read "), std::string::npos) << empty.error;
  EXPECT_NE(empty.error.find("2.png: the file is empty"), std::string::npos) << empty.error;

  const EncodedTile folder = source.fetch(TileId{2, 1, 3}, {});
  EXPECT_EQ(folder.status, TileStatus::failed);
  EXPECT_NE(folder.error.find("3.png"), std::string::npos) << folder.error;

  const EncodedTile invalid = source.fetch(TileId{2, 4, 0}, {});
  EXPECT_EQ(invalid.status, TileStatus::failed);
  EXPECT_NE(invalid.error.find("not a valid tile id"), std::string::npos);

  std::stop_source stop;
  stop.request_stop();
  EXPECT_EQ(source.fetch(TileId{2, 1, 1}, stop.get_token()).status, TileStatus::cancelled);
}

TEST(DirectorySource, RefusesWhatIsNotATileFolder) {
  TempDir dir;
  EXPECT_NE(source_error(dir.path() / "missing").find("no such folder"), std::string::npos);
  write_file(dir.path() / "file.png", small_png());
  EXPECT_NE(source_error(dir.path() / "file.png").find("file.png: not a folder"), std::string::npos);
  EXPECT_NE(source_error(dir.path()).find(dir.path().string() + ": no zoom level folders"), std::string::npos)
      << source_error(dir.path());

  fs::create_directories(dir.path() / "0/0");
  write_file(dir.path() / "metadata.json", std::string("{\"minzoom\": \"zero\"}"));
  const std::string bad_zoom = source_error(dir.path());
  EXPECT_NE(bad_zoom.find("metadata.json: metadata minzoom \"zero\" is not a zoom level"), std::string::npos)
      << bad_zoom;
  write_file(dir.path() / "metadata.json", std::string("{\"bounds\": \"1,2,3\"}"));
  EXPECT_NE(source_error(dir.path()).find("bounds \"1,2,3\""), std::string::npos) << source_error(dir.path());
  write_file(dir.path() / "metadata.json", std::string("{\"scheme\": \"google\"}"));
  EXPECT_NE(source_error(dir.path()).find("xyz or tms"), std::string::npos);
  write_file(dir.path() / "metadata.json", std::string("{\"encoding\": \"rgb\"}"));
  EXPECT_NE(source_error(dir.path()).find("encoding \"rgb\""), std::string::npos);
  write_file(dir.path() / "metadata.json", std::string("{\"minzoom\": 5, \"maxzoom\": 2}"));
  EXPECT_NE(source_error(dir.path()).find("minzoom 5 is above maxzoom 2"), std::string::npos);
  write_file(dir.path() / "metadata.json", std::string("{\"scheme\": "));
  EXPECT_NE(source_error(dir.path()).find("metadata.json: not valid JSON"), std::string::npos);
}

TEST(DirectorySource, ServesTheHeightsWrittenByTheFixtures) {
  // Two levels around Innsbruck, one tile with holes.
  test::MemoryHeightSource heights;
  const std::vector<TileId> ids = {{10, 548, 358}, {10, 549, 358}, {11, 1097, 717}};
  for (const TileId& id : ids)
    heights.add(test::make_height_tile(id, 256, [&](std::uint32_t c, std::uint32_t r) {
      if (id.zoom == 11 && c < 10 && r < 10) return kNoHeight;
      return 574.0f + static_cast<float>(c) * 3.7f + static_cast<float>(r) * 1.3f + static_cast<float>(id.x % 7);
    }));
  for (TileScheme scheme : {TileScheme::xyz, TileScheme::tms}) {
    TempDir dir;
    ASSERT_EQ(test::write_terrarium_folder(heights, ids, dir.path(), scheme), 3u);
    auto folder = std::make_shared<DirectoryTileSource>(dir.path());
    EXPECT_EQ(folder->scheme(), scheme);  // from the metadata.json the fixture wrote
    EncodedHeightSource source(folder);   // the encoding too
    EXPECT_EQ(source.encoding(), HeightEncoding::terrarium);
    EXPECT_EQ(source.info().min_zoom, 10);
    EXPECT_EQ(source.info().max_zoom, 11);
    for (const TileId& id : ids) {
      const TileResult<HeightTile> got = source.load(id, {});
      ASSERT_EQ(got.status, TileStatus::ok) << got.error;
      const TileResult<HeightTile> want = heights.load(id, {});
      ASSERT_EQ(got.tile.heights.size(), want.tile.heights.size());
      for (std::size_t i = 0; i < want.tile.heights.size(); ++i) {
        if (std::isnan(want.tile.heights[i])) {
          EXPECT_TRUE(std::isnan(got.tile.heights[i])) << i;
        } else {
          EXPECT_NEAR(got.tile.heights[i], want.tile.heights[i], 1.0 / 512) << geo::to_string(id) << " " << i;
        }
      }
    }
    EXPECT_EQ(source.load(TileId{10, 0, 0}, {}).status, TileStatus::no_data);
  }
}

TEST(DirectorySource, HeightSourceNamesSourceAndTileInDecodeErrors) {
  TempDir dir;
  write_file(dir.path() / "5/3/4.png", std::string("<html>404</html>"));
  write_file(dir.path() / "5/3/5.png", Bytes{});
  EncodedHeightSource source(std::make_shared<DirectoryTileSource>(dir.path()), HeightEncoding::mapbox);
  const TileResult<HeightTile> html = source.load(TileId{5, 3, 4}, {});
  EXPECT_EQ(html.status, TileStatus::failed);
  EXPECT_EQ(html.error, dir.path().string() +
                            " 5/3/4: not a PNG, JPEG or WebP image (starts with 3c 68 74 6d: text "
                            "\"<html>404</html>\")");
  const TileResult<HeightTile> empty = source.load(TileId{5, 3, 5}, {});
  EXPECT_EQ(empty.status, TileStatus::failed);
  EXPECT_EQ(empty.error.rfind(dir.path().string() + " 5/3/5: cannot read", 0), 0u)
      << empty.error;  // not prefixed twice

  // Without an encoding, from the caller or the metadata, there is no height source.
  try {
    EncodedHeightSource unknown(std::make_shared<DirectoryTileSource>(dir.path()));
    ADD_FAILURE() << "no error";
  } catch (const SourceError& e) {
    EXPECT_NE(std::string(e.what()).find("names no height encoding"), std::string::npos);
  }
}

}  // namespace
}  // namespace trailray::terrain
