// The legend drawn into the picture: the colour bar against the colormap's table, its labels,
// the track key, and placement and clipping for many image sizes (pure CPU).

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/pictures/colormap.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/text/legend.hpp"
#include "scene/text/text_raster.hpp"

namespace trailray::scene {
namespace {

constexpr glm::u8vec4 kSnow{250, 250, 252, 255};
constexpr glm::u8vec4 kForest{34, 70, 38, 255};
constexpr glm::u8vec4 kMidGrey{120, 120, 120, 255};

RgbaImage filled(std::uint32_t width, std::uint32_t height, glm::u8vec4 color) {
  RgbaImage image{width, height, std::vector<std::uint8_t>(std::size_t{width} * height * 4)};
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = color.r;
    image.rgba[i + 1] = color.g;
    image.rgba[i + 2] = color.b;
    image.rgba[i + 3] = color.a;
  }
  return image;
}

glm::ivec3 rgb(const RgbaImage& image, int x, int y) {
  const auto p = image.pixel(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
  return {p[0], p[1], p[2]};
}

int max_difference(glm::ivec3 a, glm::ivec3 b) {
  const glm::ivec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z});
}

// Every pixel that differs from `before` lies inside `rect`.
void expect_changes_only_inside(const RgbaImage& before, const RgbaImage& after, const PixelRect& rect) {
  ASSERT_EQ(before.rgba.size(), after.rgba.size());
  for (std::uint32_t y = 0; y < after.height; ++y)
    for (std::uint32_t x = 0; x < after.width; ++x)
      if (before.pixel(x, y) != after.pixel(x, y)) {
        ASSERT_TRUE(rect.contains(int(x), int(y))) << "pixel " << x << "," << y << " changed outside the panel";
      }
}

void expect_same_rect(const PixelRect& a, const PixelRect& b) {
  EXPECT_TRUE(a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height)
      << a.x << "," << a.y << " " << a.width << "x" << a.height << " is not " << b.x << "," << b.y << " " << b.width
      << "x" << b.height;
}

bool inside_image(const PixelRect& rect, const RgbaImage& image) {
  return PixelRect{0, 0, int(image.width), int(image.height)}.contains(rect);
}

ColorLegend speed_legend() {
  return {"Speed (km/h)", Colormap::turbo, format_legend_value(0.0, 35.0), format_legend_value(35.0, 35.0), {}};
}

std::vector<TrackKeyEntry> tracks(std::size_t count) {
  std::vector<TrackKeyEntry> entries;
  for (std::size_t i = 0; i < count; ++i) entries.push_back({"Track " + std::to_string(i + 1), palette_color(i)});
  return entries;
}

// Writes the picture to $TRAILRAY_TEST_IMAGE_DIR/name when that is set, to look at.
void keep_image(const RgbaImage& image, const std::string& name) {
  if (const char* dir = std::getenv("TRAILRAY_TEST_IMAGE_DIR"))
    write_srgb_png(std::filesystem::path(dir) / name, image);
}

TEST(LegendFontPx, ScalesWithTheImageHeightWithinLimits) {
  EXPECT_EQ(legend_font_px(360), 11);
  EXPECT_EQ(legend_font_px(720), 16);
  EXPECT_EQ(legend_font_px(1080), 24);
  EXPECT_EQ(legend_font_px(2160), 40);
  EXPECT_EQ(legend_font_px(0), 11);
}

TEST(FormatLegendValue, DecimalsFollowTheRangeAndMinusIsTypographic) {
  EXPECT_EQ(format_legend_value(35.0, 35.0), "35");
  EXPECT_EQ(format_legend_value(1234.4, 800.0), "1234");
  EXPECT_EQ(format_legend_value(2.84, 6.0), "2.8");
  EXPECT_EQ(format_legend_value(-3.25, 6.0), "\u22123.2");  // printf rounds half to even here
  EXPECT_EQ(format_legend_value(-0.04, 6.0), "0.0");        // no "-0.0"
  EXPECT_EQ(format_legend_value(0.123, 0.5), "0.12");
  EXPECT_EQ(format_legend_value(12.0, 0.0), "12");  // an empty range: decimals from the value
  EXPECT_EQ(format_legend_value(std::nan(""), 1.0), "n/a");
}

