#include "app/video/video_options.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace trailray::app {

void add_video_options(CLI::App& cmd, VideoArgs& args) {
  cmd.footer(
      "The replay runs from the tracks' first to their last time (--from/--to: a part), in --duration\n"
      "(default 60s) or at --speed. The camera follows the first track (--follow N) from behind and above\n"
      "(--distance, --pitch), circles the tracks (--camera-mode orbit), or stands still (--camera or\n"
      "--look-at, as in `render`). Ctrl-C stops and leaves no broken file.\n"
      "Exit status: 0 written, 1 a file, source, encoder or GL failed, 2 a usage error, 130 interrupted.");
  cmd.add_option("TRACK", args.tracks,
                 "Track files (GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON), folders of them, or patterns to replay")
      ->type_name("FILE")
      ->required();
  cmd.add_option("-o,--output", args.output, "The film: .mp4 (H.264) or .webm (VP9), written atomically")
      ->type_name("OUT.mp4");
  cmd.add_option("--frames-dir", args.frames_dir, "Write the frames as PNGs (frame_000001.png, ...) into DIR instead")
      ->type_name("DIR");
  cmd.add_flag("--force", args.force, "Replace an existing output file");
  cmd.add_option("--duration", args.duration, "Length of the film (default 60s)")->type_name("60s|1m30s");
  cmd.add_option("--speed", args.speed, "Replay seconds per film second instead of --duration")->type_name("50x");
  cmd.add_option("--fps", args.fps, "Frames per second (default 30)")->type_name("N");
  cmd.add_option("--from", args.from, "Start of the part filmed: a fraction, +offset, UTC time or date-time")
      ->type_name("WHEN");
  cmd.add_option("--to", args.to, "End of the part filmed (same forms as --from)")->type_name("WHEN");
  cmd.add_option("--camera-mode", args.mode,
                 "follow (default), orbit, fixed (with --camera/--look-at) or path (with --camera-path)")
      ->type_name("MODE");
  cmd.add_option("--camera-path", args.camera_path,
                 "Keyframes of the camera: lines 'WHEN camera LAT,LON,ALT,HEADING,PITCH' or 'WHEN look-at "
                 "LAT,LON,ALT DISTANCE HEADING PITCH' (WHEN: 0, 12s, 1m30s of film), interpolated smoothly")
      ->type_name("FILE");
  cmd.add_option("--follow", args.follow, "The track the camera follows, counted from 1 (default 1)")->type_name("N");
  cmd.add_option("--trail", args.trail,
                 "What of each track is drawn: all (the future ghosted, default), past, or a tail (10m)")
      ->type_name("all|past|DURATION");
  cmd.add_option("--align", args.align,
                 "Several tracks: clock (their real times, default) or start (each from its own start)")
      ->type_name("clock|start");
  cmd.add_option(
         "--gauges", args.gauges,
         "What is painted over the film: none, minimal (the clock) or full (the clock and gauges of "
         "the followed track: altitude, height above ground, speed, vario, glide; heart rate, cadence and power "
         "when recorded; default)")
      ->type_name("none|minimal|full");
  cmd.add_option("--photo-seconds", args.photo_seconds,
                 "With --photos: the film stops this many seconds at each photo's time and shows the photo "
                 "(default 2; 0: no stops, the photos stay pins)")
      ->type_name("S")
      ->check(CLI::Range(0.0, 60.0));
  cmd.add_flag("--fast", args.fast,
               "About 3x faster on a CPU: no sun shadows and no ambient occlusion (as --no-shadows --no-ssao); "
               "the relief then reads from the shading of the slopes alone");
  cmd.add_option("--crf", args.crf, "Quality: lower is better and larger (H.264 0..51, VP9 0..63; default 20)")
      ->type_name("N");
  add_picture_options(cmd, args,
                      {"Frame size in pixels, even numbers (default 1280x720)",
                       "Device pixels per pixel of the labels (default 1)",
                       "Seconds to wait for the terrain tiles of a frame (default 120)",
                       "Log the GL context, the cameras and the tiles"});
}

FilmCameraMode check_video_args(const VideoArgs& a) {
  if (a.output.empty() == a.frames_dir.empty())
    throw CLI::ValidationError("-o/--frames-dir", "give one: a film file (-o OUT.mp4) or a folder of frames");
  if (!a.duration.empty() && !a.speed.empty())
    throw CLI::ValidationError("--duration", "and --speed exclude each other");
  if (a.crf < 0 || a.crf > 63) throw CLI::ValidationError("--crf", fmt::format("'{}' is not in 0..63", a.crf));
  check_picture_args(a);
  if (a.align != "clock" && a.align != "start")
    throw CLI::ValidationError("--align", fmt::format("'{}' is not clock or start", a.align));
  if (a.follow < 1 || static_cast<std::size_t>(a.follow) > a.tracks.size())
    throw CLI::ValidationError("--follow",
                               fmt::format("'{}' is not a track number in 1..{}", a.follow, a.tracks.size()));
  const bool placed = !a.camera.camera.empty() || !a.camera.look_at.empty();
  FilmCameraMode mode = placed                   ? FilmCameraMode::fixed
                        : !a.camera_path.empty() ? FilmCameraMode::path
                                                 : FilmCameraMode::follow;
  if (a.mode == "path")
    mode = FilmCameraMode::path;
  else if (a.mode == "follow")
    mode = FilmCameraMode::follow;
  else if (a.mode == "orbit")
    mode = FilmCameraMode::orbit;
  else if (a.mode == "fixed")
    mode = FilmCameraMode::fixed;
  else if (!a.mode.empty())
    throw CLI::ValidationError("--camera-mode", fmt::format("'{}' is not follow, orbit, fixed or path", a.mode));
  if ((mode == FilmCameraMode::path) != !a.camera_path.empty())
    throw CLI::ValidationError("--camera-path", "a camera path goes with --camera-mode path (or none)");
  if (mode != FilmCameraMode::fixed && placed)
    throw CLI::ValidationError("--camera/--look-at", "place a fixed camera: they go with --camera-mode fixed");
  if (mode != FilmCameraMode::fixed && a.camera.pitch_deg &&
      !(*a.camera.pitch_deg < 0.0 && *a.camera.pitch_deg > -90.0))
    throw CLI::ValidationError("--pitch", fmt::format("'{}' is not a downward pitch in (-90, 0)", *a.camera.pitch_deg));
  if (mode != FilmCameraMode::fixed && a.camera.distance_m && !(*a.camera.distance_m > 0.0))
    throw CLI::ValidationError("--distance", fmt::format("'{}' is not a positive distance", *a.camera.distance_m));
  return mode;
}

}  // namespace trailray::app
