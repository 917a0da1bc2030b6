#include "app/options/camera_options.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <charconv>

namespace trailray::app {

void add_camera_options(CLI::App& cmd, CameraArgs& args) {
  cmd.add_option("--camera", args.camera, "Camera position and orientation (degrees, metres)")
      ->type_name("LAT,LON,ALT,HEADING,PITCH");
  cmd.add_option("--look-at", args.look_at, "Look at this point (degrees, metres)")->type_name("LAT,LON,ALT");
  cmd.add_option("--distance", args.distance_m, "With --look-at: camera distance from the point, metres (default 1000)")
      ->type_name("M");
  cmd.add_option("--heading", args.heading_deg, "With --look-at: degrees clockwise from north (default 0)")
      ->type_name("DEG");
  cmd.add_option("--pitch", args.pitch_deg, "With --look-at: degrees, negative looks down (default -45)")
      ->type_name("DEG");
  cmd.add_option("--fov", args.fov_deg, "Vertical field of view, degrees (default 45)")->type_name("DEG");
}

CameraRequest parse_camera_request(const CameraArgs& a, bool have_tracks) {
  if (!a.camera.empty() && !a.look_at.empty())
    throw CLI::ValidationError("--camera", "and --look-at exclude each other");
  if (a.look_at.empty() && (a.distance_m || a.heading_deg || a.pitch_deg))
    throw CLI::ValidationError("--distance/--heading/--pitch", "go with --look-at LAT,LON,ALT");
  if (!have_tracks && a.camera.empty() && a.look_at.empty())
    throw CLI::ValidationError(
        "camera",
        "without a track, say where to look from: --camera LAT,LON,ALT,HEADING,PITCH or --look-at LAT,LON,ALT "
        "[--distance M --heading DEG --pitch DEG]");
  CameraRequest request;
  if (!a.camera.empty()) {
    auto parsed = scene::parse_camera_option(a.camera);
    if (!parsed.ok()) throw CLI::ValidationError(parsed.error);  // it names the option
    request.placement = *parsed.value;
  } else if (!a.look_at.empty()) {
    auto parsed = scene::parse_look_at_option(a.look_at);
    if (!parsed.ok()) throw CLI::ValidationError(parsed.error);
    request.look_at = scene::LookAt{*parsed.value};
    if (a.distance_m) request.look_at->distance_m = *a.distance_m;
    if (a.heading_deg) request.look_at->heading_deg = *a.heading_deg;
    if (a.pitch_deg) request.look_at->pitch_deg = *a.pitch_deg;
  }
  return request;
}

std::optional<ImageSize> parse_image_size(std::string_view text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos) return std::nullopt;
  const auto number = [](std::string_view s) -> std::optional<std::uint32_t> {
    std::uint32_t v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || v == 0 || v > kMaxImageSide)
      return std::nullopt;
    return v;
  };
  const auto w = number(text.substr(0, x)), h = number(text.substr(x + 1));
  if (!w || !h) return std::nullopt;
  return ImageSize{*w, *h};
}

scene::Lens parse_lens(const std::string& size_text, double fov_deg) {
  const auto size = parse_image_size(size_text);
  if (!size)
    throw CLI::ValidationError(
        "--size", fmt::format("'{}' is not WxH with W and H in 1..{}, e.g. 1920x1080", size_text, kMaxImageSide));
  const scene::Lens lens{fov_deg, size->width, size->height};
  if (auto problem = scene::lens_problem(lens)) throw CLI::ValidationError("--fov/--size", *problem);
  return lens;
}

}  // namespace trailray::app
