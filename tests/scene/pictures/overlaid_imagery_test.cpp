// The overlay composited over the imagery (scene/pictures/overlaid_imagery.hpp) and a heatmap's colours
// (scene/pictures/heatmap_colors.hpp), from sources whose tiles are known pixel by pixel.
#include "scene/pictures/overlaid_imagery.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "scene/pictures/heatmap_colors.hpp"

using namespace trailray;
using terrain::ImageTile;
using terrain::TileId;
using terrain::TileResult;
using terrain::TileStatus;

namespace {

// Tiles of 4 x 4 pixels painted by a function of (tile, col, row), up to `max_zoom`.
class PaintedSource final : public terrain::ImagerySource {
 public:
  PaintedSource(int max_zoom, std::function<glm::u8vec4(const TileId&, int, int)> paint, TileStatus status = TileStatus::ok)
      : paint_(std::move(paint)), status_(status) {
    info_.name = "painted";
    info_.max_zoom = max_zoom;
  }
  const terrain::SourceInfo& info() const override { return info_; }
  TileResult<ImageTile> load(const TileId& tile, terrain::StopToken) override {
    ++loads;
    last = tile;
    TileResult<ImageTile> r;
    r.status = status_;
    if (status_ == TileStatus::failed) r.error = "painted: broken";
    if (status_ != TileStatus::ok) return r;
    r.tile.id = tile;
    r.tile.width = r.tile.height = 4;
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col) {
        const glm::u8vec4 c = paint_(tile, col, row);
        r.tile.rgba.insert(r.tile.rgba.end(), {c.r, c.g, c.b, c.a});
      }
    return r;
  }
  int loads = 0;
  TileId last;

 private:
  terrain::SourceInfo info_;
  std::function<glm::u8vec4(const TileId&, int, int)> paint_;
  TileStatus status_;
};

glm::u8vec4 pixel(const ImageTile& t, int col, int row) {
  const std::size_t i = (static_cast<std::size_t>(row) * t.width + static_cast<std::size_t>(col)) * 4;
  return {t.rgba[i], t.rgba[i + 1], t.rgba[i + 2], t.rgba[i + 3]};
}

}  // namespace

TEST(OverlaidImagery, TheOverlayIsCompositedOverTheBaseByItsAlpha) {
  auto base = std::make_unique<PaintedSource>(10, [](const TileId&, int, int) { return glm::u8vec4{0, 0, 200, 255}; });
  // Opaque red in the left column, half-transparent green in the second, nothing elsewhere.
  auto over = std::make_unique<PaintedSource>(10, [](const TileId&, int col, int) {
    return col == 0 ? glm::u8vec4{255, 0, 0, 255} : col == 1 ? glm::u8vec4{0, 255, 0, 128} : glm::u8vec4{9, 9, 9, 0};
  });
  scene::OverlaidImagery source(std::move(base), std::move(over));
  const TileResult<ImageTile> r = source.load({5, 3, 4}, {});
  ASSERT_EQ(r.status, TileStatus::ok);
  EXPECT_EQ(pixel(r.tile, 0, 2), (glm::u8vec4{255, 0, 0, 255}));
  const glm::u8vec4 half = pixel(r.tile, 1, 2);
  EXPECT_EQ(half.r, 0);
  EXPECT_NEAR(half.g, 128, 1);
  EXPECT_NEAR(half.b, 100, 1);  // 200 * (1 - 128/255)
  EXPECT_EQ(half.a, 255);
  EXPECT_EQ(pixel(r.tile, 3, 0), (glm::u8vec4{0, 0, 200, 255}));  // the base alone
}

TEST(OverlaidImagery, WithoutBaseTheOverlayGoesOutAloneAndOpacityScalesIt) {
  auto over = std::make_unique<PaintedSource>(8, [](const TileId&, int col, int) {
    return col < 2 ? glm::u8vec4{255, 0, 0, 200} : glm::u8vec4{0, 0, 0, 0};
  });
  scene::OverlaidImagery source(nullptr, std::move(over), 0.5f);
  EXPECT_EQ(source.info().max_zoom, 8);
  const TileResult<ImageTile> r = source.load({3, 1, 1}, {});
  ASSERT_EQ(r.status, TileStatus::ok);
  EXPECT_EQ(pixel(r.tile, 0, 0), (glm::u8vec4{255, 0, 0, 100}));
  EXPECT_EQ(pixel(r.tile, 3, 0).a, 0);  // the tint shows through
}

