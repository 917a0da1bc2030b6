#include "scene/text/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace trailray::scene {
namespace {

// A near-black panel at two-thirds opacity: white text on it keeps a contrast above 4.5:1 (the
// WCAG level for body text) even over white snow, while the terrain still shows through.
constexpr glm::u8vec4 kPanelColor{16, 18, 22, 176};
constexpr glm::u8vec4 kTextColor{255, 255, 255, 255};
constexpr glm::u8vec4 kQuietTextColor{200, 202, 206, 255};  // "+N more"
// A thin light frame around the bar and the ticks: the ends of magma (black) or of turbo (dark
// blue) would otherwise melt into the dark panel.
constexpr glm::u8vec4 kFrameColor{255, 255, 255, 140};

int scaled(int font_px, float factor, int minimum) {
  return std::max(minimum, static_cast<int>(std::lround(static_cast<float>(font_px) * factor)));
}

// Spacing shared by both legends, in pixels, from the text size.
struct PanelMetrics {
  int font_px, margin, padding, radius;
  int usable_width, usable_height;  // what the panel may take: the image less margins and reserve
};

PanelMetrics panel_metrics(std::uint32_t image_width, std::uint32_t image_height, const LegendOptions& options) {
  const int font_px = options.font_px > 0 ? options.font_px : legend_font_px(image_height);
  const int margin = scaled(font_px, 0.8f, 2);
  return {font_px,
          margin,
          scaled(font_px, 0.6f, 2),
          scaled(font_px, 0.4f, 1),
          static_cast<int>(image_width) - 2 * margin,
          static_cast<int>(image_height) - 2 * margin - std::max(options.reserved_bottom, 0)};
}

// The panel's rectangle: content of the given size plus padding, in the bottom-left corner.
PixelRect place_panel(std::uint32_t image_height, const PanelMetrics& m, const LegendOptions& options,
                      int content_width, int content_height) {
  const int width = content_width + 2 * m.padding, height = content_height + 2 * m.padding;
  return {m.margin, static_cast<int>(image_height) - m.margin - std::max(options.reserved_bottom, 0) - height, width,
          height};
}

glm::u8vec3 colormap_at(const ColormapTable& table, float position) {
  const float index = std::clamp(position, 0.0f, 1.0f) * static_cast<float>(kColormapSize - 1);
  const auto below = static_cast<std::size_t>(index);
  const std::size_t above = std::min(below + 1, kColormapSize - 1);
  const float fraction = index - static_cast<float>(below);
  const glm::vec3 color = glm::mix(glm::vec3(table[below]), glm::vec3(table[above]), fraction);
  return glm::u8vec3(glm::round(color));
}

void draw_frame(RgbaImage& image, const PixelRect& inner, int thickness, glm::u8vec4 color) {
  const PixelRect outer{inner.x - thickness, inner.y - thickness, inner.width + 2 * thickness,
                        inner.height + 2 * thickness};
  fill_rect(image, {outer.x, outer.y, outer.width, thickness}, color);
  fill_rect(image, {outer.x, inner.bottom(), outer.width, thickness}, color);
  fill_rect(image, {outer.x, inner.y, thickness, inner.height}, color);
  fill_rect(image, {inner.right(), inner.y, thickness, inner.height}, color);
}

// Where everything of a colour legend goes, measured but not drawn: draw_color_legend paints
// it, color_legend_panel reports its panel (so a picture can be framed around the legend that
// will be drawn, not around a guess of its size).
struct ColorLegendGeometry {
  PanelMetrics m;
  int frame, title_gap, bar_height, tick_length, tick_width, label_gap;
  TextExtent min_extent, max_extent, title_extent;
  int bar_width, content_width;
  std::string title;  // ellipsized to the panel
  PixelRect panel;
};

std::optional<ColorLegendGeometry> color_legend_geometry(std::uint32_t image_width, std::uint32_t image_height,
                                                         TextRasterizer& text, const ColorLegend& legend,
                                                         const LegendOptions& options) {
  ColorLegendGeometry g;
  g.m = panel_metrics(image_width, image_height, options);
  const int f = g.m.font_px;
  g.frame = scaled(f, 1.0f / 20.0f, 1);
  g.title_gap = scaled(f, 0.4f, 1);
  g.bar_height = scaled(f, 0.8f, 3);
  g.tick_length = scaled(f, 0.3f, 2);
  g.tick_width = scaled(f, 1.0f / 14.0f, 1);
  g.label_gap = scaled(f, 0.15f, 1);

  g.min_extent = text.measure(legend.min_label, f);
  g.max_extent = text.measure(legend.max_label, f);
  g.title_extent = text.measure(legend.title, f, FontWeight::bold);
  const bool has_title = !legend.title.empty();
  // The bar spans the panel; it is wide enough to set the two range labels apart.
  const int labels_width = g.min_extent.width + g.max_extent.width + f;
  g.bar_width = std::min(std::max({scaled(f, 12.0f, 1), labels_width, g.title_extent.width - 2 * g.frame}),
                         g.m.usable_width - 2 * g.m.padding - 2 * g.frame);
  g.content_width = g.bar_width + 2 * g.frame;
  const int content_height = (has_title ? g.title_extent.height() + g.title_gap : 0) + g.bar_height + 2 * g.frame +
                             g.tick_length + g.label_gap + g.min_extent.height();
  if (g.bar_width < labels_width || content_height + 2 * g.m.padding > g.m.usable_height) return std::nullopt;
  g.title = text.ellipsize(legend.title, std::numeric_limits<std::size_t>::max(), g.content_width, f, FontWeight::bold);
  g.panel = place_panel(image_height, g.m, options, g.content_width, content_height);
  return g;
}

// The same for a key of track names.
struct TrackKeyGeometry {
  PanelMetrics m;
  int swatch_width, swatch_thickness, swatch_gap;
  TextExtent line;
  int row_height;
  std::size_t listed = 0, hidden = 0;
  std::vector<std::string> names;  // the listed names, ellipsized
  std::string more;                // "+N more", or empty
  int row_count;
  PixelRect panel;
};

std::optional<TrackKeyGeometry> track_key_geometry(std::uint32_t image_width, std::uint32_t image_height,
                                                   TextRasterizer& text, const std::vector<TrackKeyEntry>& entries,
                                                   const LegendOptions& options) {
  if (entries.empty()) return std::nullopt;
  TrackKeyGeometry g;
  g.m = panel_metrics(image_width, image_height, options);
  const int f = g.m.font_px;
  g.swatch_width = scaled(f, 1.6f, 4);
  g.swatch_thickness = scaled(f, 0.35f, 2);
  g.swatch_gap = scaled(f, 0.5f, 2);
  g.line = text.measure("", f);
  g.row_height = g.line.height() + scaled(f, 0.3f, 1);
  const int max_name_width = g.m.usable_width - 2 * g.m.padding - g.swatch_width - g.swatch_gap;
  const int rows_that_fit = (g.m.usable_height - 2 * g.m.padding) / g.row_height;
  const int rows = std::min(rows_that_fit, static_cast<int>(kMaxTrackKeyRows));
  if (max_name_width < 2 * f || rows < 1) return std::nullopt;

  g.listed = entries.size() <= static_cast<std::size_t>(rows) ? entries.size() : static_cast<std::size_t>(rows - 1);
  g.hidden = entries.size() - g.listed;
  int names_width = 0;
  for (std::size_t i = 0; i < g.listed; ++i) {
    g.names.push_back(text.ellipsize(entries[i].name, kMaxTrackNameCodePoints, max_name_width, f));
    names_width = std::max(names_width, text.measure(g.names.back(), f).width);
  }
  g.more = g.hidden > 0 ? text.ellipsize("+" + std::to_string(g.hidden) + " more", kMaxTrackNameCodePoints,
                                         max_name_width + g.swatch_width + g.swatch_gap, f)
                        : std::string();
  const int more_width = text.measure(g.more, f).width;
  const int content_width = std::max(g.swatch_width + g.swatch_gap + names_width, more_width);
  g.row_count = static_cast<int>(g.listed) + (g.hidden > 0 ? 1 : 0);
  g.panel = place_panel(image_height, g.m, options, content_width, g.row_count * g.row_height);
  return g;
}

}  // namespace

