#include "terrain/sources/mbtiles_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "terrain/sources/encoded_sources.hpp"
#include "terrain/codecs/height_decode.hpp"
#include "test_support.hpp"
#include "terrain/tile_fixtures.hpp"

namespace trailray::terrain {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;
using test::MbtilesWriter;
using test::TempDir;

Bytes read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Distinct bytes per tile, so a row mix-up shows.
Bytes tile_bytes(const TileId& id) {
  const std::string s = "tile " + geo::to_string(id);
  return Bytes(s.begin(), s.end());
}

std::string source_error(const fs::path& file) {
  try {
    MbtilesTileSource source(file);
  } catch (const SourceError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(MbtilesSource, FetchesTilesByXyzIdFromTmsRows) {
  TempDir dir;
  const fs::path file = dir.path() / "tiles.mbtiles";
  {
    MbtilesWriter w(file);
    w.add_metadata("name", "test");
    w.add_metadata("format", "png");
    w.add_metadata("bounds", "9.5,46.5,17.25,49.0");
    w.add_metadata("minzoom", "3");
    w.add_metadata("maxzoom", "12");
    w.add_metadata("attribution", "<a href=\"https://example.org\">example</a>");
    w.add_metadata("encoding", "mapbox");
    w.add_metadata("json", "{}");
    w.add_metadata("scheme", "whatever");            // not a key of MBTiles: ignored, rows stay TMS
    w.add_raw_tile(3, 4, 5, tile_bytes({3, 4, 2}));  // TMS row 5 of 8 is XYZ row 2
    w.add_tile({12, 2138, 1443}, tile_bytes({12, 2138, 1443}));
  }
  MbtilesTileSource source(file);
  EXPECT_EQ(source.info().name, file.string());
  EXPECT_EQ(source.info().format, "png");
  EXPECT_EQ(source.info().min_zoom, 3);
  EXPECT_EQ(source.info().max_zoom, 12);
  EXPECT_EQ(source.info().encoding, HeightEncoding::mapbox);
  EXPECT_EQ(source.info().attribution, "<a href=\"https://example.org\">example</a>");
  ASSERT_TRUE(source.info().bounds);
  EXPECT_DOUBLE_EQ(source.info().bounds->min_lon, 9.5);
  EXPECT_DOUBLE_EQ(source.info().bounds->max_lat, 49.0);

  const EncodedTile a = source.fetch(TileId{3, 4, 2}, {});
  ASSERT_EQ(a.status, TileStatus::ok) << a.error;
  EXPECT_EQ(a.bytes, tile_bytes({3, 4, 2}));
  EXPECT_EQ(source.fetch(TileId{3, 4, 5}, {}).status, TileStatus::no_data);
  EXPECT_EQ(source.fetch(TileId{12, 2138, 1443}, {}).bytes, tile_bytes({12, 2138, 1443}));
  EXPECT_EQ(source.fetch(TileId{2, 1, 1}, {}).status, TileStatus::no_data);   // below minzoom
  EXPECT_EQ(source.fetch(TileId{13, 1, 1}, {}).status, TileStatus::no_data);  // above maxzoom

  const EncodedTile invalid = source.fetch(TileId{3, 9, 0}, {});
  EXPECT_EQ(invalid.status, TileStatus::failed);
  EXPECT_NE(invalid.error.find(file.string() + " 3/9/0: not a valid tile id"), std::string::npos);
  std::stop_source stop;
  stop.request_stop();
  EXPECT_EQ(source.fetch(TileId{3, 4, 2}, stop.get_token()).status, TileStatus::cancelled);
}

TEST(MbtilesSource, TakesZoomLevelsFromTheTilesWhenMetadataLacksThem) {
  TempDir dir;
  const fs::path file = dir.path() / "bare.mbtiles";
  {
    MbtilesWriter w(file, MbtilesWriter::NoSchema{});
    // No metadata table at all; only the tiles.
    w.exec("CREATE TABLE tiles (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_data BLOB)");
    w.exec("INSERT INTO tiles VALUES (5, 1, 1, x'89504e47'), (8, 2, 2, x'ffd8ff')");
  }
  MbtilesTileSource source(file);
  EXPECT_EQ(source.info().min_zoom, 5);
  EXPECT_EQ(source.info().max_zoom, 8);
  EXPECT_FALSE(source.info().bounds);
  EXPECT_FALSE(source.info().encoding);
  EXPECT_EQ(source.fetch(TileId{8, 2, 253}, {}).bytes, (Bytes{0xff, 0xd8, 0xff}));
}

TEST(MbtilesSource, ReadsTheDeduplicatedSchemaOfMbUtil) {
  // mb-util and others store each distinct image once: `tiles` is a view over map + images.
  TempDir dir;
  const fs::path file = dir.path() / "dedup.mbtiles";
  {
    MbtilesWriter w(file, MbtilesWriter::NoSchema{});
    w.exec("CREATE TABLE map (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, tile_id TEXT)");
    w.exec("CREATE TABLE images (tile_data BLOB, tile_id TEXT)");
    w.exec("CREATE TABLE metadata (name TEXT, value TEXT)");
    w.exec(
        "CREATE VIEW tiles AS SELECT map.zoom_level AS zoom_level, map.tile_column AS tile_column, "
        "map.tile_row AS tile_row, images.tile_data AS tile_data FROM map JOIN images ON images.tile_id = map.tile_id");
    w.exec("INSERT INTO images VALUES (x'0102', 'sea'), (x'0304', 'land')");
    w.exec("INSERT INTO map VALUES (1, 0, 0, 'sea'), (1, 1, 0, 'sea'), (1, 0, 1, 'land')");
    w.exec("INSERT INTO metadata VALUES ('minzoom', '1'), ('maxzoom', '1')");
  }
  MbtilesTileSource source(file);
  EXPECT_EQ(source.fetch(TileId{1, 0, 1}, {}).bytes, (Bytes{1, 2}));
  EXPECT_EQ(source.fetch(TileId{1, 1, 1}, {}).bytes, (Bytes{1, 2}));
  EXPECT_EQ(source.fetch(TileId{1, 0, 0}, {}).bytes, (Bytes{3, 4}));
  EXPECT_EQ(source.fetch(TileId{1, 1, 0}, {}).status, TileStatus::no_data);
}

TEST(MbtilesSource, RefusesFilesThatAreNotRasterMbtiles) {
  TempDir dir;
  EXPECT_EQ(source_error(dir.path() / "missing.mbtiles"), (dir.path() / "missing.mbtiles").string() + ": no such file");
  EXPECT_NE(source_error(dir.path()).find("a folder, not an MBTiles file"), std::string::npos);

  const fs::path text = dir.path() / "text.mbtiles";
  test::write_file(text, std::string("this is not a database, just some text that is long enough to have a header\n"
                                     "and more text, and more, and more, and more, and more, and more ............."));
  const std::string not_sqlite = source_error(text);
  EXPECT_NE(not_sqlite.find(text.string() + ": not an MBTiles file (not an SQLite database"), std::string::npos)
      << not_sqlite;

  const fs::path other = dir.path() / "other.sqlite";
  {
    MbtilesWriter w(other, MbtilesWriter::NoSchema{});
    w.exec("CREATE TABLE things (a INTEGER)");
  }
  EXPECT_EQ(source_error(other), other.string() + ": not an MBTiles file (no tiles table)");

  const fs::path vector = dir.path() / "vector.mbtiles";
  {
    MbtilesWriter w(vector);
    w.add_metadata("format", "pbf");
    w.add_raw_tile(0, 0, 0, Bytes{0x1f, 0x8b, 8, 0});
  }
  EXPECT_NE(source_error(vector).find("holds vector tiles (format pbf)"), std::string::npos);

  const fs::path empty = dir.path() / "empty.mbtiles";
  { MbtilesWriter w(empty); }
  EXPECT_EQ(source_error(empty), empty.string() + ": the tiles table is empty");

  const fs::path bad_bounds = dir.path() / "bad.mbtiles";
  {
    MbtilesWriter w(bad_bounds);
    w.add_metadata("bounds", "200,0,10,10");
    w.add_raw_tile(0, 0, 0, Bytes{1});
  }
  EXPECT_NE(source_error(bad_bounds).find("bad.mbtiles: metadata bounds \"200,0,10,10\""), std::string::npos)
      << source_error(bad_bounds);
}

TEST(MbtilesSource, ReportsEmptyAndCompressedTileDataAsFailed) {
  TempDir dir;
  const fs::path file = dir.path() / "odd.mbtiles";
  {
    MbtilesWriter w(file);
    w.add_tile({2, 1, 1}, Bytes{});
    w.add_tile({2, 1, 2}, Bytes{0x1f, 0x8b, 8, 0, 0, 0});
  }
  MbtilesTileSource source(file);
  const EncodedTile empty = source.fetch(TileId{2, 1, 1}, {});
  EXPECT_EQ(empty.status, TileStatus::failed);
  EXPECT_EQ(empty.error, file.string() + " 2/1/1: empty tile data");
  const EncodedTile gzip = source.fetch(TileId{2, 1, 2}, {});
  EXPECT_EQ(gzip.status, TileStatus::failed);
  EXPECT_NE(gzip.error.find("gzip-compressed tile data"), std::string::npos);
}

TEST(MbtilesSource, NeverWritesToTheFile) {
  TempDir dir;
  // Characters that mean something in an SQLite URI must stay part of the path.
  const fs::path file = dir.path() / "odd ?name#100%.mbtiles";
  {
    MbtilesWriter w(file);
    w.add_metadata("minzoom", "0");
    w.add_metadata("maxzoom", "1");
    w.add_tile({1, 1, 0}, tile_bytes({1, 1, 0}));
  }
  const Bytes before = read_bytes(file);
  const auto mtime = fs::last_write_time(file);
  {
    MbtilesTileSource source(file);
    EXPECT_EQ(source.fetch(TileId{1, 1, 0}, {}).bytes, tile_bytes({1, 1, 0}));
  }
  EXPECT_EQ(read_bytes(file), before);
  EXPECT_EQ(fs::last_write_time(file), mtime);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir.path())) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{".anchor", "odd ?name#100%.mbtiles"}));  // no journal, no -wal
}

