#include "app/view/film_settings.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "app/options/camera_options.hpp"
#include "app/video/film_writer.hpp"

namespace trailray::app::view {

std::string default_film_path(const scene::TrackSet& tracks) {
  if (tracks.empty()) return "trailray-film.mp4";
  std::string name;
  for (const char c : tracks[0].name) {
    const bool plain =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
    // A run of other characters (spaces, slashes, UTF-8 bytes) becomes one '-'.
    if (plain)
      name += c;
    else if (!name.empty() && name.back() != '-')
      name += '-';
  }
  while (!name.empty() && (name.back() == '-' || name.back() == '.')) name.pop_back();
  while (!name.empty() && (name.front() == '-' || name.front() == '.')) name.erase(name.begin());
  return name.empty() ? std::string("trailray-film.mp4") : "trailray-film-" + name + ".mp4";
}

std::size_t film_follow_track(const FilmSettings& settings, const scene::TrackSet& tracks, int preferred) {
  const auto timed = [&](int i) {
    return i >= 0 && static_cast<std::size_t>(i) < tracks.size() && !tracks[static_cast<std::size_t>(i)].is_route &&
           tracks[static_cast<std::size_t>(i)].start_time().has_value();
  };
  if (timed(settings.follow_track)) return static_cast<std::size_t>(settings.follow_track);
  if (timed(preferred)) return static_cast<std::size_t>(preferred);
  for (std::size_t i = 0; i < tracks.size(); ++i)
    if (timed(static_cast<int>(i))) return i;
  return 0;
}

std::string film_settings_problem(const FilmSettings& s) {
  if (s.path.empty()) return "no file to write the film to";
  if (!codec_for_path(s.path)) return s.path + ": a film is .mp4 (H.264) or .webm (VP9)";
  std::error_code error;
  if (std::filesystem::exists(s.path, error) && !s.replace)
    return s.path + ": already exists (tick 'replace' to write over it)";
  if (s.width < 16 || s.height < 16 || s.width > static_cast<int>(kMaxImageSide) ||
      s.height > static_cast<int>(kMaxImageSide) || s.width % 2 != 0 || s.height % 2 != 0)
    return fmt::format("{}x{}: a film's size is even numbers of pixels, 16..{}", s.width, s.height, kMaxImageSide);
  if (!(s.seconds > 0.0 && s.seconds <= 24 * 3600.0)) return fmt::format("{} s: not a film's length", s.seconds);
  if (!(s.fps >= 1.0 && s.fps <= 120.0)) return fmt::format("{} frames per second: not in 1..120", s.fps);
  return {};
}

}  // namespace trailray::app::view