int legend_font_px(std::uint32_t image_height) { return std::clamp(static_cast<int>(image_height / 45), 11, 40); }

std::string format_legend_value(double value, double span) {
  if (!std::isfinite(value)) return "n/a";
  const double magnitude = std::isfinite(span) && span > 0.0 ? span : std::abs(value);
  const int decimals = magnitude >= 10.0 ? 0 : magnitude >= 1.0 ? 1 : 2;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string text = buffer;
  if (text.front() == '-') {
    // "-0.0" is a rounding artefact, not a negative value.
    if (text.find_first_of("123456789") == std::string::npos) return text.substr(1);
    return "\u2212" + text.substr(1);
  }
  return text;
}

PixelRect color_legend_panel(std::uint32_t image_width, std::uint32_t image_height, TextRasterizer& text,
                             const ColorLegend& legend, const LegendOptions& options) {
  const auto g = color_legend_geometry(image_width, image_height, text, legend, options);
  return g ? g->panel : PixelRect{};
}

PixelRect track_key_panel(std::uint32_t image_width, std::uint32_t image_height, TextRasterizer& text,
                          const std::vector<TrackKeyEntry>& entries, const LegendOptions& options) {
  const auto g = track_key_geometry(image_width, image_height, text, entries, options);
  return g ? g->panel : PixelRect{};
}

