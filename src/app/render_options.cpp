#include "app/render_options.hpp"

#include <fmt/format.h>

#include <cmath>

#include "app/track_options.hpp"

namespace trailray::app {
namespace {

constexpr int kMaxProfiledFrames = 10000;

}  // namespace

void add_render_options(CLI::App& cmd, RenderArgs& args) {
  cmd.footer(
      "Without tracks a camera is needed (--camera or --look-at). Heading 0 looks north, pitch 0 is\n"
      "horizontal, negative looks down. The sun stands where it was at --time (default: local solar noon\n"
      "on the track's first day, today's for tracks without times, now without tracks). Where no source\n"
      "covers the view a neutral ground"
      " is drawn at the tracks' lowest point.\n"
      "Exit status: 0 written, 1 a file, source or GL failed, 2 a usage error.");
  cmd.add_option(
         "TRACK", args.tracks,
         "Track files (GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON), folders of them, or patterns ('flights/*.igc') to "
         "draw (the view frames them)")
      ->type_name("FILE");
  cmd.add_option("-o,--output", args.output, "The PNG to write (atomically)")->required()->type_name("OUT.png");
  cmd.add_option("--size", args.size, "Image size in pixels (default 1920x1080)")->type_name("WxH");
  cmd.add_option("--pixel-ratio", args.pixel_ratio,
                 "Device pixels per pixel of the labels, for high-DPI output: 2 draws labels twice as large "
                 "(default 1)")
      ->type_name("R");
  add_camera_options(cmd, args.camera);
  cmd.add_option("--timeout", args.timeout_s, "Seconds to wait for terrain tiles (default 120)")->type_name("S");
  cmd.add_flag("--verbose", args.verbose, "Log the GL context, camera, sun and tiles");
  add_shading_options(cmd, args.style);
  cmd.add_flag("--profile", args.profile,
               "After the tiles are loaded, render --frames times and print CPU and GPU time per pass to "
               "standard error");
  cmd.add_option("--frames", args.frames, "With --profile: frames to render and average (default 1)")->type_name("N");
  add_terrain_options(cmd, args.terrain);
  add_imagery_option(cmd, args.terrain);
  add_track_style_options(cmd, args.style);
  add_waypoint_options(cmd, args.waypoints);
  add_airspace_options(cmd, args.airspace);
  add_label_options(cmd, args.style);
  add_read_options(cmd, args.read);
  add_cleaning_options(cmd, args.analysis);
}

void check_render_args(const RenderArgs& a) {
  if (a.frames < 1 || a.frames > kMaxProfiledFrames)
    throw CLI::ValidationError("--frames",
                               fmt::format("'{}' is not a frame count in 1..{}", a.frames, kMaxProfiledFrames));
  if (a.frames > 1 && !a.profile) throw CLI::ValidationError("--frames", "goes with --profile");
  if (!(a.pixel_ratio >= 0.25 && a.pixel_ratio <= 8.0))
    throw CLI::ValidationError("--pixel-ratio", fmt::format("'{}' is not a ratio in 0.25..8", a.pixel_ratio));
  if (!(a.timeout_s > 0.0) || !std::isfinite(a.timeout_s))
    throw CLI::ValidationError("--timeout", fmt::format("'{}' is not a positive number of seconds", a.timeout_s));
}

std::chrono::milliseconds timeout_of(const RenderArgs& a) {
  return std::chrono::milliseconds(static_cast<long long>(a.timeout_s * 1000.0));
}

}  // namespace trailray::app
