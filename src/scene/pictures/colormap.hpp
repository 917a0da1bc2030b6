#pragma once
// Colormaps for tracks coloured by a metric (DESIGN.md "Metrics ... the shader only looks colours
// up"), the qualitative palette that gives several solid tracks distinct colours, and the
// neutral colour of points without a value. Pure CPU tables: the track pass uploads a table as a
// 256x1 texture, the legend draws its colour bar from the same table, so both always agree.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

namespace trailray::scene {

// cover: three bands (open, under cover, below the ground: `--color-by cover` over 0..2).
enum class Colormap { turbo, viridis, magma, cividis, diverging, warm, cover };

inline constexpr std::size_t kColormapSize = 256;

// 256 sRGB colours, entry 0 for the range's minimum and 255 for its maximum.
using ColormapTable = std::array<glm::u8vec3, kColormapSize>;

// The table of a colormap (built once, cached; thread-safe).
const ColormapTable& colormap_table(Colormap map);

// The colour (sRGB, 0..1) of a position 0..1 along the map, interpolated between entries;
// clamped outside 0..1. NaN gives kMissingValueColorSrgb.
glm::vec3 colormap_color(Colormap map, float position);

// "turbo", "viridis", "magma", "cividis", "diverging", "warm" (pale yellow to deep red: the
// climb in thermals of `--color-by phase`).
std::string_view colormap_name(Colormap map);
std::optional<Colormap> parse_colormap(std::string_view name);  // exact lower-case names

// The classes of `--color-by cover` (sRGB): open sky yellow, under cover forest green, below
// the ground violet; Colormap::cover's three bands.
inline constexpr glm::vec3 kOpenColorSrgb{0.95f, 0.76f, 0.18f};
inline constexpr glm::vec3 kCoveredColorSrgb{0.10f, 0.55f, 0.25f};
inline constexpr glm::vec3 kBelowGroundColorSrgb{0.52f, 0.27f, 0.68f};

// Points without a value (no time, no heart rate): a neutral mid grey, sRGB.
inline constexpr glm::vec3 kMissingValueColorSrgb{0.62f, 0.62f, 0.62f};

// Points of a category rather than a value (track::kCategoryValue: gliding, for `--color-by
// phase`): a cool blue, unlike every warm climb colour and unlike the grey of no value, sRGB.
inline constexpr glm::vec3 kCategoryColorSrgb{0.16f, 0.47f, 0.86f};

// Qualitative palette for several solid tracks: distinct, colour-blind-safe hues that stand
// out on imagery and on the hypsometric tint; index wraps around.
glm::vec3 palette_color(std::size_t index);  // sRGB 0..1
std::size_t palette_size();

// `--color '#rrggbb'` (also '#rgb'); nullopt for anything else.
std::optional<glm::vec3> parse_hex_color(std::string_view text);

}  // namespace trailray::scene
