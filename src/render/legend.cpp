#include "render/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace trailray::render {
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

PanelMetrics panel_metrics(const RgbaImage& image, const LegendOptions& options) {
  const int font_px = options.font_px > 0 ? options.font_px : legend_font_px(image.height);
  const int margin = scaled(font_px, 0.8f, 2);
  return {font_px,
          margin,
          scaled(font_px, 0.6f, 2),
          scaled(font_px, 0.4f, 1),
          static_cast<int>(image.width) - 2 * margin,
          static_cast<int>(image.height) - 2 * margin - std::max(options.reserved_bottom, 0)};
}

// The panel's rectangle: content of the given size plus padding, in the bottom-left corner.
PixelRect place_panel(const RgbaImage& image, const PanelMetrics& m, const LegendOptions& options, int content_width,
                      int content_height) {
  const int width = content_width + 2 * m.padding, height = content_height + 2 * m.padding;
  return {m.margin, static_cast<int>(image.height) - m.margin - std::max(options.reserved_bottom, 0) - height, width,
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

LegendLayout draw_color_legend(RgbaImage& image, TextRasterizer& text, const ColorLegend& legend,
                               const LegendOptions& options) {
  const PanelMetrics m = panel_metrics(image, options);
  const int f = m.font_px;
  const int frame = scaled(f, 1.0f / 20.0f, 1);
  const int title_gap = scaled(f, 0.4f, 1), bar_height = scaled(f, 0.8f, 3);
  const int tick_length = scaled(f, 0.3f, 2), tick_width = scaled(f, 1.0f / 14.0f, 1);
  const int label_gap = scaled(f, 0.15f, 1);

  const TextExtent min_extent = text.measure(legend.min_label, f), max_extent = text.measure(legend.max_label, f);
  const TextExtent title_extent = text.measure(legend.title, f, FontWeight::bold);
  const bool has_title = !legend.title.empty();
  // The bar spans the panel; it is wide enough to set the two range labels apart.
  const int labels_width = min_extent.width + max_extent.width + f;
  const int bar_width = std::min(std::max({scaled(f, 12.0f, 1), labels_width, title_extent.width - 2 * frame}),
                                 m.usable_width - 2 * m.padding - 2 * frame);
  const int content_width = bar_width + 2 * frame;
  const int content_height = (has_title ? title_extent.height() + title_gap : 0) + bar_height + 2 * frame +
                             tick_length + label_gap + min_extent.height();
  if (bar_width < labels_width || content_height + 2 * m.padding > m.usable_height) return {};
  const std::string title =
      text.ellipsize(legend.title, std::numeric_limits<std::size_t>::max(), content_width, f, FontWeight::bold);

  LegendLayout layout;
  layout.drawn = true;
  layout.font_px = f;
  layout.panel = place_panel(image, m, options, content_width, content_height);
  fill_rounded_rect(image, layout.panel, m.radius, kPanelColor);
  const int left = layout.panel.x + m.padding;
  int top = layout.panel.y + m.padding;

  if (has_title) {
    layout.text_boxes.push_back(
        text.draw(image, title, left, top + title_extent.ascent, {f, FontWeight::bold, kTextColor}));
    top += title_extent.height() + title_gap;
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
  const int label_top = tick_top + tick_length + label_gap;
  const int baseline = label_top + min_extent.ascent;
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
      text.draw(image, legend.max_label, left + content_width - max_extent.width, baseline, label_style));

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
  if (entries.empty()) return {};
  const PanelMetrics m = panel_metrics(image, options);
  const int f = m.font_px;
  const int swatch_width = scaled(f, 1.6f, 4), swatch_thickness = scaled(f, 0.35f, 2);
  const int swatch_gap = scaled(f, 0.5f, 2);
  const TextExtent line = text.measure("", f);
  const int row_height = line.height() + scaled(f, 0.3f, 1);
  const int max_name_width = m.usable_width - 2 * m.padding - swatch_width - swatch_gap;
  const int rows_that_fit = (m.usable_height - 2 * m.padding) / row_height;
  const int rows = std::min(rows_that_fit, static_cast<int>(kMaxTrackKeyRows));
  if (max_name_width < 2 * f || rows < 1) return {};

  LegendLayout layout;
  const auto listed =
      entries.size() <= static_cast<std::size_t>(rows) ? entries.size() : static_cast<std::size_t>(rows - 1);
  layout.hidden_entries = entries.size() - listed;
  std::vector<std::string> names;
  int names_width = 0;
  for (std::size_t i = 0; i < listed; ++i) {
    names.push_back(text.ellipsize(entries[i].name, kMaxTrackNameCodePoints, max_name_width, f));
    names_width = std::max(names_width, text.measure(names.back(), f).width);
  }
  const std::string more = layout.hidden_entries > 0
                               ? text.ellipsize("+" + std::to_string(layout.hidden_entries) + " more",
                                                kMaxTrackNameCodePoints, max_name_width + swatch_width + swatch_gap, f)
                               : std::string();
  const int more_width = text.measure(more, f).width;
  const int content_width = std::max(swatch_width + swatch_gap + names_width, more_width);
  const int row_count = static_cast<int>(listed) + (layout.hidden_entries > 0 ? 1 : 0);

  layout.drawn = true;
  layout.font_px = f;
  layout.panel = place_panel(image, m, options, content_width, row_count * row_height);
  fill_rounded_rect(image, layout.panel, m.radius, kPanelColor);
  const int left = layout.panel.x + m.padding;
  const TextStyle name_style{f, FontWeight::regular, kTextColor};
  for (int row = 0; row < row_count; ++row) {
    const int baseline = layout.panel.y + m.padding + row * row_height + (row_height - line.height()) / 2 + line.ascent;
    if (static_cast<std::size_t>(row) == listed) {
      layout.text_boxes.push_back(text.draw(image, more, left, baseline, {f, FontWeight::regular, kQuietTextColor}));
      break;
    }
    // A short thick line, as the track itself looks, centred on the lower-case letters' middle.
    const glm::vec3 requested = entries[row].color_srgb;
    const glm::vec3 safe = glm::any(glm::isnan(requested)) ? kMissingValueColorSrgb : requested;
    const glm::vec3 color = glm::round(glm::clamp(safe, 0.0f, 1.0f) * 255.0f);
    const PixelRect swatch{left, baseline - scaled(f, 0.32f, 1) - swatch_thickness / 2, swatch_width, swatch_thickness};
    fill_rounded_rect(image, swatch, swatch_thickness / 2, glm::u8vec4(glm::u8vec3(color), 255));
    layout.swatches.push_back(swatch);
    layout.text_boxes.push_back(text.draw(image, names[row], left + swatch_width + swatch_gap, baseline, name_style));
  }
  return layout;
}

}  // namespace trailray::render
