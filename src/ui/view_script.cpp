#include "ui/view_script.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "track/io/parse_util.hpp"

namespace trailray::ui {
namespace {

using Kind = ScriptCommand::Kind;

struct Syntax {
  std::string_view name;
  Kind kind;
  int numbers;  // how many numbers follow (after the path)
  bool non_negative;
  std::string_view usage;
  bool path = false;  // a path first
};

constexpr Syntax kSyntax[] = {
    {"orbit", Kind::orbit, 2, false, "orbit DX DY"},
    {"pan", Kind::pan, 2, false, "pan DX DY"},
    {"zoom", Kind::zoom, 1, false, "zoom STEPS"},
    {"select", Kind::select, 1, true, "select TRACK_INDEX"},
    {"select-waypoint", Kind::select_waypoint, 1, true, "select-waypoint WAYPOINT_INDEX"},
    {"print-waypoints", Kind::print_waypoints, 0, false, "print-waypoints"},
    {"hover", Kind::hover, 2, false, "hover X Y"},
    {"print-hover", Kind::print_hover, 0, false, "print-hover"},
    {"print-marker", Kind::print_marker, 0, false, "print-marker"},
    {"print-camera", Kind::print_camera, 0, false, "print-camera"},
    {"print-state", Kind::print_state, 0, false, "print-state"},
    {"play", Kind::play, 1, true, "play SECONDS"},
    {"speed", Kind::speed, 1, true, "speed X"},
    {"wait", Kind::wait, 1, true, "wait FRAMES"},
    {"screenshot", Kind::screenshot, 0, false, "screenshot PATH", true},
    {"window-screenshot", Kind::window_screenshot, 0, false, "window-screenshot PATH", true},
    {"hide-panels", Kind::hide_panels, 0, false, "hide-panels"},
    {"print-frame-times", Kind::print_frame_times, 0, false, "print-frame-times"},
    {"record-film", Kind::record_film, 1, true, "record-film PATH SECONDS", true},
    {"start-film", Kind::start_film, 1, true, "start-film PATH SECONDS", true},
    {"cancel-film", Kind::cancel_film, 0, false, "cancel-film"},
    {"film-size", Kind::film_size, 2, true, "film-size WIDTH HEIGHT"},
    {"film-fps", Kind::film_fps, 1, true, "film-fps N"},
    {"film-camera", Kind::film_camera, 0, false, "film-camera follow|orbit|fixed", true},
};

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// Through the track readers' parse_double: the browser's libc++ has no from_chars for doubles.
bool parse_number(std::string_view text, double& value) {
  const std::optional<double> parsed = track::parse_double(text);
  if (!parsed) return false;
  value = *parsed;
  return true;
}

}  // namespace

ViewScript parse_view_script(std::string_view text, const std::string& file) {
  ViewScript script{file, {}};
  int number = 0;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
    ++number;
    const auto w = words(line);
    if (w.empty() || w[0].front() == '#') continue;
    const auto fail = [&](const std::string& why) { throw ScriptError(fmt::format("{}:{}: {}", file, number, why)); };
    const Syntax* syntax = nullptr;
    for (const Syntax& s : kSyntax)
      if (s.name == w[0]) syntax = &s;
    if (syntax == nullptr)
      fail(
          fmt::format("unknown command '{}' (orbit, pan, zoom, select, select-waypoint, print-waypoints, hover, "
                      "print-hover, print-marker, "
                      "print-camera, print-state, play, speed, wait, screenshot, window-screenshot, hide-panels, "
                      "print-frame-times, record-film, start-film, cancel-film, film-size, film-fps, film-camera)",
                      w[0]));
    ScriptCommand c;
    c.kind = syntax->kind;
    c.line = number;
    const std::size_t first = syntax->path ? 2 : 1;  // the first number's word
    if (w.size() != first + static_cast<std::size_t>(syntax->numbers))
      fail(fmt::format("expected '{}'", syntax->usage));
    if (syntax->path) c.path = std::string(w[1]);
    if (c.kind == Kind::film_camera && c.path != "follow" && c.path != "orbit" && c.path != "fixed")
      fail(fmt::format("'{}' is not a film camera (expected '{}')", c.path, syntax->usage));
    double values[2] = {0.0, 0.0};
    for (int i = 0; i < syntax->numbers; ++i) {
      const std::string_view word = w[first + static_cast<std::size_t>(i)];
      if (!parse_number(word, values[i]))
        fail(fmt::format("'{}' is not a number (expected '{}')", word, syntax->usage));
      if (syntax->non_negative && values[i] < 0.0)
        fail(fmt::format("'{}' is negative (expected '{}')", word, syntax->usage));
    }
    c.x = values[0];
    c.y = values[1];
    script.commands.push_back(std::move(c));
  }
  return script;
}

ViewScript load_view_script(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScriptError(path + ": cannot read the script");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_view_script(text.str(), path);
}

}  // namespace trailray::ui
