#include "app/view/viewer_app.hpp"

#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <imgui.h>
#include <GeographicLib/Geocentric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <future>
#include <limits>
#include <memory>
#include <numeric>

#include "app/track_legend.hpp"
#include "app/view/legend_overlay.hpp"
#include "app/view/panel_layout.hpp"
#include "app/view/camera_controller.hpp"
#include "app/view/profiler_table.hpp"
#include "app/view/track_loading.hpp"
#include "app/view/track_picking.hpp"
#include "app/view/view_script.hpp"
#include "app/view/viewer_overlay.hpp"
#include "render/gl/frame_profiler.hpp"
#include "render/gl/framebuffer_readback.hpp"
#include "scene/framing.hpp"
#include "render/gl/gl_api.hpp"
#include "render/platform/imgui_layer.hpp"
#include "render/scene_renderer.hpp"
#include "scene/sun_position.hpp"
#include "render/platform/window.hpp"

namespace trailray::app::view {
namespace {

using Clock = std::chrono::steady_clock;

void warn(const std::string& message) { fmt::print(stderr, "trailray: warning: {}\n", message); }

// "frames: 100, mean 41.2 ms, median 40.8 ms (24.5 fps)".
std::string frame_time_summary(const std::string& what, std::vector<double> ms) {
  const double mean = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
  std::sort(ms.begin(), ms.end());
  const std::size_t n = ms.size();
  const double median = n % 2 == 1 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  return fmt::format("{}: {}, mean {:.1f} ms, median {:.1f} ms ({:.1f} fps)", what, n, mean, median,
                     median > 0.0 ? 1000.0 / median : 0.0);
}

// Where a framing may put the tracks: out of a corner, within an area of the window.
struct FramingRoom {
  scene::KeptClearCorner keep_clear;
  std::optional<scene::ImageArea> area;
};

class ViewerApp {
 public:
  explicit ViewerApp(const ViewerOptions& options);
  int run();

 private:
  // One frame: input (unless scripted), scene, panels, overlays, swap. `wall_s` drives the
  // replay clock and the camera's flights.
  void frame(double wall_s, bool scripted);
  void handle_mouse(const scene::Camera& camera);
  void handle_keys(double wall_s);
  void take_dropped_files();
  void adopt(LoadedViewerTracks loaded);
  void sync_track_buffers();
  render::SceneRenderOptions scene_options() const;
  std::pair<TrackStyle, TrackScene> legend_inputs(const render::TrackSceneSettings& settings) const;
  scene::KeptClearCorner legend_corner(const scene::Lens& lens) const;
  FramingRoom framing_room(const scene::Lens& lens) const;
  void update_hover(double x_px, double y_px, const scene::Camera& camera);
  void fly_to_track(int index);
  void follow_replay();  // the replay's camera follow (chase, or orbit round the marker)
  // `status`: say so in the window too (the P key; not scripted pictures).
  void screenshot(const std::string& path, bool status = false);
  void run_script(const ViewScript& script);
  double sun_unix_time() const;