TEST(ColorLegend, BarReproducesTheColormapLeftToRight) {
  TextRasterizer text;
  for (const Colormap map : {Colormap::turbo, Colormap::viridis, Colormap::magma, Colormap::diverging}) {
    RgbaImage image = filled(1280, 720, kSnow);
    ColorLegend legend = speed_legend();
    legend.map = map;
    const LegendLayout layout = draw_color_legend(image, text, legend);
    ASSERT_TRUE(layout.drawn);
    ASSERT_GT(layout.bar.width, 100);
    const ColormapTable& table = colormap_table(map);
    const int y = layout.bar.y + layout.bar.height / 2;
    const int last = layout.bar.width - 1;
    EXPECT_LE(max_difference(rgb(image, layout.bar.x, y), glm::ivec3(table[0])), 1) << colormap_name(map);
    EXPECT_LE(max_difference(rgb(image, layout.bar.x + last, y), glm::ivec3(table[255])), 1) << colormap_name(map);
    EXPECT_LE(max_difference(rgb(image, layout.bar.x + last / 2, y), glm::ivec3(table[128])), 4) << colormap_name(map);
    // Every column: the table's entry at that fraction of the bar (neighbouring entries differ by
    // a few levels, hence the tolerance), and the same in every row of the bar.
    for (int column = 0; column <= last; ++column) {
      const auto entry = static_cast<std::size_t>(std::lround(255.0 * column / last));
      const glm::ivec3 top = rgb(image, layout.bar.x + column, layout.bar.y);
      ASSERT_LE(max_difference(top, glm::ivec3(table[entry])), 8) << colormap_name(map) << " column " << column;
      ASSERT_EQ(top, rgb(image, layout.bar.x + column, layout.bar.bottom() - 1));
    }
  }
}

TEST(ColorLegend, BarIsOpaqueAndThePanelDarkensTheBackground) {
  TextRasterizer text;
  RgbaImage on_snow = filled(1280, 720, kSnow), on_forest = filled(1280, 720, kForest);
  const LegendLayout a = draw_color_legend(on_snow, text, speed_legend());
  const LegendLayout b = draw_color_legend(on_forest, text, speed_legend());
  ASSERT_TRUE(a.drawn);
  ASSERT_EQ(a.bar.x, b.bar.x);
  for (int x = a.bar.x; x < a.bar.right(); x += 7)
    EXPECT_EQ(rgb(on_snow, x, a.bar.y + 1), rgb(on_forest, x, a.bar.y + 1));
  // Inside the panel's padding, next to its left edge, halfway down: snow turns dark grey.
  const glm::ivec3 panel = rgb(on_snow, a.panel.x + 2, a.panel.y + a.panel.height / 2);
  EXPECT_LT(panel.r, 110);
  EXPECT_EQ(rgb(on_snow, a.panel.x - 1, a.panel.y + a.panel.height / 2), glm::ivec3(250, 250, 252));
}

TEST(ColorLegend, TextIsBrightInsideItsBoxesAndNothingChangesOutsideThePanel) {
  TextRasterizer text;
  const RgbaImage before = filled(1920, 1080, kMidGrey);
  RgbaImage image = before;
  const LegendLayout layout = draw_color_legend(image, text, speed_legend());
  ASSERT_TRUE(layout.drawn);
  EXPECT_EQ(layout.font_px, 24);
  ASSERT_EQ(layout.text_boxes.size(), 3u);  // title, minimum, maximum
  expect_changes_only_inside(before, image, layout.panel);
  for (const PixelRect& box : layout.text_boxes) {
    EXPECT_TRUE(layout.panel.contains(box));
    int bright = 0;
    for (int y = box.y; y < box.bottom(); ++y)
      for (int x = box.x; x < box.right(); ++x) bright += rgb(image, x, y).g > 220 ? 1 : 0;
    EXPECT_GT(bright, 10) << "box at " << box.x << "," << box.y;
  }
  // The title is above the bar, the labels under its two ends.
  const PixelRect &title = layout.text_boxes[0], &min = layout.text_boxes[1], &max = layout.text_boxes[2];
  EXPECT_LE(title.bottom(), layout.bar.y);
  EXPECT_GE(min.y, layout.bar.bottom());
  EXPECT_EQ(min.y, max.y);
  EXPECT_LE(std::abs(min.x - layout.bar.x), 3);
  EXPECT_LE(std::abs(max.right() - layout.bar.right()), 3);
  // Bottom-left corner, a margin away from the edges.
  EXPECT_GT(layout.panel.x, 0);
  EXPECT_LT(layout.panel.x, 40);
  EXPECT_GT(1080 - layout.panel.bottom(), 0);
  EXPECT_LT(1080 - layout.panel.bottom(), 40);
}

