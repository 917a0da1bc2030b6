// Pure CPU: the colormap tables, the palette and colour parsing (no GL context).
#include "scene/pictures/colormap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace trailray::scene {
namespace {

constexpr float kStep = 1.0f / 255.0f;  // one 8-bit step

glm::vec3 hex(std::uint32_t rgb) {
  return glm::vec3(static_cast<float>((rgb >> 16) & 0xff), static_cast<float>((rgb >> 8) & 0xff),
                   static_cast<float>(rgb & 0xff)) /
         255.0f;
}

std::string describe(const glm::vec3& c) {
  return "(" + std::to_string(c.r * 255.0f) + ", " + std::to_string(c.g * 255.0f) + ", " +
         std::to_string(c.b * 255.0f) + ")";
}

// Every channel within `steps` 8-bit steps.
::testing::AssertionResult near_color(const glm::vec3& actual, const glm::vec3& expected, float steps) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(actual[c] - expected[c]) > steps * kStep + 1e-6f) {
      return ::testing::AssertionFailure()
             << describe(actual) << " is not within " << steps << " steps of " << describe(expected);
    }
  }
  return ::testing::AssertionSuccess();
}

// CIE L* (D65) of an sRGB colour: the lightness a viewer perceives.
double lightness(const glm::vec3& srgb) {
  const auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  const double y = 0.2126729 * linear(srgb.r) + 0.7151522 * linear(srgb.g) + 0.0721750 * linear(srgb.b);
  return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

glm::vec3 entry(Colormap map, std::size_t i) { return glm::vec3(colormap_table(map)[i]) / 255.0f; }

TEST(Colormap, KnownColoursAtTheEndsAndTheMiddle) {
  // matplotlib's viridis, magma and cividis; Google's Turbo.
  EXPECT_TRUE(near_color(colormap_color(Colormap::viridis, 0.0f), hex(0x440154), 1.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::viridis, 0.5f), hex(0x21918c), 2.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::viridis, 1.0f), hex(0xfde725), 1.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::magma, 0.0f), hex(0x000004), 1.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::magma, 0.5f), hex(0xb63679), 2.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::magma, 1.0f), hex(0xfcfdbf), 1.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::cividis, 0.0f), hex(0x00224e), 1.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::cividis, 0.5f), hex(0x7c7b78), 2.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::cividis, 1.0f), hex(0xfee838), 1.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::turbo, 0.0f), {0.19f, 0.07f, 0.23f}, 2.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::turbo, 1.0f), {0.48f, 0.02f, 0.01f}, 2.0f));
  // Turbo's middle is a yellowish green: bright green, some red, little blue.
  const glm::vec3 middle = colormap_color(Colormap::turbo, 0.5f);
  EXPECT_GT(middle.g, 0.95f) << describe(middle);
  EXPECT_GT(middle.r, 0.5f) << describe(middle);
  EXPECT_LT(middle.r, 0.75f) << describe(middle);
  EXPECT_LT(middle.b, 0.3f) << describe(middle);
  // A quarter in: Turbo is blue-cyan (blue above red), three quarters in orange (red above blue).
  const glm::vec3 quarter = colormap_color(Colormap::turbo, 0.25f);
  const glm::vec3 three_quarters = colormap_color(Colormap::turbo, 0.75f);
  EXPECT_GT(quarter.b, quarter.r + 0.5f) << describe(quarter);
  EXPECT_GT(three_quarters.r, three_quarters.b + 0.5f) << describe(three_quarters);
}

TEST(Colormap, SequentialMapsGetLighterAllTheWay) {
  for (Colormap map : {Colormap::viridis, Colormap::magma, Colormap::cividis}) {
    double previous = lightness(entry(map, 0));
    const double first = previous;
    for (std::size_t i = 1; i < kColormapSize; ++i) {
      const double l = lightness(entry(map, i));
      // 8-bit rounding can take back a few hundredths of a unit between neighbours, no more.
      EXPECT_GE(l, previous - 0.1) << colormap_name(map) << " entry " << i;
      if (i % 16 == 0) {
        EXPECT_GT(l, lightness(entry(map, i - 16)) + 2.0) << colormap_name(map) << " entry " << i;
      }
      previous = l;
    }
    EXPECT_GT(previous - first, 75.0) << colormap_name(map) << ": dark to light";
  }
}

