#pragma once
// Where the picture is taken from, as options spelled the same in `render` and `view`: --camera,
// --look-at, --distance, --heading, --pitch, --fov, and the image's --size.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "scene/camera/camera.hpp"
#include "scene/camera/first_camera.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

struct CameraArgs {
  std::string camera, look_at;
  std::optional<double> distance_m, heading_deg, pitch_deg;
  double fov_deg = scene::kDefaultVerticalFovDeg;
};
void add_camera_options(CLI::App& command, CameraArgs& args);

// The camera the options ask for: a placement, a look-at, or neither (frame the tracks).
using CameraRequest = scene::CameraRequest;
// Throws CLI::ValidationError naming the option: --camera with --look-at, --distance/--heading/
// --pitch without --look-at, no camera and no track (`have_tracks` false), unparsable text.
CameraRequest parse_camera_request(const CameraArgs& args, bool have_tracks);

// `--size WxH`: both within 1..kMaxImageSide. nullopt for anything else.
inline constexpr std::uint32_t kMaxImageSide = 16384;
struct ImageSize {
  std::uint32_t width = 0, height = 0;
};
std::optional<ImageSize> parse_image_size(std::string_view text);

// The lens of --size and --fov. Throws CLI::ValidationError naming the option.
scene::Lens parse_lens(const std::string& size, double fov_deg);

}  // namespace trailray::app