LegendLayout draw_color_legend(RgbaImage& image, TextRasterizer& text, const ColorLegend& legend,
                               const LegendOptions& options) {
  const auto geometry = color_legend_geometry(image.width, image.height, text, legend, options);
  if (!geometry) return {};
  const ColorLegendGeometry& g = *geometry;
  const int f = g.m.font_px, frame = g.frame, bar_width = g.bar_width, bar_height = g.bar_height;
  const int tick_length = g.tick_length, tick_width = g.tick_width, content_width = g.content_width;

  LegendLayout layout;
  layout.drawn = true;
  layout.font_px = f;
  layout.panel = g.panel;
  fill_rounded_rect(image, layout.panel, g.m.radius, kPanelColor);
  const int left = layout.panel.x + g.m.padding;
  int top = layout.panel.y + g.m.padding;

  if (!legend.title.empty()) {
    layout.text_boxes.push_back(
        text.draw(image, g.title, left, top + g.title_extent.ascent, {f, FontWeight::bold, kTextColor}));
    top += g.title_extent.height() + g.title_gap;
  }

  layout.bar = {left + frame, top + frame, bar_width, bar_height};
  const ColormapTable& table = colormap_table(legend.map);
  for (int column = 0; column < bar_width; ++column) {
    const float position = bar_width > 1 ? static_cast<float>(column) / static_cast<float>(bar_width - 1) : 0.0f;
    const glm::u8vec3 color = colormap_at(table, position);
    fill_rect(image, {layout.bar.x + column, layout.bar.y, 1, bar_height}, glm::u8vec4(color, 255));
  }
  draw_frame(image, layout.bar, frame, kFrameColor);

  // Ticks hang from the frame at the ends and at the inner labels; the labels sit under them.
  const int tick_top = layout.bar.bottom() + frame;
  const int label_top = tick_top + tick_length + g.label_gap;
  const int baseline = label_top + g.min_extent.ascent;
  const auto tick_x = [&](double position) {
    return layout.bar.x + static_cast<int>(std::lround(std::clamp(position, 0.0, 1.0) * (bar_width - 1)));
  };
  const auto draw_tick = [&](int x) {
    const int tick_left = std::clamp(x - tick_width / 2, layout.bar.x - frame, layout.bar.right() + frame - tick_width);
    fill_rect(image, {tick_left, tick_top, tick_width, tick_length}, kFrameColor);
  };
  draw_tick(layout.bar.x - frame);
  draw_tick(layout.bar.right() + frame - 1);
  const TextStyle label_style{f, FontWeight::regular, kTextColor};
  layout.text_boxes.push_back(text.draw(image, legend.min_label, left, baseline, label_style));
  layout.text_boxes.push_back(
      text.draw(image, legend.max_label, left + content_width - g.max_extent.width, baseline, label_style));

  // Inner labels, centred on their ticks, kept when they clear every label already placed by
  // half an em (overlapping numbers would be unreadable).
  std::vector<PixelRect> taken(layout.text_boxes.end() - 2, layout.text_boxes.end());
  for (const LegendTick& tick : legend.ticks) {
    if (!std::isfinite(tick.position) || tick.position < 0.0 || tick.position > 1.0) continue;
    const int x = tick_x(tick.position);
    const TextExtent extent = text.measure(tick.label, f);
    const PixelRect box{x - extent.width / 2, label_top, extent.width, extent.height()};
    const PixelRect padded{box.x - f / 2, box.y, box.width + f, box.height};
    if (!PixelRect{left, label_top, content_width, extent.height()}.contains(box)) continue;
    if (std::any_of(taken.begin(), taken.end(), [&](const PixelRect& other) { return padded.intersects(other); }))
      continue;
    draw_tick(x);
    layout.text_boxes.push_back(text.draw(image, tick.label, box.x, baseline, label_style));
    taken.push_back(box);
  }
  return layout;
}