TEST(MbtilesSource, FetchesConcurrently) {
  TempDir dir;
  const fs::path file = dir.path() / "many.mbtiles";
  std::vector<TileId> ids;
  {
    MbtilesWriter w(file);
    for (std::uint32_t x = 0; x < 32; ++x)
      for (std::uint32_t y = 0; y < 32; ++y) {
        ids.push_back({5, x, y});
        w.add_tile(ids.back(), tile_bytes(ids.back()));
      }
  }
  MbtilesTileSource source(file);
  std::atomic<int> wrong{0}, done{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      std::mt19937 random(static_cast<unsigned>(t));
      for (int i = 0; i < 300; ++i) {
        const TileId& id = ids[random() % ids.size()];
        const EncodedTile tile = source.fetch(id, {});
        if (tile.status != TileStatus::ok || tile.bytes != tile_bytes(id)) ++wrong;
        ++done;
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(done.load(), 8 * 300);
  EXPECT_EQ(wrong.load(), 0);
}

TEST(MbtilesSource, ServesTheHeightsWrittenByTheFixtures) {
  test::MemoryHeightSource heights;
  const std::vector<TileId> ids = {{9, 274, 179}, {9, 275, 179}, {10, 549, 358}};
  for (const TileId& id : ids)
    heights.add(test::make_height_tile(id, 256, [&](std::uint32_t c, std::uint32_t r) {
      if (c == 100 && r == 7) return kNoHeight;
      return 2100.0f - static_cast<float>(c) * 2.3f + static_cast<float>(r) * 0.9f + static_cast<float>(id.zoom);
    }));
  TempDir dir;
  const fs::path file = dir.path() / "heights.mbtiles";
  ASSERT_EQ(test::write_terrarium_mbtiles(heights, ids, file), 3u);
  EncodedHeightSource source(std::make_shared<MbtilesTileSource>(file));  // encoding from the metadata
  EXPECT_EQ(source.encoding(), HeightEncoding::terrarium);
  EXPECT_EQ(source.info().format, "png");
  EXPECT_EQ(source.info().min_zoom, 9);
  EXPECT_EQ(source.info().max_zoom, 10);
  ASSERT_TRUE(source.info().bounds);
  const auto b9 = geo::tile_bounds_latlon({9, 274, 179});
  EXPECT_NEAR(source.info().bounds->min_lon, b9->min_lon, 1e-8);
  for (const TileId& id : ids) {
    const TileResult<HeightTile> got = source.load(id, {});
    ASSERT_EQ(got.status, TileStatus::ok) << got.error;
    const HeightTile want = heights.load(id, {}).tile;
    EXPECT_TRUE(std::isnan(got.tile.at(100, 7)));
    for (std::uint32_t r = 0; r < 256; r += 17)
      for (std::uint32_t c = 0; c < 256; c += 13)
        if (!std::isnan(want.at(c, r))) {
          EXPECT_NEAR(got.tile.at(c, r), want.at(c, r), 1.0 / 512);
        }
  }
  EXPECT_EQ(source.load(TileId{10, 0, 0}, {}).status, TileStatus::no_data);

  // A tile that is not an image: failed, naming the file and the tile.
  {
    MbtilesWriter w(dir.path() / "broken.mbtiles");
    w.add_tile({4, 8, 5}, Bytes{'n', 'o', 'p', 'e'});
  }
  EncodedHeightSource broken(std::make_shared<MbtilesTileSource>(dir.path() / "broken.mbtiles"),
                             HeightEncoding::terrarium);
  const TileResult<HeightTile> bad = broken.load(TileId{4, 8, 5}, {});
  EXPECT_EQ(bad.status, TileStatus::failed);
  EXPECT_EQ(bad.error.rfind((dir.path() / "broken.mbtiles").string() + " 4/8/5: not a PNG, JPEG or WebP image", 0), 0u)
      << bad.error;
}

}  // namespace
}  // namespace trailray::terrain