  ViewerOptions options_;
  TerrainSources sources_;
  double neutral_ = 0.0;
  TrackPoints points_;
  ViewerModel model_;
  // GL objects after the window (the context) and before nothing else: destroyed first.
  render::Window window_;
  render::ImGuiLayer imgui_;
  render::SceneRenderer renderer_;
  render::FrameProfiler profiler_;
  std::vector<std::unique_ptr<render::TrackBuffer>> buffers_;
  std::vector<std::size_t> buffer_revisions_;
  CameraController controller_;
  std::vector<std::future<LoadedViewerTracks>> loading_;
  terrain::LoadProgress progress_;
  std::string status_;                       // a line at the bottom (screenshot written, ...)
  std::optional<glm::dvec2> script_cursor_;  // `hover X Y`
  bool panels_ = true;                       // false: `hide-panels`
  std::string window_grab_;                  // `window-screenshot PATH`: after the next frame's UI
};

render::WindowOptions window_options(const ViewerOptions& o) {
  render::WindowOptions w;
  w.width_px = o.lens.width_px;
  w.height_px = o.lens.height_px;
  w.title = o.tracks.empty() ? std::string("trailray") : "trailray - " + o.tracks.front();
  w.vsync = o.frames == 0 && o.script.empty();  // scripted runs go as fast as they can
  return w;
}

// The first view: the options' camera, else framed on the tracks where the panels and the
// legend leave the window free; the pivot on the ground.
CameraController first_view(const ViewerOptions& o, const TrackPoints& points, terrain::HeightSource* heights,
                            double neutral, const FramingRoom& room) {
  if (o.camera.look_at) return CameraController(*o.camera.look_at, o.lens);
  if (points.points.empty() && !o.camera.placement)
    throw std::runtime_error("no track could be read and no camera was given (--camera or --look-at)");
  const scene::Camera camera = initial_camera(o.camera, o.lens, points, heights, room.keep_clear, room.area);
  // The pivot where the view's centre meets the tracks' lowest level (no tile read for it).
  return CameraController(CameraController::look_at_from_camera(camera, neutral), o.lens);
}

TrackLoadInputs load_inputs(const ViewerOptions& o, terrain::HeightSource* heights, double neutral) {
  return {o.read, o.analysis, o.style, heights, neutral, 0};
}

}  // namespace

// The start, in the order that lets each step use the one before: sources, tracks (errors
// kept for the window), the window and GL, the camera.
ViewerApp::ViewerApp(const ViewerOptions& o)
    : options_(o),
      sources_(open_terrain_sources(o.terrain, warn)),
      window_(window_options(o)),
      imgui_(window_),
      renderer_({sources_.heights.get(), sources_.imagery.get()}),
      profiler_(window_.capabilities(), 60),
      controller_(scene::LookAt{}, o.lens) {
  if (o.verbose)
    for (const std::string& line : window_.describe()) fmt::print(stderr, "trailray: {}\n", line);
  // Tracks are read before the first frame (like `render`); later files load in the background.
  LoadedViewerTracks first =
      load_viewer_tracks(o.tracks, load_inputs(o, sources_.heights.get(), std::numeric_limits<double>::quiet_NaN()));
  const double lowest = lowest_height(first.points.points);
  neutral_ = std::isnan(lowest) ? 0.0 : lowest;
  points_ = first.points;
  model_.settings = settings_from_style(o.style);
  model_.settings.ssao = !o.effects.no_ssao;
  model_.settings.shadows = !o.effects.no_shadows;
  model_.settings.atmosphere = !o.effects.no_atmosphere;
  model_.settings.snow = {o.effects.snow, o.effects.snowline_m};
  model_.settings.sun_time_unix = sun_time(o.effects.time, points_);
  model_.analysis = o.analysis;
  // The tracks first: the legend they call for is kept clear by the first view's framing.
  adopt(std::move(first));
  controller_ = first_view(o, points_, sources_.heights.get(), neutral_, framing_room(o.lens));
  controller_.set_ground([this](double lat, double lon) { return renderer_.height_in_memory(lat, lon); });
}

double ViewerApp::sun_unix_time() const {
  return std::isnan(model_.settings.sun_time_unix) ? sun_time("", points_) : model_.settings.sun_time_unix;
}

void ViewerApp::adopt(LoadedViewerTracks loaded) {
  for (const std::string& w : loaded.warnings) warn(w);
  for (std::string& e : loaded.errors) {
    fmt::print(stderr, "trailray: error: {}\n", e);
    model_.errors.push_back(std::move(e));
  }
  for (ViewerTrack& t : loaded.tracks) model_.tracks.push_back(std::move(t));
  if (model_.selected_track < 0 && !model_.tracks.empty()) model_.selected_track = 0;
}

void ViewerApp::sync_track_buffers() {
  buffers_.resize(model_.tracks.size());
  buffer_revisions_.resize(model_.tracks.size(), static_cast<std::size_t>(-1));
  for (std::size_t i = 0; i < model_.tracks.size(); ++i)
    if (!buffers_[i] || buffer_revisions_[i] != model_.tracks[i].geometry_revision) {
      buffers_[i] = std::make_unique<render::TrackBuffer>(model_.tracks[i].geometry);
      buffer_revisions_[i] = model_.tracks[i].geometry_revision;
    }
}

render::SceneRenderOptions ViewerApp::scene_options() const {
  const ViewerSettings& s = model_.settings;
  render::SceneRenderOptions o;
  o.sun_direction_ecef = scene::sun_direction_ecef(sun_unix_time());
  o.neutral_ground_height_m = neutral_;
  o.ssao = s.ssao;
  o.shadows = s.shadows;
  o.atmosphere = s.atmosphere;
  o.snow = s.snow;
  o.track_settings = track_scene_settings(model_.tracks, s);
  const bool by_value = s.color_by != track::ColorMetric::solid && effective_range(model_.tracks, s).has_value();
  for (std::size_t i = 0; i < model_.tracks.size(); ++i)
    if (model_.tracks[i].visible && buffers_[i])
      o.tracks.push_back({buffers_[i].get(), model_.tracks[i].color_srgb, by_value && model_.tracks[i].by_value});
  return o;
}

void ViewerApp::take_dropped_files() {
  std::vector<std::string> dropped = window_.take_dropped_files();
  if (!dropped.empty()) {
    TrackLoadInputs inputs = load_inputs(options_, sources_.heights.get(), neutral_);
    inputs.tracks_open = model_.tracks.size();
    // Colours chosen against what is open now; files dropped together share one load.
    inputs.style.metric = model_.settings.color_by;
    loading_.push_back(load_viewer_tracks_async(std::move(dropped), std::move(inputs)));
  }
  for (auto it = loading_.begin(); it != loading_.end();) {
    if (it->wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++it;
      continue;
    }
    LoadedViewerTracks loaded = it->get();
    it = loading_.erase(it);
    const int first_new = static_cast<int>(model_.tracks.size());
    const bool any = !loaded.tracks.empty();
    adopt(std::move(loaded));
    if (any) fly_to_track(first_new);
  }
}

void ViewerApp::update_hover(double x_px, double y_px, const scene::Camera& camera) {
  // The terrain under the cursor (from the tiles in memory): a track point behind it loses to
  // one in front.
  std::optional<double> ground_depth_m;
  if (const auto ground = controller_.ground_point_at(x_px, y_px))
    if (const auto seen = camera.project(scene::ecef_from(*ground))) ground_depth_m = seen->depth_m;
  const HoverState picked = pick_track_point(model_.tracks, camera, x_px, y_px, kPickRadiusPx, ground_depth_m);
  if (picked.track >= 0 || !model_.hover.from_chart) model_.hover = picked;
}

void ViewerApp::fly_to_track(int index) {
  if (index < 0 || index >= static_cast<int>(model_.tracks.size())) return;
  const ViewerTrack& t = model_.tracks[static_cast<std::size_t>(index)];
  std::vector<scene::GeoPosition> points;
  points.reserve(t.ecef.size());
  for (const glm::dvec3& p : t.ecef) {
    scene::GeoPosition g;
    GeographicLib::Geocentric::WGS84().Reverse(p.x, p.y, p.z, g.lat_deg, g.lon_deg, g.height_m);
    points.push_back(g);
  }
  scene::FramingOptions framing;
  framing.lens = controller_.lens();
  framing.preferred_heading_deg = controller_.view().heading_deg;
  const FramingRoom room = framing_room(framing.lens);
  framing.keep_clear = room.keep_clear;
  framing.area = room.area;
  const auto framed = scene::frame_points(points, framing);
  if (!framed.ok()) return;
  double ground =
      renderer_.height_in_memory(framed.value->look_at.target.lat_deg, framed.value->look_at.target.lon_deg);
  if (std::isnan(ground)) ground = lowest_height(points);
  if (std::isnan(ground)) ground = neutral_;
  controller_.fly_to(CameraController::look_at_from_camera(framed.value->camera, ground));
}

void ViewerApp::follow_replay() {
  const ReplayClock& clock = model_.clock;
  if (clock.follow == FollowMode::off || clock.follow_track < 0 ||
      clock.follow_track >= static_cast<int>(model_.tracks.size()))
    return;
  const ViewerTrack& t = model_.tracks[static_cast<std::size_t>(clock.follow_track)];
  const TrackPosition p = position_at(t, clock.time());
  if (!p.valid) return;
  scene::GeoPosition at;
  GeographicLib::Geocentric::WGS84().Reverse(p.ecef.x, p.ecef.y, p.ecef.z, at.lat_deg, at.lon_deg, at.height_m);
  std::optional<double> heading;
  if (clock.follow == FollowMode::chase && p.point + 1 < t.ecef.size()) {
    // Look along the way the track goes from here (the segment the marker is on).
    const scene::EnuAxes enu = scene::enu_axes_at(at.lat_deg, at.lon_deg);
    const glm::dvec3 d = t.ecef[p.point + 1] - t.ecef[p.point];
    const double east = glm::dot(d, enu.east), north = glm::dot(d, enu.north);
    if (std::hypot(east, north) > 0.1) heading = std::atan2(east, north) * 180.0 / 3.14159265358979323846;
  }
  controller_.follow(at, heading);
}

void ViewerApp::handle_mouse(const scene::Camera& camera) {
  const ImGuiIO& io = ImGui::GetIO();
  if (imgui_.wants_mouse()) return;
  const double x = io.MousePos.x * io.DisplayFramebufferScale.x, y = io.MousePos.y * io.DisplayFramebufferScale.y;
  const glm::dvec2 delta(io.MouseDelta.x * io.DisplayFramebufferScale.x,
                         io.MouseDelta.y * io.DisplayFramebufferScale.y);
  if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    if (const auto ground = controller_.ground_point_at(x, y)) {
      scene::LookAt to = controller_.view();
      to.target = *ground;
      to.distance_m *= 0.5;
      controller_.fly_to(to);
    }
  } else if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && (delta.x != 0.0 || delta.y != 0.0)) {
    controller_.orbit(delta.x, delta.y);
  }
  if (ImGui::IsMouseDown(ImGuiMouseButton_Right) && (delta.x != 0.0 || delta.y != 0.0))
    controller_.pan(x - delta.x, y - delta.y, x, y);
  if (io.MouseWheel != 0.0f) controller_.zoom(io.MouseWheel, x, y);
  if (x >= 0 && y >= 0 && !ImGui::IsMouseDown(ImGuiMouseButton_Left) && !ImGui::IsMouseDown(ImGuiMouseButton_Right))
    update_hover(x, y, camera);
}

