#include "terrain/codecs/height_decode.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "test_support.hpp"
#include "terrain/tile_fixtures.hpp"

namespace trailray::terrain {
namespace {

using Bytes = std::vector<unsigned char>;
constexpr TileId kTile{12, 2138, 1443};

Bytes read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// An 8-bit image of `size` x `size` pixels all set to `pixel` (3 or 4 values).
DecodedImage uniform_image(std::uint32_t size, std::vector<std::uint8_t> pixel) {
  DecodedImage image;
  image.width = image.height = size;
  image.channels = static_cast<std::uint32_t>(pixel.size());
  image.samples8.resize(std::size_t{size} * size * pixel.size());
  for (std::size_t i = 0; i < image.samples8.size(); ++i) image.samples8[i] = pixel[i % pixel.size()];
  return image;
}

std::string decode_error(const Bytes& bytes, HeightEncoding encoding) {
  try {
    decode_height_tile(bytes, encoding, kTile);
  } catch (const TileDecodeError& e) {
    return e.what();
  }
  return "(no error)";
}

// A smooth mountain: 500 m valleys to a 3500 m peak.
float mountain(std::uint32_t c, std::uint32_t r, std::uint32_t size) {
  const double x = (c + 0.5) / size - 0.5, y = (r + 0.5) / size - 0.5;
  return static_cast<float>(500.0 + 3000.0 * std::exp(-(x * x + y * y) * 8.0) + 37.3 * std::sin(c * 0.37));
}

TEST(HeightEncoding, ParsesNamesAndPrintsThem) {
  EXPECT_EQ(parse_height_encoding("terrarium"), HeightEncoding::terrarium);
  EXPECT_EQ(parse_height_encoding(" Terrarium\n"), HeightEncoding::terrarium);
  EXPECT_EQ(parse_height_encoding("mapbox"), HeightEncoding::mapbox);
  EXPECT_EQ(parse_height_encoding("terrain-rgb"), HeightEncoding::mapbox);
  EXPECT_EQ(parse_height_encoding("mapbox-terrain-rgb"), HeightEncoding::mapbox);
  EXPECT_EQ(parse_height_encoding("AlpineMaps"), HeightEncoding::alpinemaps);
  EXPECT_EQ(parse_height_encoding("float"), HeightEncoding::float32);
  EXPECT_EQ(parse_height_encoding("terra"), std::nullopt);
  EXPECT_EQ(parse_height_encoding(""), std::nullopt);
  for (HeightEncoding e :
       {HeightEncoding::terrarium, HeightEncoding::mapbox, HeightEncoding::alpinemaps, HeightEncoding::float32})
    EXPECT_EQ(parse_height_encoding(to_string(e)), e);
}

TEST(HeightDecode, AppliesEachEncodingsFormula) {
  // terrarium: R*256 + G + B/256 - 32768.
  EXPECT_FLOAT_EQ(heights_from_image(uniform_image(4, {128, 0, 0}), HeightEncoding::terrarium, kTile).heights[0], 0.0f);
  EXPECT_FLOAT_EQ(heights_from_image(uniform_image(4, {129, 44, 128}), HeightEncoding::terrarium, kTile).heights[5],
                  300.5f);
  EXPECT_FLOAT_EQ(heights_from_image(uniform_image(4, {126, 10, 64}), HeightEncoding::terrarium, kTile).heights[0],
                  -501.75f);  // 32256 + 10 - 32768 + 0.25
  // mapbox: -10000 + (R*65536 + G*256 + B) / 10; 1,134,160 is 100000 -> 0 m.
  EXPECT_FLOAT_EQ(heights_from_image(uniform_image(4, {1, 134, 160}), HeightEncoding::mapbox, kTile).heights[0], 0.0f);
  EXPECT_NEAR(heights_from_image(uniform_image(4, {1, 180, 41}), HeightEncoding::mapbox, kTile).heights[0], 1165.7,
              1e-3);
  // alpinemaps: (R*256 + G) / 8, B unused.
  EXPECT_FLOAT_EQ(heights_from_image(uniform_image(4, {14, 160, 99}), HeightEncoding::alpinemaps, kTile).heights[0],
                  468.0f);
  const HeightTile t = heights_from_image(uniform_image(4, {129, 44, 128}), HeightEncoding::terrarium, kTile);
  EXPECT_EQ(t.id, kTile);
  EXPECT_EQ(t.width, 4u);
  EXPECT_EQ(t.heights.size(), 16u);
  EXPECT_FLOAT_EQ(t.min_m, 300.5f);
  EXPECT_FLOAT_EQ(t.max_m, 300.5f);
}

TEST(HeightDecode, TransparentPixelsAreHoles) {
  DecodedImage image = uniform_image(4, {128, 100, 0, 255});
  image.samples8[4 * 5 + 3] = 0;    // pixel 5 transparent
  image.samples8[4 * 6 + 1] = 200;  // pixel 6 higher
  const HeightTile t = heights_from_image(image, HeightEncoding::terrarium, kTile);
  EXPECT_TRUE(std::isnan(t.heights[5]));
  EXPECT_FLOAT_EQ(t.heights[4], 100.0f);
  EXPECT_FLOAT_EQ(t.min_m, 100.0f);
  EXPECT_FLOAT_EQ(t.max_m, 200.0f);

  const HeightTile empty = heights_from_image(uniform_image(4, {0, 0, 0, 0}), HeightEncoding::mapbox, kTile);
  EXPECT_FALSE(empty.has_data());
  EXPECT_TRUE(std::isnan(empty.heights[0]));
}

TEST(HeightDecode, LayoutFollowsTheSize) {
  EXPECT_EQ(layout_for_size(65), SampleLayout::pixel_is_point);
  EXPECT_EQ(layout_for_size(257), SampleLayout::pixel_is_point);
  EXPECT_EQ(layout_for_size(3), SampleLayout::pixel_is_point);
  EXPECT_EQ(layout_for_size(256), SampleLayout::pixel_is_area);
  EXPECT_EQ(layout_for_size(512), SampleLayout::pixel_is_area);
  EXPECT_EQ(layout_for_size(2), SampleLayout::pixel_is_area);
  EXPECT_EQ(layout_for_size(63), SampleLayout::pixel_is_area);
  EXPECT_EQ(layout_for_size(66), SampleLayout::pixel_is_area);
  EXPECT_EQ(heights_from_image(uniform_image(65, {14, 160, 0}), HeightEncoding::alpinemaps, kTile).layout,
            SampleLayout::pixel_is_point);
  EXPECT_EQ(heights_from_image(uniform_image(16, {128, 0, 0}), HeightEncoding::terrarium, kTile).layout,
            SampleLayout::pixel_is_area);
}

TEST(HeightDecode, RejectsTilesThatAreNotSquareOrTooSmall) {
  DecodedImage wide = uniform_image(4, {128, 0, 0});
  wide.width = 8;
  wide.height = 2;
  try {
    heights_from_image(wide, HeightEncoding::terrarium, kTile);
    ADD_FAILURE() << "no error";
  } catch (const TileDecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("wrong tile size 8x2"), std::string::npos) << e.what();
  }
  const Bytes one_pixel = encode_png(uniform_image(1, {128, 0, 0}));
  EXPECT_NE(decode_error(one_pixel, HeightEncoding::terrarium).find("wrong tile size 1x1"), std::string::npos);
}

TEST(HeightDecode, SaysWhichEncodingFitsWhenHeightsAreImplausible) {
  HeightTile tile = test::make_height_tile(kTile, 32, [](auto c, auto r) { return mountain(c, r, 32); });
  const Bytes terrarium = encode_height_tile(tile, HeightEncoding::terrarium);
  const Bytes mapbox = encode_height_tile(tile, HeightEncoding::mapbox);

  const std::string as_mapbox = decode_error(terrarium, HeightEncoding::mapbox);
  EXPECT_NE(as_mapbox.find("with the mapbox encoding"), std::string::npos) << as_mapbox;
  EXPECT_NE(as_mapbox.find("the encoding is probably wrong"), std::string::npos) << as_mapbox;
  EXPECT_NE(as_mapbox.find("terrarium"), std::string::npos) << as_mapbox;
  EXPECT_NE(as_mapbox.find("outside -11000..9000 m"), std::string::npos) << as_mapbox;

  const std::string as_terrarium = decode_error(mapbox, HeightEncoding::terrarium);
  EXPECT_NE(as_terrarium.find("mapbox"), std::string::npos) << as_terrarium;
  EXPECT_EQ(as_terrarium.find("terrarium would"), std::string::npos) << as_terrarium;

  // A few wild values among plausible ones are data, not a wrong encoding.
  tile.heights[0] = 20000.0f;
  EXPECT_NO_THROW(decode_height_tile(encode_height_tile(tile, HeightEncoding::mapbox), HeightEncoding::mapbox, kTile));
}

TEST(HeightDecode, EncodesAndDecodesEveryEncodingWithinItsStep) {
  const HeightTile tile = test::make_height_tile(kTile, 64, [](auto c, auto r) {
    if (c == 3 && r == 5) return kNoHeight;
    return mountain(c, r, 64) - 900.0f;  // some below sea level
  });
  const struct {
    HeightEncoding encoding;
    double step;
  } kCases[] = {{HeightEncoding::terrarium, 1.0 / 256},
                {HeightEncoding::mapbox, 0.1},
                {HeightEncoding::alpinemaps, 1.0 / 8},
                {HeightEncoding::float32, 0.0}};
  for (const auto& c : kCases) {
    const Bytes bytes = encode_height_tile(tile, c.encoding);
    const HeightTile back = decode_height_tile(bytes, c.encoding, kTile);
    ASSERT_EQ(back.width, 64u) << to_string(c.encoding);
    ASSERT_EQ(back.heights.size(), tile.heights.size());
    EXPECT_TRUE(std::isnan(back.at(3, 5))) << to_string(c.encoding);
    double worst = 0;
    for (std::size_t i = 0; i < tile.heights.size(); ++i) {
      if (std::isnan(tile.heights[i])) continue;
      // alpinemaps has no negative heights: they are clamped to 0.
      const double expected =
          c.encoding == HeightEncoding::alpinemaps ? std::max(0.0f, tile.heights[i]) : tile.heights[i];
      worst = std::max(worst, std::abs(back.heights[i] - expected));
    }
    EXPECT_LE(worst, c.step / 2 + 1e-3) << to_string(c.encoding);
    EXPECT_LE(back.min_m, back.max_m);
  }
  // Without holes the PNG is RGB, with them RGBA.
  EXPECT_EQ(decode_image(encode_terrarium_png(tile)).channels, 4u);
  EXPECT_EQ(
      decode_image(encode_terrarium_png(test::make_height_tile(kTile, 4, [](auto, auto) { return 1.0f; }))).channels,
      3u);
  HeightTile malformed = tile;
  malformed.heights.pop_back();
  EXPECT_THROW(encode_height_tile(malformed, HeightEncoding::terrarium), std::invalid_argument);
}

TEST(HeightDecode, Keeps16BitPrecision) {
  // AlpineMaps' R*256 + G in one 16-bit gray channel: 1/8 m steps survive.
  DecodedImage gray16;
  gray16.width = gray16.height = 2;
  gray16.channels = 1;
  gray16.bit_depth = 16;
  gray16.samples16 = {12345, 3744, 0, 65535};
  const HeightTile a = decode_height_tile(encode_png(gray16), HeightEncoding::alpinemaps, kTile);
  EXPECT_FLOAT_EQ(a.heights[0], 1543.125f);
  EXPECT_FLOAT_EQ(a.heights[1], 468.0f);
  EXPECT_FLOAT_EQ(a.heights[3], 8191.875f);

  // 16-bit RGB read as Terrarium: each channel scaled to 8 bits (128 * 257 -> 128).
  DecodedImage rgb16;
  rgb16.width = rgb16.height = 2;
  rgb16.channels = 3;
  rgb16.bit_depth = 16;
  for (int i = 0; i < 4; ++i) rgb16.samples16.insert(rgb16.samples16.end(), {128 * 257, 100 * 257, 0});
  EXPECT_FLOAT_EQ(decode_height_tile(encode_png(rgb16), HeightEncoding::terrarium, kTile).heights[2], 100.0f);
}

TEST(HeightDecode, FloatTilesAreTiffsAndOnlyTiffs) {
  const HeightTile tile = test::make_height_tile(kTile, 17, [](std::uint32_t c, std::uint32_t r) {
    return -3.25f + static_cast<float>(c) * 100.5f + static_cast<float>(r);
  });
  const Bytes tiff = encode_height_tile(tile, HeightEncoding::float32);
  ASSERT_GE(tiff.size(), 4u);
  EXPECT_TRUE(tiff[0] == 'I' || tiff[0] == 'M');
  const HeightTile back = decode_height_tile(tiff, HeightEncoding::float32, kTile);
  EXPECT_EQ(back.heights, tile.heights);
  EXPECT_EQ(back.layout, SampleLayout::pixel_is_point);  // 17 = 2^4 + 1

  EXPECT_NE(decode_error(encode_terrarium_png(tile), HeightEncoding::float32).find("this is a PNG"), std::string::npos);
  EXPECT_NE(decode_error(tiff, HeightEncoding::terrarium).find("a TIFF tile"), std::string::npos);
  Bytes truncated(tiff.begin(), tiff.begin() + 64);
  EXPECT_NE(decode_error(truncated, HeightEncoding::float32).find("TIFF"), std::string::npos)
      << decode_error(truncated, HeightEncoding::float32);

  const HeightTile absurd = test::make_height_tile(kTile, 8, [](auto, auto) { return 1e6f; });
  EXPECT_NE(decode_error(encode_height_tile(absurd, HeightEncoding::float32), HeightEncoding::float32)
                .find("not heights in metres"),
            std::string::npos);
}

TEST(HeightDecode, FloatTilesDecodeConcurrently) {
  // Each thread decodes its own tiles through GDAL's in-memory files: no name may collide.
  std::vector<Bytes> tiffs;
  for (int t = 0; t < 8; ++t)
    tiffs.push_back(encode_height_tile(
        test::make_height_tile(
            kTile, 16,
            [t](std::uint32_t c, std::uint32_t) { return static_cast<float>(t * 1000 + static_cast<int>(c)); }),
        HeightEncoding::float32));
  std::vector<int> wrong(8, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 25; ++i) {
        const HeightTile h = decode_height_tile(tiffs[t], HeightEncoding::float32, kTile);
        if (h.at(5, 3) != static_cast<float>(t * 1000 + 5)) ++wrong[t];
      }
    });
  for (auto& th : threads) th.join();
  for (int w : wrong) EXPECT_EQ(w, 0);
}