TEST(OverlaidImagery, FinerThanTheOverlaysLevelsItsAncestorIsEnlarged) {
  auto base = std::make_unique<PaintedSource>(14, [](const TileId&, int, int) { return glm::u8vec4{10, 10, 10, 255}; });
  // Each pixel says where it is: red = 60 * column, green = 60 * row.
  auto over_source = std::make_unique<PaintedSource>(10, [](const TileId&, int col, int row) {
    return glm::u8vec4{static_cast<std::uint8_t>(60 * col), static_cast<std::uint8_t>(60 * row), 0, 255};
  });
  PaintedSource* over = over_source.get();
  scene::OverlaidImagery source(std::move(base), std::move(over_source));
  EXPECT_EQ(source.info().max_zoom, 14);
  // Tile 11/(2*5+1)/(2*7) is the north-east quarter of 10/5/7: its 4 x 4 pixels enlarge columns 2..3
  // and rows 0..1 of the ancestor, each twice.
  const TileResult<ImageTile> r = source.load({11, 11, 14}, {});
  ASSERT_EQ(r.status, TileStatus::ok);
  EXPECT_EQ(over->last, (TileId{10, 5, 7}));
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) {
      const glm::u8vec4 p = pixel(r.tile, col, row);
      EXPECT_EQ(p.r, 60 * (2 + col / 2)) << col << "," << row;
      EXPECT_EQ(p.g, 60 * (row / 2)) << col << "," << row;
    }
}

TEST(OverlaidImagery, AFailingOverlayIsReportedAndAFailingBaseLeavesTheOverlay) {
  {
    auto base = std::make_unique<PaintedSource>(10, [](const TileId&, int, int) { return glm::u8vec4{1, 1, 1, 255}; });
    auto over = std::make_unique<PaintedSource>(10, [](const TileId&, int, int) { return glm::u8vec4{}; }, TileStatus::failed);
    scene::OverlaidImagery source(std::move(base), std::move(over));
    const auto r = source.load({2, 1, 1}, {});
    EXPECT_EQ(r.status, TileStatus::failed);
    EXPECT_NE(r.error.find("broken"), std::string::npos);
  }
  {
    auto base = std::make_unique<PaintedSource>(10, [](const TileId&, int, int) { return glm::u8vec4{}; }, TileStatus::failed);
    auto over = std::make_unique<PaintedSource>(10, [](const TileId&, int, int) { return glm::u8vec4{7, 7, 7, 255}; });
    scene::OverlaidImagery source(std::move(base), std::move(over));
    const auto r = source.load({2, 1, 1}, {});
    ASSERT_EQ(r.status, TileStatus::ok);
    EXPECT_EQ(pixel(r.tile, 1, 1), (glm::u8vec4{7, 7, 7, 255}));
  }
  {
    auto base = std::make_unique<PaintedSource>(10, [](const TileId&, int, int) { return glm::u8vec4{}; }, TileStatus::failed);
    auto over = std::make_unique<PaintedSource>(10, [](const TileId&, int, int) { return glm::u8vec4{}; }, TileStatus::no_data);
    scene::OverlaidImagery source(std::move(base), std::move(over));
    EXPECT_EQ(source.load({2, 1, 1}, {}).status, TileStatus::failed);  // nothing hides the base's failure
  }
}

TEST(HeatmapColors, ALogScaleFromOneToTheLargestCountAndZeroTransparent) {
  scene::HeatmapPalette p;
  p.max_count = 1000;
  EXPECT_EQ(scene::heatmap_position(p, 1), 0.0f);
  EXPECT_NEAR(scene::heatmap_position(p, 10), 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(scene::heatmap_position(p, 100), 2.0 / 3.0, 1e-6);
  EXPECT_EQ(scene::heatmap_position(p, 5000), 1.0f);
  EXPECT_EQ(scene::heatmap_rgba(p, 0).a, 0);
  EXPECT_EQ(scene::heatmap_rgba(p, std::nan("")).a, 0);
  EXPECT_LT(scene::heatmap_rgba(p, 1).a, scene::heatmap_rgba(p, 1000).a);
  EXPECT_EQ(scene::heatmap_rgba(p, 1000).a, 255);
  const glm::vec3 end = scene::colormap_color(p.colormap, 1.0f);
  EXPECT_EQ(scene::heatmap_rgba(p, 1000).r, static_cast<std::uint8_t>(std::lround(end.r * 255)));
  p.scale = scene::HeatmapScale::linear;
  EXPECT_NEAR(scene::heatmap_position(p, 500.5), 0.5, 1e-6);
  const scene::ColorLegend legend = scene::heatmap_legend({scene::Colormap::warm, scene::HeatmapScale::log, 1000},
                                                          "Tracks", 50);
  EXPECT_EQ(legend.title, "Tracks per cell (50 m)");
  EXPECT_EQ(legend.min_label, "1");
  EXPECT_EQ(legend.max_label, "1000");
  ASSERT_EQ(legend.ticks.size(), 2u);  // 10 and 100
  EXPECT_EQ(legend.ticks[1].label, "100");
  EXPECT_NEAR(legend.ticks[1].position, 2.0 / 3.0, 1e-6);
  EXPECT_FALSE(scene::parse_heatmap_scale("Log"));
}
