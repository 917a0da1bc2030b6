#pragma once
// A film's clock (`trailray video`): which part of the tracks' time it shows, how many frames,
// and the replay time of each frame. The first frame shows the start, the last the end.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "scene/camera/camera.hpp"
#include "scene/tracks/replay_position.hpp"

namespace trailray::scene {

struct FilmTiming {
  TimeSpan span;           // replay times filmed (unix seconds)
  std::size_t frames = 1;  // at least 1
  double fps = 30.0;

  // The replay time of frame `i` (0..frames-1): evenly spread from span.start to span.end.
  double time_of(std::size_t i) const;
  double film_seconds() const { return static_cast<double>(frames) / fps; }
  // Replay seconds per film second.
  double speed() const { return (span.end - span.start) / film_seconds(); }
};

// The film's length: its own length in seconds, or a time factor (replay seconds per film
// second); exactly one is set.
struct FilmLength {
  std::optional<double> duration_s;
  std::optional<double> speed;
};

// frames = round(duration * fps) (at least 1), or round(span / speed * fps). Error text names
// the option for a length or rate that is not positive, or more than kMaxFilmFrames frames.
inline constexpr std::size_t kMaxFilmFrames = 1000000;
Result<FilmTiming> make_film_timing(const TimeSpan& span, const FilmLength& length, double fps);

// Option text. "60s", "90", "1m30s", "2m", "1h": seconds of film.
Result<double> parse_film_duration(std::string_view text);
// "50x" or "50": replay seconds per film second.
Result<double> parse_film_speed(std::string_view text);
// --from/--to: a fraction of the span ("0.25"), an offset from its start ("+10m", "+1h30m"), a
// UTC time of day on the span's first day ("13:45", "13:45:30") or a UTC date-time
// ("2024-07-01T13:45:00Z"). The result lies within the span. `option` names it in errors.
Result<double> parse_film_instant(std::string_view text, const TimeSpan& span, std::string_view option);

}  // namespace trailray::scene