TEST(Colormap, DivergingIsBlueWhiteRedAndBalanced) {
  EXPECT_TRUE(near_color(colormap_color(Colormap::diverging, 0.0f), hex(0x2166ac), 2.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::diverging, 0.5f), hex(0xf7f7f7), 3.0f));
  EXPECT_TRUE(near_color(colormap_color(Colormap::diverging, 1.0f), hex(0xb2182b), 2.0f));
  const double white = lightness(colormap_color(Colormap::diverging, 0.5f));
  EXPECT_GT(white, 95.0);
  for (int k = 0; k < 64; ++k) {
    const float t = static_cast<float>(k) / 128.0f;  // 0 .. just below 0.5
    const glm::vec3 sink = colormap_color(Colormap::diverging, t);
    const glm::vec3 climb = colormap_color(Colormap::diverging, 1.0f - t);
    // Blue on the sink side, red on the climb side (up to where both are nearly white).
    if (t < 0.45f) {
      EXPECT_GT(sink.b, sink.r + 0.02f) << t;
      EXPECT_GT(climb.r, climb.b + 0.02f) << t;
    }
    // Equally far from zero looks equally strong: lightness within a few units on both sides.
    EXPECT_NEAR(lightness(sink), lightness(climb), 5.0) << t;
    // Lightness rises towards the white middle on both sides.
    const float next = static_cast<float>(k + 1) / 128.0f;
    EXPECT_LT(lightness(sink), lightness(colormap_color(Colormap::diverging, next)) + 0.1) << t;
    EXPECT_LT(lightness(climb), lightness(colormap_color(Colormap::diverging, 1.0f - next)) + 0.1) << t;
  }
}

TEST(Colormap, NaNGivesTheMissingColourAndPositionsAreClamped) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (Colormap map : {Colormap::turbo, Colormap::viridis, Colormap::magma, Colormap::cividis, Colormap::diverging}) {
    EXPECT_EQ(colormap_color(map, kNaN), kMissingValueColorSrgb) << colormap_name(map);
    EXPECT_EQ(colormap_color(map, -0.5f), colormap_color(map, 0.0f)) << colormap_name(map);
    EXPECT_EQ(colormap_color(map, -kInf), colormap_color(map, 0.0f)) << colormap_name(map);
    EXPECT_EQ(colormap_color(map, 7.0f), colormap_color(map, 1.0f)) << colormap_name(map);
    EXPECT_EQ(colormap_color(map, kInf), colormap_color(map, 1.0f)) << colormap_name(map);
  }
  // The missing colour is a neutral grey, not a colour any map could mean.
  EXPECT_EQ(kMissingValueColorSrgb.r, kMissingValueColorSrgb.g);
  EXPECT_EQ(kMissingValueColorSrgb.g, kMissingValueColorSrgb.b);
}

TEST(Colormap, ColourIsTheTableInterpolated) {
  for (Colormap map : {Colormap::turbo, Colormap::magma, Colormap::diverging}) {
    for (std::size_t i : {std::size_t{0}, std::size_t{1}, std::size_t{100}, std::size_t{254}, std::size_t{255}}) {
      const float at = static_cast<float>(i) / 255.0f;
      EXPECT_TRUE(near_color(colormap_color(map, at), entry(map, i), 0.01f)) << colormap_name(map) << " " << i;
    }
    for (std::size_t i : {std::size_t{0}, std::size_t{77}, std::size_t{254}}) {
      const float between = (static_cast<float>(i) + 0.5f) / 255.0f;
      const glm::vec3 mean = (entry(map, i) + entry(map, i + 1)) * 0.5f;
      EXPECT_TRUE(near_color(colormap_color(map, between), mean, 0.01f)) << colormap_name(map) << " " << i;
    }
  }
}