void ViewerApp::handle_keys(double wall_s) {
  if (imgui_.wants_keyboard()) return;
  const double step = std::min(0.1, 0.8 * wall_s);  // fractions of the distance per frame
  const auto down = [](int key) { return ImGui::IsKeyDown(key); };
  if (down(GLFW_KEY_W) || down(GLFW_KEY_UP)) controller_.move(0.0, step);
  if (down(GLFW_KEY_S) || down(GLFW_KEY_DOWN)) controller_.move(0.0, -step);
  if (down(GLFW_KEY_D) || down(GLFW_KEY_RIGHT)) controller_.move(step, 0.0);
  if (down(GLFW_KEY_A) || down(GLFW_KEY_LEFT)) controller_.move(-step, 0.0);
  if (down(GLFW_KEY_Q)) controller_.orbit(-200.0 * wall_s, 0.0);
  if (down(GLFW_KEY_E)) controller_.orbit(200.0 * wall_s, 0.0);
  if (down(GLFW_KEY_PAGE_UP)) controller_.tilt(40.0 * wall_s);
  if (down(GLFW_KEY_PAGE_DOWN)) controller_.tilt(-40.0 * wall_s);
  const glm::dvec2 centre(controller_.lens().width_px / 2.0, controller_.lens().height_px / 2.0);
  if (down(GLFW_KEY_EQUAL) || down(GLFW_KEY_KP_ADD)) controller_.zoom(4.0 * wall_s, centre.x, centre.y);
  if (down(GLFW_KEY_MINUS) || down(GLFW_KEY_KP_SUBTRACT)) controller_.zoom(-4.0 * wall_s, centre.x, centre.y);
  if (ImGui::IsKeyPressed(GLFW_KEY_N, false)) controller_.reset_north();
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) fly_to_track(std::max(0, model_.selected_track));
  if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) model_.clock.toggle();
  if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) {
    char name[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(name, sizeof name, "trailray-%Y%m%d-%H%M%S.png", std::localtime(&now));
    screenshot(name, true);
  }
}

