#include "app/pictures/render_options.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

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
  add_picture_options(
      cmd, args,
      {"Image size in pixels (default 1920x1080)",
       "Device pixels per pixel of the labels, for high-DPI output: 2 draws labels twice as large (default 1)",
       "Seconds to wait for terrain tiles (default 120)", "Log the GL context, camera, sun and tiles"},
      [&] {
        cmd.add_flag("--profile", args.profile,
                     "After the tiles are loaded, render --frames times and print CPU and GPU time per pass to "
                     "standard error");
        cmd.add_option("--frames", args.frames, "With --profile: frames to render and average (default 1)")
            ->type_name("N");
      });
}

void check_render_args(const RenderArgs& a) {
  if (a.frames < 1 || a.frames > kMaxProfiledFrames)
    throw CLI::ValidationError("--frames",
                               fmt::format("'{}' is not a frame count in 1..{}", a.frames, kMaxProfiledFrames));
  if (a.frames > 1 && !a.profile) throw CLI::ValidationError("--frames", "goes with --profile");
  check_picture_args(a);
}

}  // namespace trailray::app