TEST(HeightDecode, DecodesImageryToRgba8) {
  const ImageTile rgba = decode_image_tile(encode_png(uniform_image(3, {10, 20, 30})), kTile);
  EXPECT_EQ(rgba.id, kTile);
  EXPECT_EQ(rgba.width, 3u);
  ASSERT_EQ(rgba.rgba.size(), 36u);
  EXPECT_EQ(rgba.rgba[4], 10);
  EXPECT_EQ(rgba.rgba[7], 255);
  // Imagery may be any size, unlike height tiles.
  DecodedImage wide = uniform_image(4, {1, 2, 3});
  wide.width = 8;
  wide.height = 2;
  EXPECT_EQ(decode_image_tile(encode_png(wide), kTile).width, 8u);
  EXPECT_THROW(decode_image_tile(Bytes{'<', 'h', 't', 'm', 'l', '>'}, kTile), TileDecodeError);
}

TEST(HeightDecode, TheRealAlpineMapsTileHasAustrianHeights) {
  TRAILRAY_REQUIRE_DATA(path, "tiles/alpinemaps/test-tile.png");
  const Bytes bytes = read_bytes(path);
  const HeightTile tile = decode_height_tile(bytes, HeightEncoding::alpinemaps, kTile);
  EXPECT_EQ(tile.width, 65u);
  EXPECT_EQ(tile.layout, SampleLayout::pixel_is_point);
  EXPECT_FLOAT_EQ(tile.at(0, 0), 468.0f);   // raw 3744
  EXPECT_FLOAT_EQ(tile.at(1, 0), 464.75f);  // raw 3718
  // Heights of the Austrian pre-Alps (measured once with GDAL's Python bindings: raw 3350..9178).
  EXPECT_FLOAT_EQ(tile.min_m, 418.75f);
  EXPECT_FLOAT_EQ(tile.max_m, 1147.25f);
  // Read as Terrarium it is nonsense (R = 14 gives about -29000 m), and the error says so.
  const std::string wrong = decode_error(bytes, HeightEncoding::terrarium);
  EXPECT_NE(wrong.find("probably wrong"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("alpinemaps"), std::string::npos) << wrong;
}

TEST(HeightDecode, TheRealOrthoTileDecodesAsImagery) {
  TRAILRAY_REQUIRE_DATA(path, "tiles/alpinemaps_ortho/7/68/83.jpg");
  const ImageTile tile = decode_image_tile(read_bytes(path), TileId{7, 68, 44});
  EXPECT_EQ(tile.width, 256u);
  EXPECT_EQ(tile.height, 256u);
  ASSERT_EQ(tile.rgba.size(), 256u * 256u * 4u);
  EXPECT_EQ(tile.rgba[3], 255);
  // Not blank: a real picture has many distinct colours.
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < tile.rgba.size(); i += 4)
    colours.insert(tile.rgba[i] << 16 | tile.rgba[i + 1] << 8 | tile.rgba[i + 2]);
  EXPECT_GT(colours.size(), 1000u);
}

}  // namespace
}  // namespace trailray::terrain
