// `trailray view --script`: each command carried out on the viewer (the session's as the page
// carries them out, ui/script_session.hpp), then its frames drawn.
#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <string>

#include "app/common/interrupt_guard.hpp"
#include "app/view/viewer_shell.hpp"
#include "app/view/viewer_ui.hpp"
#include "ui/script_session.hpp"

namespace trailray::app::view {

void ViewerApp::run_script(const ViewScript& script) {
  // Ctrl-C ends the script between frames (run() then cancels a film being recorded).
  for (const ScriptCommand& c : script.commands) {
    if (interrupt_requested()) return;
    const int frames = run_script_command(c, script);
    std::fflush(stdout);
    for (int i = 0; i < frames && !interrupt_requested(); ++i) frame(0.0, true);
  }
}

int ViewerApp::run_script_command(const ScriptCommand& c, const ViewScript& script) {
  // The session's commands as the page runs them too (ui/script_session.hpp); what they print to
  // standard output.
  if (const std::optional<std::string> printed = run_session_command(session_, c, script.file)) {
    fmt::print("{}", *printed);
    return 1;
  }
  {
    using Kind = ScriptCommand::Kind;
    const auto fail = [&](const std::string& why) {
      throw ScriptError(fmt::format("{}:{}: {}", script.file, c.line, why));
    };
    int frames = 1;
    switch (c.kind) {
      case Kind::hover:
        script_cursor_ = glm::dvec2(c.x, c.y);
        break;
      case Kind::wait:
        frames = static_cast<int>(c.x);
        break;
      case Kind::screenshot:
        screenshot(c.path);
        break;
      case Kind::window_screenshot:
        window_grab_ = c.path;
        break;
      case Kind::hide_panels:
        panels_ = false;
        break;
      case Kind::print_frame_times:
        fmt::print("{}\n", frame_times_since_last_print());
        if (options_.verbose) {  // and the renderer's share, per pass, of the last 60 frames
          profiler_.finish();
          fmt::print("{}", profiler_.table());
        }
        frames = 0;
        break;
      case Kind::record_film:
      case Kind::start_film:
        model_.film.path = c.path;
        model_.film.seconds = c.x;
        try {
          start_film();
        } catch (const std::exception& e) {
          fail(e.what());
        }
        if (c.kind == Kind::record_film) {
          while (film_ && !interrupt_requested()) frame(0.0, true);  // each frame draws some of the film
          if (!film_error_.empty()) fail(film_error_);
        }
        break;
      case Kind::film_size:
        model_.film.width = static_cast<int>(c.x);
        model_.film.height = static_cast<int>(c.y);
        break;
      case Kind::film_fps:
        model_.film.fps = c.x;
        break;
      case Kind::film_camera:
        model_.film.camera = c.path == "orbit"   ? FilmCamera::orbit
                             : c.path == "fixed" ? FilmCamera::fixed
                                                 : FilmCamera::follow;
        break;
      case Kind::cancel_film:
        if (!film_) fail("cancel-film: no film is recording");
        cancel_film();
        break;
      default:  // the session's: carried out above
        break;
    }
    return frames;
  }
}

}  // namespace trailray::app::view