TEST(Colormap, TablesAreBuiltOnceAndSharedAcrossThreads) {
  std::vector<const ColormapTable*> seen(8, nullptr);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t) {
    threads.emplace_back([&seen, t] { seen[t] = &colormap_table(Colormap::diverging); });
  }
  for (std::thread& t : threads) t.join();
  for (const ColormapTable* table : seen) EXPECT_EQ(table, &colormap_table(Colormap::diverging));
  EXPECT_NE(&colormap_table(Colormap::turbo), &colormap_table(Colormap::viridis));
}

TEST(Colormap, NamesRoundTrip) {
  for (Colormap map : {Colormap::turbo, Colormap::viridis, Colormap::magma, Colormap::cividis, Colormap::diverging}) {
    const auto parsed = parse_colormap(colormap_name(map));
    ASSERT_TRUE(parsed) << colormap_name(map);
    EXPECT_EQ(*parsed, map);
  }
  EXPECT_EQ(colormap_name(Colormap::diverging), "diverging");
  EXPECT_FALSE(parse_colormap("Turbo"));
  EXPECT_FALSE(parse_colormap("jet"));
  EXPECT_FALSE(parse_colormap(""));
  EXPECT_FALSE(parse_colormap("viridis "));
}

TEST(Palette, DistinctColoursThatWrapAround) {
  ASSERT_GE(palette_size(), 8u);
  for (std::size_t i = 0; i < palette_size(); ++i) {
    for (std::size_t j = i + 1; j < palette_size(); ++j) {
      const glm::vec3 d = (palette_color(i) - palette_color(j)) * 255.0f;
      EXPECT_GT(glm::length(d), 60.0f) << i << " and " << j << " look alike";
    }
    EXPECT_EQ(palette_color(i + palette_size()), palette_color(i));
  }
  // The first track is a strong red-orange: it stands out on green and grey terrain.
  const glm::vec3 first = palette_color(0);
  EXPECT_GT(first.r, 0.75f) << describe(first);
  EXPECT_GT(first.r, first.g + 0.3f) << describe(first);
  EXPECT_GT(first.r, first.b + 0.5f) << describe(first);
  // Neither black nor yellow nor grey (lost in shadows, on snow, on rock): every entry is saturated.
  for (std::size_t i = 0; i < palette_size(); ++i) {
    const glm::vec3 c = palette_color(i);
    const float spread = std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b});
    EXPECT_GT(spread, 0.3f) << i << " " << describe(c);
    EXPECT_FALSE(c.r > 0.8f && c.g > 0.8f && c.b < 0.5f) << i << " is yellow";
  }
}

TEST(HexColor, ParsesSixAndThreeDigitForms) {
  const auto a = parse_hex_color("#ff8000");
  ASSERT_TRUE(a);
  EXPECT_EQ(*a, hex(0xff8000));
  const auto b = parse_hex_color("#1A2b3C");
  ASSERT_TRUE(b);
  EXPECT_EQ(*b, hex(0x1a2b3c));
  const auto c = parse_hex_color("#f80");
  ASSERT_TRUE(c);
  EXPECT_EQ(*c, hex(0xff8800)) << "each digit doubled, as in CSS";
  const auto white = parse_hex_color("#FFF");
  ASSERT_TRUE(white);
  EXPECT_EQ(*white, glm::vec3(1.0f));
  const auto black = parse_hex_color("#000000");
  ASSERT_TRUE(black);
  EXPECT_EQ(*black, glm::vec3(0.0f));
}

TEST(HexColor, RejectsEverythingElse) {
  for (const char* bad : {"", "#", "ff8000", "#ff800", "#ff80000", "#ff8000ff", "#gg0000", "# ff800", "#ff8000 ",
                          " #ff8000", "#f8", "#f800", "red", "0xff8000", "##f80", "#-12345"}) {
    EXPECT_FALSE(parse_hex_color(bad)) << '"' << bad << '"';
  }
}

}  // namespace
}  // namespace trailray::scene