TEST(ColorLegend, DifferentLabelsDrawDifferentPixels) {
  TextRasterizer text;
  const RgbaImage before = filled(1280, 720, kForest);
  RgbaImage a = before, b = before, c = before;
  ColorLegend legend = speed_legend();
  draw_color_legend(a, text, legend);
  legend.max_label = "36";
  draw_color_legend(b, text, legend);
  legend.max_label = "35";
  legend.title = "Heart rate (bpm)";
  draw_color_legend(c, text, legend);
  EXPECT_NE(a.rgba, b.rgba);
  EXPECT_NE(a.rgba, c.rgba);
  RgbaImage again = before;
  draw_color_legend(again, text, speed_legend());
  EXPECT_EQ(a.rgba, again.rgba);
}

TEST(ColorLegend, InnerTicksAreLabelledWhereTheyFit) {
  TextRasterizer text;
  RgbaImage image = filled(1280, 720, kMidGrey);
  const ColorLegend legend{"Vertical speed (m/s)",
                           Colormap::diverging,
                           format_legend_value(-3.0, 6.0),
                           format_legend_value(3.0, 6.0),
                           {{0.5, "0"}, {0.02, "crowded"}, {1.5, "outside"}}};
  const LegendLayout layout = draw_color_legend(image, text, legend);
  ASSERT_TRUE(layout.drawn);
  ASSERT_EQ(layout.text_boxes.size(), 4u);  // title, ends, and only the tick at 0.5
  const PixelRect& zero = layout.text_boxes[3];
  const int bar_middle = layout.bar.x + (layout.bar.width - 1) / 2;
  EXPECT_LE(std::abs(zero.x + zero.width / 2 - bar_middle), 2);
  EXPECT_EQ(zero.y, layout.text_boxes[1].y);
}

TEST(ColorLegend, LongTitlesWidenThePanelUpToTheImageThenAreCut) {
  TextRasterizer text;
  ColorLegend legend = speed_legend();
  legend.title = "Power output averaged over thirty seconds (watts per kilogram)";
  RgbaImage wide = filled(1920, 1080, kMidGrey);
  const LegendLayout a = draw_color_legend(wide, text, legend);
  ASSERT_TRUE(a.drawn);
  EXPECT_GE(a.bar.width, text.measure(legend.title, a.font_px, FontWeight::bold).width - 4);
  RgbaImage narrow = filled(320, 240, kMidGrey);
  const LegendLayout b = draw_color_legend(narrow, text, legend);
  ASSERT_TRUE(b.drawn);
  EXPECT_TRUE(inside_image(b.panel, narrow));
  EXPECT_LE(b.text_boxes[0].width, b.panel.width);
}

TEST(TrackKey, OneSwatchOfEachColourBesideEachName) {
  TextRasterizer text;
  const RgbaImage before = filled(1280, 720, kSnow);
  RgbaImage image = before;
  const std::vector<TrackKeyEntry> entries{
      {"Zürich", {0.90f, 0.10f, 0.10f}}, {"Škofja Loka", {0.10f, 0.45f, 0.95f}}, {"Αθήνα", {0.95f, 0.75f, 0.05f}}};
  const LegendLayout layout = draw_track_key(image, text, entries);
  ASSERT_TRUE(layout.drawn);
  ASSERT_EQ(layout.swatches.size(), 3u);
  ASSERT_EQ(layout.text_boxes.size(), 3u);
  EXPECT_EQ(layout.hidden_entries, 0u);
  expect_changes_only_inside(before, image, layout.panel);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const glm::ivec3 color = glm::ivec3(glm::round(entries[i].color_srgb * 255.0f));
    // Pixels of exactly the track's colour: only in its swatch, and plenty of them.
    int inside = 0, outside = 0;
    for (int y = 0; y < int(image.height); ++y)
      for (int x = 0; x < int(image.width); ++x)
        if (rgb(image, x, y) == color) (layout.swatches[i].contains(x, y) ? inside : outside) += 1;
    EXPECT_GT(inside, layout.swatches[i].width * layout.swatches[i].height / 2) << entries[i].name;
    EXPECT_EQ(outside, 0) << entries[i].name;
    // The name is on the swatch's row, right of it.
    const PixelRect& name = layout.text_boxes[i];
    EXPECT_GT(name.x, layout.swatches[i].right());
    EXPECT_GT(layout.swatches[i].y, name.y);
    EXPECT_LT(layout.swatches[i].bottom(), name.bottom());
  }
  EXPECT_LT(layout.swatches[0].y, layout.swatches[1].y);  // in the given order, top to bottom
}