void ViewerApp::frame(double wall_s, bool scripted) {
  window_.poll_events();
  take_dropped_files();
  const std::uint32_t width = window_.framebuffer_width(), height = window_.framebuffer_height();
  std::optional<std::array<float, 2>> cursor;
  if (scripted) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    cursor = script_cursor_ ? std::array<float, 2>{static_cast<float>(script_cursor_->x) / scale.x,
                                                   static_cast<float>(script_cursor_->y) / scale.y}
                            : std::array<float, 2>{nan, nan};
  }
  imgui_.begin_frame(cursor);
  if (width > 0 && height > 0) controller_.set_image_size(width, height);
  if (!scripted) {
    handle_mouse(controller_.camera());
    handle_keys(wall_s);
  }
  controller_.update(wall_s);
  follow_replay();
  const PanelActions actions = panels_ ? draw_panels(model_, scripted ? 0.0 : wall_s) : PanelActions{};
  if (actions.fly_to_track >= 0) fly_to_track(actions.fly_to_track);
  sync_track_buffers();
  const scene::Camera camera = controller_.camera();
  if (scripted && script_cursor_) update_hover(script_cursor_->x, script_cursor_->y, camera);

  OverlayState overlay{
      model_, camera, progress_, status_, controller_.view().heading_deg, scripted ? script_cursor_ : std::nullopt};
  if (panels_ && draw_overlays(overlay)) controller_.reset_north();
  // Once a frame: the colour range behind it is a percentile over every track value.
  render::SceneRenderOptions options = scene_options();
  if (panels_ && model_.settings.legend) {
    const auto [style, legend_scene] = legend_inputs(options.track_settings);
    draw_legend_overlay(color_legend_for(style, legend_scene), track_key_for(style, legend_scene));
  }

  if (width > 0 && height > 0) {
    options.wait_for_tiles = false;
    options.read_back = false;
    options.blit_to_default_framebuffer = true;
    options.profiler = &profiler_;
    const render::RenderedScene scene = renderer_.render(camera, options);
    progress_ = scene.report.progress;
    model_.loading = progress_.pending() > 0;
    model_.profile = profiler_table(profiler_, wall_s);
    model_.profile.mesh_bytes = scene.report.gpu_meshes.bytes;
    model_.profile.mesh_budget_bytes = scene.report.gpu_meshes.budget_bytes;
    model_.profile.imagery_bytes = scene.report.gpu_imagery.bytes;
    model_.profile.imagery_budget_bytes = scene.report.gpu_imagery.budget_bytes;
    glViewport(0, 0, static_cast<GLsizei>(width), static_cast<GLsizei>(height));
  }
  imgui_.render();
  if (!window_grab_.empty() && width > 0 && height > 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    scene::write_srgb_png(window_grab_, render::read_rgba8(0, 0, static_cast<int>(width), static_cast<int>(height)));
    fmt::print(stderr, "trailray: wrote {} ({}x{}, the window)\n", window_grab_, width, height);
    window_grab_.clear();
  }
  window_.swap_buffers();
}

