// `trailray view --script`: each command carried out on the viewer, then its frames drawn.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "app/common/interrupt_guard.hpp"
#include "app/view/viewer_shell.hpp"
#include "app/view/viewer_ui.hpp"
#include "scene/volumes/volume_shapes.hpp"
#include "ui/session_state.hpp"
#include "ui/tooltip.hpp"
#include "ui/track_picking.hpp"
#include "ui/waypoint_view.hpp"

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
  const glm::dvec2 centre(camera().lens().width_px / 2.0, camera().lens().height_px / 2.0);
  {
    using Kind = ScriptCommand::Kind;
    const auto fail = [&](const std::string& why) {
      throw ScriptError(fmt::format("{}:{}: {}", script.file, c.line, why));
    };
    int frames = 1;
    switch (c.kind) {
      case Kind::orbit:
        session_.orbit(c.x, c.y);
        break;
      case Kind::pan:
        session_.pan(centre.x, centre.y, centre.x + c.x, centre.y + c.y);
        break;
      case Kind::zoom:
        session_.zoom(c.x, centre.x, centre.y);
        break;
      case Kind::select:
        if (c.x >= static_cast<double>(model_.tracks.size()) || c.x != std::floor(c.x))
          fail(fmt::format("select {}: there {} {} track{} (0..{})", c.x, model_.tracks.size() == 1 ? "is" : "are",
                           model_.tracks.size(), model_.tracks.size() == 1 ? "" : "s",
                           static_cast<int>(model_.tracks.size()) - 1));
        model_.selected_track = static_cast<int>(c.x);
        session_.fly_to_track(model_.selected_track);
        session_.update(1e9);  // scripted flights arrive at once
        break;
      case Kind::select_waypoint:
        if (c.x >= static_cast<double>(model_.waypoints.points.size()) || c.x != std::floor(c.x))
          fail(fmt::format("select-waypoint {}: there are {} waypoints", c.x, model_.waypoints.points.size()));
        session_.fly_to_waypoint(static_cast<int>(c.x));
        session_.update(1e9);  // scripted flights arrive at once
        break;
      case Kind::print_waypoints: {
        const scene::Camera seen = camera().camera();
        const int chart = model_.tracks.empty() ? -1 : std::max(0, model_.selected_track);
        std::vector<ChartWaypoint> on_chart;
        if (chart >= 0) on_chart = chart_waypoints(model_.tracks[static_cast<std::size_t>(chart)], model_.waypoints);
        for (std::size_t i = 0; i < model_.waypoints.points.size(); ++i) {
          const scene::Waypoint& w = model_.waypoints.points[i];
          std::string where = "behind the camera";
          if (const auto s = pin_screen_position(seen, w, model_.settings.style.pins))
            where = fmt::format("pin at {:.1f} {:.1f}", s->x, s->y);
          std::string chart_text = "not on the chart";
          for (const ChartWaypoint& cw : on_chart)
            if (cw.waypoint == i) chart_text = fmt::format("chart point {}", cw.point);
          fmt::print("waypoint {} '{}' {} {}{}, {}\n", i, w.name,
                     w.kind == scene::WaypointKind::Place ? "place" : "waypoint", where, w.visible ? "" : " (hidden)",
                     chart_text);
        }
        break;
      }
      case Kind::hover:
        script_cursor_ = glm::dvec2(c.x, c.y);
        break;
      case Kind::print_hover: {
        const HoverState& h = model_.hover;
        if (h.waypoint >= 0 && h.waypoint < static_cast<int>(model_.waypoints.points.size())) {
          const scene::Waypoint& w = model_.waypoints.points[static_cast<std::size_t>(h.waypoint)];
          fmt::print("hover: waypoint {} '{}'\n", h.waypoint, w.name);
          for (const std::string& line : waypoint_tooltip_lines(w)) fmt::print("  {}\n", line);
        } else if (h.track < 0 && h.volume >= 0 && h.volume < static_cast<int>(model_.volumes.volumes.size())) {
          const scene::Volume& v = model_.volumes.volumes[static_cast<std::size_t>(h.volume)];
          fmt::print("hover: airspace {} '{}'\n", h.volume, v.name);
          for (const std::string& line : scene::volume_tooltip_lines(v)) fmt::print("  {}\n", line);
        } else if (h.track < 0) {
          fmt::print("hover: none\n");
        } else {
          const scene::Track& t = model_.tracks[static_cast<std::size_t>(h.track)];
          fmt::print("hover: track {} '{}' point {}\n", h.track, t.name, h.point);
          for (const std::string& line : tooltip_lines(t, h.point)) fmt::print("  {}\n", line);
        }
        break;
      }
      case Kind::print_marker: {
        const scene::Camera seen = camera().camera();
        for (std::size_t i = 0; i < model_.tracks.size(); ++i) {
          const TrackPosition p = position_at(model_.tracks[i], model_.clock.time());
          const auto s = p.valid ? screen_position(seen, p.ecef) : std::nullopt;
          if (s)
            fmt::print("marker: track {} point {} at {:.1f} {:.1f}\n", i, p.point, s->x, s->y);
          else
            fmt::print("marker: track {} none\n", i);
        }
        break;
      }
      case Kind::print_camera: {
        const scene::LookAt& v = camera().view();
        fmt::print("camera: pivot {:.6f},{:.6f},{:.1f} distance {:.1f} heading {:.2f} pitch {:.2f}\n", v.target.lat_deg,
                   v.target.lon_deg, v.target.height_m, v.distance_m, v.heading_deg, v.pitch_deg);
        break;
      }
      case Kind::print_state:
        fmt::print("{}\n", ui::session_state_json(session_));
        break;
      case Kind::play:
        model_.clock.play();
        model_.clock.advance(c.x);
        model_.clock.pause();
        break;
      case Kind::speed:
        model_.clock.set_speed(c.x);
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
    }
    return frames;
  }
}

}  // namespace trailray::app::view