// A route's swatch is dashed, as the route is drawn: its colour along the swatch's middle row
// stops twice (two gaps), a track's does not; the name is whole, with nothing added.
TEST(TrackKey, ARoutesSwatchIsDashed) {
  TextRasterizer text;
  RgbaImage image = filled(1280, 720, kSnow);
  const glm::vec3 red{0.9f, 0.1f, 0.1f}, blue{0.1f, 0.45f, 0.95f};
  const LegendLayout layout = draw_track_key(image, text, {{"Flight", red, false}, {"Planned", blue, true}});
  ASSERT_EQ(layout.swatches.size(), 2u);
  const auto runs = [&](std::size_t i, glm::vec3 c) {
    const glm::ivec3 color = glm::ivec3(glm::round(c * 255.0f));
    const PixelRect& s = layout.swatches[i];
    const int y = s.y + s.height / 2;
    int count = 0;
    bool in = false;
    for (int x = s.x - 1; x <= s.right() + 1; ++x) {
      const bool now = rgb(image, x, y) == color;
      count += now && !in;
      in = now;
    }
    return count;
  };
  EXPECT_EQ(runs(0, red), 1);
  EXPECT_EQ(runs(1, blue), 3);
  EXPECT_EQ(swatch_dashes(32), (std::vector<std::pair<int, int>>{{0, 8}, {12, 8}, {24, 8}}));
}

TEST(TrackKey, NonAsciiNamesDrawTheirLetters) {
  TextRasterizer text;
  RgbaImage with = filled(640, 360, kForest), without = filled(640, 360, kForest);
  draw_track_key(with, text, {{"Zürich", {1, 0, 0}}});
  draw_track_key(without, text, {{"Zurich", {1, 0, 0}}});
  EXPECT_NE(with.rgba, without.rgba);  // the diaeresis
  for (const char32_t c : decode_utf8("Zürich Škofja Loka")) EXPECT_TRUE(text.has_glyph(c));
}

TEST(TrackKey, ManyTracksEndInAMoreRow) {
  TextRasterizer text;
  RgbaImage image = filled(1280, 720, kMidGrey);
  const LegendLayout layout = draw_track_key(image, text, tracks(20));
  ASSERT_TRUE(layout.drawn);
  EXPECT_EQ(layout.swatches.size() + 1, kMaxTrackKeyRows);
  EXPECT_EQ(layout.hidden_entries, 20u - layout.swatches.size());
  EXPECT_EQ(layout.text_boxes.size(), kMaxTrackKeyRows);
  // Exactly twelve fit without a "+N more" row.
  RgbaImage twelve = filled(1280, 720, kMidGrey);
  EXPECT_EQ(draw_track_key(twelve, text, tracks(12)).swatches.size(), 12u);
  // A short image lists fewer rows, and still sums up the rest.
  RgbaImage short_image = filled(1280, 150, kMidGrey);
  const LegendLayout few = draw_track_key(short_image, text, tracks(20));
  ASSERT_TRUE(few.drawn);
  EXPECT_LT(few.swatches.size(), 6u);
  EXPECT_EQ(few.swatches.size() + few.hidden_entries, 20u);
  EXPECT_TRUE(inside_image(few.panel, short_image));
}

TEST(TrackKey, LongNamesAreCut) {
  TextRasterizer text;
  const std::string long_name(80, 'x');
  RgbaImage image = filled(1920, 1080, kMidGrey);
  const LegendLayout layout = draw_track_key(image, text, {{long_name, {1, 1, 0}}});
  ASSERT_TRUE(layout.drawn);
  const int full = text.measure(long_name, layout.font_px).width;
  const int cut = text.measure(std::string(39, 'x') + "…", layout.font_px).width;
  EXPECT_EQ(layout.text_boxes[0].width, cut);
  EXPECT_LT(layout.text_boxes[0].width, full);
  // On a narrow image the name is cut to the image's width instead.
  RgbaImage narrow = filled(200, 200, kMidGrey);
  const LegendLayout small = draw_track_key(narrow, text, {{long_name, {1, 1, 0}}});
  ASSERT_TRUE(small.drawn);
  EXPECT_TRUE(inside_image(small.panel, narrow));
  EXPECT_LT(small.text_boxes[0].width, cut);
}