// What the legend shows, as `render` would decide it for the tracks now visible.
std::pair<TrackStyle, TrackScene> ViewerApp::legend_inputs(const render::TrackSceneSettings& settings) const {
  TrackStyle style;
  style.settings = settings;
  style.metric = model_.settings.color_by;
  style.legend = model_.settings.legend;
  TrackScene scene;
  scene.range = effective_range(model_.tracks, model_.settings);
  for (const ViewerTrack& t : model_.tracks) {
    if (!t.visible) continue;
    SceneTrack named;
    named.name = t.name;
    named.color_srgb = t.color_srgb;
    scene.tracks.push_back(std::move(named));
  }
  return {style, scene};
}

// The corner a framing keeps the tracks out of: the legend's, large enough for the legend window
// (where it first appears, in the bottom-left corner) and for the legend of screenshots (drawn
// there too), whichever is larger. Nothing when no legend is shown.
scene::KeptClearCorner ViewerApp::legend_corner(const scene::Lens& lens) const {
  if (!model_.settings.legend) return {};
  // The scene's colour settings (not scene_options(): the first view is framed before the tracks
  // have GPU buffers).
  const auto [style, legend_scene] = legend_inputs(track_scene_settings(model_.tracks, model_.settings));
  const scene::KeptClearCorner picture =
      legend_clearance(scene_legend_panel(lens.width_px, lens.height_px, style, legend_scene), lens.height_px);
  if (!panels_) return picture;  // `hide-panels`: no legend window
  const scene::KeptClearCorner window =
      legend_clearance(legend_overlay_rect(color_legend_for(style, legend_scene), track_key_for(style, legend_scene),
                                           static_cast<float>(lens.width_px), static_cast<float>(lens.height_px)),
                       lens.height_px);
  return {scene::ImageCorner::bottom_left, std::max(picture.width_px, window.width_px),
          std::max(picture.height_px, window.height_px)};
}

