#pragma once
// `trailray render`: a picture of the terrain (and, from issue 5, the tracks) as an sRGB PNG.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace trailray::app {

void add_render_command(CLI::App& app, int& exit_code);

// `--size WxH`: both within 1..16384. nullopt for anything else.
struct ImageSize {
  std::uint32_t width = 0, height = 0;
};
std::optional<ImageSize> parse_image_size(std::string_view text);

}  // namespace trailray::app
