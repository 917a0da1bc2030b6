#pragma once
// What a film shows over the picture (`trailray video --overlay`), painted on the CPU like the
// legend: a clock (the replay's time, UTC) top left, and with `full` a panel of gauges top right
// for each followed track (altitude, height above the ground, speed, vertical speed, glide
// ratio; heart rate, cadence and power when recorded), read at the track's position for the frame.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/pictures/image_paint.hpp"
#include "scene/tracks/replay_position.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/text/text_raster.hpp"
#include "scene/tracks/track_set.hpp"

namespace trailray::scene {

enum class OverlayLevel { none, minimal, full };
// `--overlay none|minimal|full`; errors name --overlay.
Result<OverlayLevel> parse_overlay_level(std::string_view text);

// A track's numbers at a position, interpolated between its points (NaN: not recorded there).
struct GaugeReadings {
  std::string name;
  double altitude_m, ground_m, speed_kmh, vspeed_ms, heart_rate_bpm, cadence_rpm, power_w;
};
GaugeReadings gauge_readings(const Track& track, const TrackPosition& at);

// The gauges as lines of text ("Alt 1 234 m", ...), those with a value only.
std::vector<std::string> gauge_lines(const GaugeReadings& readings);

// "2024-06-18 10:15:42 UTC".
std::string film_clock_text(double time_unix_s);

// Paints the clock (`minimal`, `full`), the gauge panels (`full`) and the map data's
// `attribution` (`minimal`, `full`; bottom right, when not empty) into `image`; returns the
// rectangles it covered (labels keep out of them).
std::vector<PixelRect> draw_film_overlay(RgbaImage& image, TextRasterizer& text, OverlayLevel level, double time_unix_s,
                                         const std::vector<GaugeReadings>& gauges, const std::string& attribution = {});

// The rectangles draw_film_overlay would cover, without drawing.
std::vector<PixelRect> film_overlay_panels(std::uint32_t width, std::uint32_t height, TextRasterizer& text,
                                           OverlayLevel level, const std::vector<GaugeReadings>& gauges,
                                           const std::string& attribution = {});

}  // namespace trailray::scene
