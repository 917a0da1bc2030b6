// libFuzzer target for the text of `trailray video`: camera path files (--camera-path FILE) and
// the film's option values. The first byte picks the parser; each must answer or refuse with a
// message, never crash, and what it accepts must be sane:
//   path      parse_camera_path -> an error naming the file and a line, or keyframes with finite
//             values at rising film times, and camera_path_look finite between and beyond them
//   duration  parse_film_duration / parse_film_speed -> finite and positive, then
//             make_film_timing -> at most kMaxFilmFrames frames, or a refusal
//   instant   parse_film_instant (--from/--to) -> within the span
//   trail     parse_trail_mode -> a tail of finite positive length for DURATION

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "scene/film/camera_path.hpp"
#include "scene/film/film_timing.hpp"
#include "scene/film/film_tracks.hpp"

namespace {

using namespace trailray::scene;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "broken contract: %s\n", what);
    std::abort();
  }
}

bool finite_look(const FilmLook& l) {
  return std::isfinite(l.target.x) && std::isfinite(l.target.y) && std::isfinite(l.target.z) &&
         std::isfinite(l.heading_deg) && std::isfinite(l.pitch_deg) && std::isfinite(l.distance_m);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  // A three-hour flight's span for the options that need one.
  const TimeSpan span{1.7e9, 1.7e9 + 3 * 3600.0};
  switch (data[0] % 4) {
    case 0: {
      const auto keys = parse_camera_path(text, "shots.txt");
      if (!keys.ok()) {
        check(keys.error.rfind("shots.txt", 0) == 0, "a path error names the file");
        break;
      }
      check(!keys.value->empty(), "a path has a keyframe");
      double last = -INFINITY;
      for (const CameraKeyframe& k : *keys.value) {
        check(std::isfinite(k.film_s) && k.film_s > last, "keyframe times rise");
        check(finite_look(k.look), "keyframe finite");
        last = k.film_s;
      }
      const double first = keys.value->front().film_s;
      for (double t : {first - 1.0, first, (first + last) / 2, last, last + 1.0})
        check(finite_look(camera_path_look(*keys.value, t)), "interpolated look finite");
      break;
    }
    case 1: {
      const auto duration = parse_film_duration(text);
      if (duration.ok()) check(std::isfinite(*duration.value) && *duration.value > 0, "duration positive");
      const auto speed = parse_film_speed(text);
      if (speed.ok()) check(std::isfinite(*speed.value) && *speed.value > 0, "speed positive");
      for (double fps : {1.0, 30.0, 120.0}) {
        FilmLength length;
        if (duration.ok())
          length.duration_s = duration.value;
        else if (speed.ok())
          length.speed = speed.value;
        else
          break;
        const auto timing = make_film_timing(span, length, fps);
        if (timing.ok())
          check(timing.value->frames >= 1 && timing.value->frames <= kMaxFilmFrames, "frame count");
        else
          check(!timing.error.empty(), "a refusal says why");
      }
      break;
    }
    case 2: {
      const auto at = parse_film_instant(text, span, "--from");
      if (at.ok())
        check(*at.value >= span.start && *at.value <= span.end, "instant within the span");
      else
        check(!at.error.empty(), "a refusal says why");
      break;
    }
    default: {
      const auto trail = parse_trail_mode(text);
      if (trail.ok() && trail.value->kind == TrailKind::tail)
        check(std::isfinite(trail.value->tail_s) && trail.value->tail_s > 0, "tail positive");
      break;
    }
  }
  return 0;
}
