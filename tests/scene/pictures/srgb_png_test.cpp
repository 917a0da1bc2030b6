// linear -> sRGB encoding, row flipping and the PNG file (pure CPU).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "scene/pictures/rgba_image.hpp"
#include "scene/scene_error.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "test_support.hpp"

namespace trailray::scene {
namespace {

std::vector<unsigned char> read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

scene::RgbaImage pattern(std::uint32_t width, std::uint32_t height) {
  scene::RgbaImage image{width, height, std::vector<std::uint8_t>(std::size_t{width} * height * 4)};
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = static_cast<std::uint8_t>((i * 37 + i / 7) & 0xff);
  return image;
}

TEST(LinearToSrgb8, KnownValues) {
  EXPECT_EQ(scene::linear_to_srgb8(0.0f), 0);
  EXPECT_EQ(scene::linear_to_srgb8(1.0f), 255);
  EXPECT_EQ(scene::linear_to_srgb8(0.5f), 188);   // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
  EXPECT_EQ(scene::linear_to_srgb8(0.18f), 118);  // middle grey: 0.4614
  EXPECT_EQ(scene::linear_to_srgb8(0.002f), 7);   // the linear segment: 12.92 * 0.002 = 0.02584
  EXPECT_EQ(scene::linear_to_srgb8(-0.5f), 0);
  EXPECT_EQ(scene::linear_to_srgb8(7.0f), 255);
  EXPECT_EQ(scene::linear_to_srgb8(std::nanf("")), 0);
}

TEST(LinearToSrgb8, IsTheInverseOfDecodingForEveryByte) {
  for (int value = 0; value < 256; ++value) {
    const auto byte = static_cast<std::uint8_t>(value);
    EXPECT_EQ(scene::linear_to_srgb8(scene::srgb8_to_linear(byte)), byte) << value;
  }
  EXPECT_NEAR(scene::srgb8_to_linear(188), 0.5f, 0.003f);  // half an 8-bit step there
  // Monotonic: more light never encodes darker.
  for (int i = 1; i <= 1000; ++i)
    EXPECT_GE(scene::linear_to_srgb8(static_cast<float>(i) / 1000.0f), scene::linear_to_srgb8(static_cast<float>(i - 1) / 1000.0f));
}

TEST(FlipRows, ReversesTheRowOrder) {
  std::vector<std::uint8_t> pixels{1, 2, 3, 4, 5, 6, 7, 8, 9};
  scene::flip_rows(pixels, 3);
  EXPECT_EQ(pixels, (std::vector<std::uint8_t>{7, 8, 9, 4, 5, 6, 1, 2, 3}));
  std::vector<std::uint8_t> two_rows{1, 2, 3, 4};
  scene::flip_rows(two_rows, 2);
  EXPECT_EQ(two_rows, (std::vector<std::uint8_t>{3, 4, 1, 2}));
  std::vector<std::uint8_t> one_row{1, 2};
  scene::flip_rows(one_row, 2);
  EXPECT_EQ(one_row, (std::vector<std::uint8_t>{1, 2}));
}

TEST(SrgbPng, WrittenFileDecodesToTheSamePixels) {
  const test::TempFile file("render.png");
  const scene::RgbaImage image = pattern(23, 11);
  write_srgb_png(file.path(), image);
  const std::vector<unsigned char> bytes = read_file(file.path());
  const terrain::DecodedImage decoded = terrain::decode_image(bytes);
  EXPECT_EQ(decoded.format, terrain::ImageFormat::png);
  EXPECT_EQ(decoded.width, 23u);
  EXPECT_EQ(decoded.height, 11u);
  EXPECT_EQ(decoded.channels, 4u);
  EXPECT_EQ(decoded.bit_depth, 8u);
  EXPECT_EQ(decoded.samples8, image.rgba);
  // The sRGB chunk right after IHDR: length 1, "sRGB", intent 0 (perceptual), its CRC.
  const std::vector<unsigned char> srgb_chunk{0, 0, 0, 1, 's', 'R', 'G', 'B', 0, 0xAE, 0xCE, 0x1C, 0xE9};
  ASSERT_GT(bytes.size(), 33u + srgb_chunk.size());
  EXPECT_EQ(std::vector<unsigned char>(bytes.begin() + 33, bytes.begin() + 46), srgb_chunk);
  EXPECT_EQ(bytes, encode_srgb_png(image));
}

TEST(SrgbPng, ReplacesAnOldFileAndLeavesNoTemporaryBehind) {
  const test::TempFile file("out.png", "an older picture");
  write_srgb_png(file.path(), pattern(4, 4));
  write_srgb_png(file.path(), pattern(5, 3));
  EXPECT_EQ(terrain::decode_image(read_file(file.path())).width, 5u);
  std::size_t entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(file.path().parent_path())) {
    ++entries;
    EXPECT_EQ(entry.path().filename(), "out.png");
  }
  EXPECT_EQ(entries, 1u);
}

TEST(SrgbPng, AnUnwritablePathIsAnErrorNamingIt) {
  const test::TempFile file("x.png");
  const std::filesystem::path missing_folder = file.path().parent_path() / "no-such-folder" / "out.png";
  try {
    write_srgb_png(missing_folder, pattern(2, 2));
    FAIL() << "wrote into a folder that does not exist";
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.starts_with("cannot write " + missing_folder.string() + ": ")) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  EXPECT_FALSE(std::filesystem::exists(missing_folder.parent_path()));
}

TEST(SrgbPng, PixelsThatDoNotMatchTheSizeAreRefused) {
  scene::RgbaImage image = pattern(4, 4);
  image.rgba.pop_back();
  EXPECT_THROW(encode_srgb_png(image), std::invalid_argument);
  EXPECT_THROW(encode_srgb_png(scene::RgbaImage{}), std::invalid_argument);
}

}  // namespace
}  // namespace trailray::scene