LegendLayout draw_track_key(RgbaImage& image, TextRasterizer& text, const std::vector<TrackKeyEntry>& entries,
                            const LegendOptions& options) {
  const auto geometry = track_key_geometry(image.width, image.height, text, entries, options);
  if (!geometry) return {};
  const TrackKeyGeometry& g = *geometry;
  const int f = g.m.font_px;

  LegendLayout layout;
  layout.hidden_entries = g.hidden;
  layout.drawn = true;
  layout.font_px = f;
  layout.panel = g.panel;
  fill_rounded_rect(image, layout.panel, g.m.radius, kPanelColor);
  const int left = layout.panel.x + g.m.padding;
  const TextStyle name_style{f, FontWeight::regular, kTextColor};
  for (int row = 0; row < g.row_count; ++row) {
    const int baseline =
        layout.panel.y + g.m.padding + row * g.row_height + (g.row_height - g.line.height()) / 2 + g.line.ascent;
    if (static_cast<std::size_t>(row) == g.listed) {
      layout.text_boxes.push_back(text.draw(image, g.more, left, baseline, {f, FontWeight::regular, kQuietTextColor}));
      break;
    }
    // A short thick line, as the track itself looks, centred on the lower-case letters' middle.
    const glm::vec3 requested = entries[static_cast<std::size_t>(row)].color_srgb;
    const glm::vec3 safe = glm::any(glm::isnan(requested)) ? kMissingValueColorSrgb : requested;
    const glm::vec3 color = glm::round(glm::clamp(safe, 0.0f, 1.0f) * 255.0f);
    const PixelRect swatch{left, baseline - scaled(f, 0.32f, 1) - g.swatch_thickness / 2, g.swatch_width,
                           g.swatch_thickness};
    const glm::u8vec4 rgba(glm::u8vec3(color), 255);
    if (entries[static_cast<std::size_t>(row)].dashed) {
      for (const auto& [start, length] : swatch_dashes(swatch.width))
        fill_rect(image, {swatch.x + start, swatch.y, length, swatch.height}, rgba);
    } else {
      fill_rounded_rect(image, swatch, g.swatch_thickness / 2, rgba);
    }
    layout.swatches.push_back(swatch);
    layout.text_boxes.push_back(text.draw(image, g.names[static_cast<std::size_t>(row)],
                                          left + g.swatch_width + g.swatch_gap, baseline, name_style));
  }
  return layout;
}

std::vector<std::pair<int, int>> swatch_dashes(int width) {
  // dash gap dash gap dash, the gaps half a dash: 4 + 2 + 4 + 2 + 4 parts.
  const auto at = [width](int part) { return width * part / 16; };
  return {{at(0), at(4) - at(0)}, {at(6), at(10) - at(6)}, {at(12), width - at(12)}};
}

}  // namespace trailray::scene
