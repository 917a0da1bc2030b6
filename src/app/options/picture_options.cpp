#include "app/options/picture_options.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>

namespace trailray::app {

void add_picture_options(CLI::App& cmd, PictureArgs& args, const PictureHelp& help,
                         const std::function<void()>& extra) {
  cmd.add_option("--size", args.size, help.size)->type_name("WxH");
  cmd.add_option("--pixel-ratio", args.pixel_ratio, help.pixel_ratio)->type_name("R");
  add_camera_options(cmd, args.camera);
  cmd.add_option("--timeout", args.timeout_s, help.timeout)->type_name("S");
  cmd.add_flag("--verbose", args.verbose, help.verbose);
  add_shading_options(cmd, args.style);
  if (extra) extra();
  add_scene_options(cmd, args);
}

void check_picture_args(const PictureArgs& a) {
  if (!(a.pixel_ratio >= 0.25 && a.pixel_ratio <= 8.0))
    throw CLI::ValidationError("--pixel-ratio", fmt::format("'{}' is not a ratio in 0.25..8", a.pixel_ratio));
  check_timeout_option(a.timeout_s);
}

void check_timeout_option(double seconds) {
  if (!(seconds > 0.0) || !std::isfinite(seconds))
    throw CLI::ValidationError("--timeout", fmt::format("'{}' is not a positive number of seconds", seconds));
}

std::chrono::milliseconds timeout_of(const PictureArgs& a) {
  return std::chrono::milliseconds(static_cast<long long>(a.timeout_s * 1000.0));
}

}  // namespace trailray::app