// With the panels shown, the part of the window their first layout leaves free (right of the
// panel column, below the menu, above the chart), clear of the replay panel's corner; the legend
// window lies under the column, outside that area (if a wide key reaches into it, the area ends
// above it). Without panels (`hide-panels`), the whole window clear of the legend.
FramingRoom ViewerApp::framing_room(const scene::Lens& lens) const {
  const scene::KeptClearCorner legend = legend_corner(lens);
  if (!panels_) return {legend, std::nullopt};
  const ViewerSettings& s = model_.settings;
  const auto w = static_cast<float>(lens.width_px), h = static_cast<float>(lens.height_px);
  const float menu = s.show_menu ? kPanelTitleBarHeight : 0.0f;
  const PanelLayout l = default_panel_layout(w, h, menu);
  scene::ImageArea area{0.0, menu, w, h};
  if (s.show_tracks || s.show_statistics) area.left_px = l.tracks.right();
  if (s.show_chart) area.bottom_px = l.chart.y;
  if (!legend.empty() && legend.width_px > area.left_px)
    area.bottom_px = std::min(area.bottom_px, static_cast<double>(h) - legend.height_px);
  // A window too small for the panels and a view (the free part misses the window's centre,
  // which framing needs): frame on all of it.
  if (!(area.left_px < 0.5 * w && area.bottom_px > 0.5 * h)) return {legend, std::nullopt};
  scene::KeptClearCorner replay;
  if (s.show_replay) replay = {scene::ImageCorner::top_right, w - l.replay.x, l.replay.bottom()};
  return {replay, area};
}

// A picture as `render` makes it: the scene once its tiles are in, with the legend.
void ViewerApp::screenshot(const std::string& path, bool status) {
  sync_track_buffers();
  render::SceneRenderOptions options = scene_options();
  options.timeout = std::chrono::milliseconds(static_cast<long long>(options_.timeout_s * 1000.0));
  render::RenderedScene scene = renderer_.render(controller_.camera(), options);
  if (scene.report.timed_out)
    warn(fmt::format("tiles still loading after {} s: the picture has what had arrived", options_.timeout_s));
  const auto [style, legend_scene] = legend_inputs(options.track_settings);
  draw_scene_legend(scene.image, style, legend_scene);
  scene::write_srgb_png(path, scene.image);
  const std::string wrote = fmt::format("wrote {} ({}x{})", path, scene.image.width, scene.image.height);
  if (status) status_ = wrote;
  fmt::print(stderr, "trailray: {}\n", wrote);
}