TEST(Legends, StackWhenOneReservesTheBottom) {
  TextRasterizer text;
  RgbaImage image = filled(1280, 720, kMidGrey);
  const LegendLayout bar = draw_color_legend(image, text, speed_legend());
  const LegendLayout key =
      draw_track_key(image, text, tracks(3), {.font_px = 0, .reserved_bottom = int(image.height) - bar.panel.y});
  ASSERT_TRUE(key.drawn);
  EXPECT_LT(key.panel.bottom(), bar.panel.y);
  EXPECT_FALSE(key.panel.intersects(bar.panel));
}

TEST(Legends, StayInsideTheImageForManySizesAndVanishWhenTheyCannotFit) {
  TextRasterizer text;
  const std::vector<glm::uvec2> sizes{{0, 0},       {1, 1},       {32, 32},    {64, 48},    {100, 100},
                                      {160, 90},    {200, 40},    {320, 180},  {640, 360},  {1280, 720},
                                      {1920, 1080}, {3840, 2160}, {2000, 100}, {100, 2000}, {4000, 30}};
  for (const glm::uvec2 size : sizes) {
    SCOPED_TRACE(std::to_string(size.x) + "x" + std::to_string(size.y));
    const RgbaImage before = filled(size.x, size.y, kForest);
    RgbaImage image = before;
    const LegendLayout bar = draw_color_legend(image, text, speed_legend());
    // Measured without drawing: the same panel (what the framing keeps clear), or none.
    expect_same_rect(color_legend_panel(size.x, size.y, text, speed_legend()), bar.drawn ? bar.panel : PixelRect{});
    if (bar.drawn) {
      EXPECT_TRUE(inside_image(bar.panel, image));
      expect_changes_only_inside(before, image, bar.panel);
    } else {
      EXPECT_EQ(image.rgba, before.rgba);
    }
    image = before;
    const LegendLayout key = draw_track_key(image, text, tracks(15));
    expect_same_rect(track_key_panel(size.x, size.y, text, tracks(15)), key.drawn ? key.panel : PixelRect{});
    if (key.drawn) {
      EXPECT_TRUE(inside_image(key.panel, image));
      expect_changes_only_inside(before, image, key.panel);
    } else {
      EXPECT_EQ(image.rgba, before.rgba);
    }
    // From 640x360 up, both always fit.
    if (size.x >= 320 && size.y >= 180) {
      EXPECT_TRUE(bar.drawn);
      EXPECT_TRUE(key.drawn);
    }
    if (size.x <= 32 || size.y <= 32) {
      EXPECT_FALSE(bar.drawn);
    }
  }
}

TEST(Legends, ExamplePictures) {
  // A scene-like background: snow on the left, forest on the right, a hard edge between, so the
  // panel's readability on both shows; kept in $TRAILRAY_TEST_IMAGE_DIR to look at.
  TextRasterizer text;
  for (const glm::uvec2 size : {glm::uvec2(640, 360), glm::uvec2(1920, 1080), glm::uvec2(3840, 2160)}) {
    RgbaImage image = filled(size.x, size.y, kForest);
    for (std::uint32_t y = 0; y < size.y; ++y)
      for (std::uint32_t x = 0; x < size.x / 8; ++x)
        std::copy_n(&kSnow.r, 4, &image.rgba[(std::size_t{y} * size.x + x) * 4]);
    const LegendLayout bar = draw_color_legend(image, text,
                                               {"Vertical speed (m/s)",
                                                Colormap::diverging,
                                                format_legend_value(-3.2, 6.0),
                                                format_legend_value(2.8, 6.0),
                                                {{3.2 / 6.0, "0"}}});
    ASSERT_TRUE(bar.drawn);
    std::vector<TrackKeyEntry> entries{{"Zürich – Uetliberg", palette_color(0)},
                                       {"Škofja Loka loop", palette_color(1)},
                                       {"Hochtour über den Großvenediger-Nordgrat mit Abstieg", palette_color(2)}};
    const LegendLayout key =
        draw_track_key(image, text, entries, {.font_px = 0, .reserved_bottom = int(size.y) - bar.panel.y});
    ASSERT_TRUE(key.drawn);
    keep_image(image, "legend-" + std::to_string(size.x) + "x" + std::to_string(size.y) + ".png");
  }
  // Magma starts black: its frame must keep the bar's left end apart from the dark panel.
  RgbaImage altitude = filled(1280, 720, kSnow);
  ASSERT_TRUE(draw_color_legend(altitude, text, {"Altitude (m)", Colormap::magma, "412", "2967", {}}).drawn);
  keep_image(altitude, "legend-magma-1280x720.png");
}

}  // namespace
}  // namespace trailray::scene