void ViewerApp::run_script(const ViewScript& script) {
  const glm::dvec2 centre(controller_.lens().width_px / 2.0, controller_.lens().height_px / 2.0);
  for (const ScriptCommand& c : script.commands) {
    using Kind = ScriptCommand::Kind;
    const auto fail = [&](const std::string& why) {
      throw ScriptError(fmt::format("{}:{}: {}", script.file, c.line, why));
    };
    int frames = 1;
    switch (c.kind) {
      case Kind::orbit:
        controller_.orbit(c.x, c.y);
        break;
      case Kind::pan:
        controller_.pan(centre.x, centre.y, centre.x + c.x, centre.y + c.y);
        break;
      case Kind::zoom:
        controller_.zoom(c.x, centre.x, centre.y);
        break;
      case Kind::select:
        if (c.x >= static_cast<double>(model_.tracks.size()) || c.x != std::floor(c.x))
          fail(fmt::format("select {}: there {} {} track{} (0..{})", c.x, model_.tracks.size() == 1 ? "is" : "are",
                           model_.tracks.size(), model_.tracks.size() == 1 ? "" : "s",
                           static_cast<int>(model_.tracks.size()) - 1));
        model_.selected_track = static_cast<int>(c.x);
        fly_to_track(model_.selected_track);
        controller_.update(1e9);  // scripted flights arrive at once
        break;
      case Kind::hover:
        script_cursor_ = glm::dvec2(c.x, c.y);
        break;
      case Kind::print_hover: {
        const HoverState& h = model_.hover;
        if (h.track < 0) {
          fmt::print("hover: none\n");
        } else {
          const ViewerTrack& t = model_.tracks[static_cast<std::size_t>(h.track)];
          fmt::print("hover: track {} '{}' point {}\n", h.track, t.name, h.point);
          for (const std::string& line : tooltip_lines(t, h.point)) fmt::print("  {}\n", line);
        }
        break;
      }
      case Kind::print_marker: {
        const scene::Camera camera = controller_.camera();
        for (std::size_t i = 0; i < model_.tracks.size(); ++i) {
          const TrackPosition p = position_at(model_.tracks[i], model_.clock.time());
          const auto s = p.valid ? screen_position(camera, p.ecef) : std::nullopt;
          if (s)
            fmt::print("marker: track {} point {} at {:.1f} {:.1f}\n", i, p.point, s->x, s->y);
          else
            fmt::print("marker: track {} none\n", i);
        }
        break;
      }
      case Kind::print_camera: {
        const scene::LookAt& v = controller_.view();
        fmt::print("camera: pivot {:.6f},{:.6f},{:.1f} distance {:.1f} heading {:.2f} pitch {:.2f}\n", v.target.lat_deg,
                   v.target.lon_deg, v.target.height_m, v.distance_m, v.heading_deg, v.pitch_deg);
        break;
      }
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
    }
    std::fflush(stdout);
    for (int i = 0; i < frames; ++i) frame(0.0, true);
  }
}

int ViewerApp::run() {
  const bool scripted = options_.frames > 0 || !options_.script.empty() || !options_.screenshot.empty();
  if (!scripted) {
    Clock::time_point last = Clock::now();
    while (!window_.should_close()) {
      const Clock::time_point now = Clock::now();
      frame(std::chrono::duration<double>(now - last).count(), false);
      last = now;
    }
    return 0;
  }
  // The script is read first: a typo fails before any frame is drawn.
  const std::optional<ViewScript> script =
      options_.script.empty() ? std::nullopt : std::optional<ViewScript>(load_view_script(options_.script));
  frame(0.0, true);
  if (options_.frames > 0) {
    // Timed frames, as a person would see them (tiles stream in meanwhile): the figures for the
    // issue's FPS report, printed to standard error.
    std::vector<double> all_ms, settled_ms;
    for (int i = 0; i < options_.frames; ++i) {
      const Clock::time_point start = Clock::now();
      frame(0.0, true);
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      all_ms.push_back(ms);
      if (progress_.done()) settled_ms.push_back(ms);
    }
    fmt::print(stderr, "trailray: {}\n", frame_time_summary("frames", all_ms));
    if (settled_ms.size() != all_ms.size())
      fmt::print(stderr, "trailray: {}\n",
                 settled_ms.empty() ? std::string("frames with every tile loaded: none")
                                    : frame_time_summary("frames with every tile loaded", settled_ms));
    if (options_.verbose) {
      // The renderer's share of those frames, per pass (the last 60 frames).
      profiler_.finish();
      fmt::print(stderr, "{}", profiler_.table());
    }
  }
  if (script) run_script(*script);
  if (!options_.screenshot.empty()) screenshot(options_.screenshot);
  return 0;
}

int run_viewer(const ViewerOptions& options) {
  // A script that does not parse fails before a window opens.
  if (!options.script.empty()) load_view_script(options.script);
  ViewerApp app(options);
  return app.run();
}

}  // namespace trailray::app::view
