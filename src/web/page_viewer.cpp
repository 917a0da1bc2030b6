#include "web/page_viewer.hpp"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_internal.h>  // MovingWindow: a panel moved is no edit
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <utility>

#include "scene/diagnostics.hpp"
#include "scene/camera/framing.hpp"
#include "scene/text/legend_content.hpp"
#include "scene/scene.hpp"
#include "scene/tracks/track_building.hpp"
#include "terrain/sources/encoded_sources.hpp"
#include "terrain/codecs/height_encoding.hpp"
#include "track/io/text_output.hpp"
#include "ui/framing_room.hpp"
#include "ui/profile_chart.hpp"
#include "ui/script_session.hpp"
#include "ui/session_state.hpp"
#include "ui/view_script.hpp"
#include "ui/viewer_overlay.hpp"
#include "ui/viewer_panels.hpp"
#include "ui/waypoint_view.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "web/fetched_tiles.hpp"
#include "web/page_panels.hpp"

namespace trailray::web {
namespace {

// The bytes as a file of the page's in-memory file system, in a folder of its own so that the
// readers (which take paths, and sniff gzip and the format) name it as the person knows it.
class FileInMemory {
 public:
  FileInMemory(int serial, const std::string& name, std::string_view bytes)
      : folder_("/opened/" + std::to_string(serial)) {
    std::filesystem::create_directories(folder_);
    std::ofstream(folder_ / name, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    std::filesystem::current_path(folder_);
  }
  ~FileInMemory() {
    std::error_code ec;
    std::filesystem::current_path("/", ec);
    std::filesystem::remove_all(folder_, ec);
  }

 private:
  std::filesystem::path folder_;
};

// Where the page looks before any track is open (the Bernese Oberland), in daylight whatever the
// hour: local solar noon of today there.
constexpr double kOverviewLonDeg = 8.0;
double noon_today(double lon_deg) {
  const double now = static_cast<double>(std::time(nullptr));
  return std::floor(now / 86400.0) * 86400.0 + 43200.0 - lon_deg / 15.0 * 3600.0;
}

// A name that cannot leave its folder (a file name, not a path).
std::string plain_file_name(const std::string& name) {
  std::string out = std::filesystem::path(name).filename().string();
  if (out.empty() || out == "." || out == "..") out = "track";
  return out;
}

}  // namespace

PageViewer::PageViewer() {
  model_.offers_moving_frame = false;
  session_.set_framing_room([this](const scene::Lens& lens) { return framing_room(lens); });
  open_terrain();
}

void PageViewer::open_terrain() {
  terrain_view_.reset();
  heights_.reset();
  imagery_.reset();
  fetched_.clear();
  const auto redraw = [this] { dirty_ = true; };
  const auto info_of = [](const terrain::SourceSettings& s) {
    terrain::SourceInfo info;
    info.name = s.source;
    info.min_zoom = s.min_zoom.value_or(0);
    info.max_zoom = s.max_zoom.value_or(15);
    info.encoding = s.encoding;
    info.attribution = s.attribution;
    return info;
  };
  if (options_.terrain.source != "none") {
    auto tiles = std::make_shared<FetchedTiles>(info_of(options_.terrain), redraw);
    fetched_.push_back(tiles);
    heights_ = std::make_unique<terrain::EncodedHeightSource>(
        tiles, options_.terrain.encoding.value_or(terrain::HeightEncoding::terrarium));
  }
  if (options_.imagery.source != "none") {
    auto tiles = std::make_shared<FetchedTiles>(info_of(options_.imagery), redraw);
    fetched_.push_back(tiles);
    imagery_ = std::make_unique<terrain::EncodedImagerySource>(std::move(tiles));
  }
  if (heights_ || imagery_) {
    terrain::TileLoaderOptions loading;
    loading.memory_budget_bytes = 256u << 20;
    // Without threads the loader looks at this many queued tiles a frame: every one that arrived
    // is taken and new requests start (FetchedTiles bounds those). Few would leave arrived tiles
    // waiting behind the ones still on their way, a frame (a second, in software GL) each.
    loading.tiles_per_request = 64;
    terrain_view_ = std::make_unique<scene::TerrainView>(heights_.get(), imagery_.get(), loading);
    scene::TileLoadPolicy policy;
    policy.wait = false;  // draw what is there; arrivals ask for another frame
    terrain_view_->set_policy(policy);
  }
  dirty_ = true;
}

std::string PageViewer::open_track(const std::string& name, std::string_view bytes) {
  scene::CollectedDiagnostics diagnostics;
  try {
    const std::string file = plain_file_name(name);
    scene::LoadedTrackFile loaded;
    {
      FileInMemory in_memory(++files_opened_, file, bytes);
      loaded = scene::read_track_file(file, track::ReadOptions{}, diagnostics);
    }
    files_.push_back(std::move(loaded));
    std::vector<std::string> read_before = std::exchange(read_warnings_, diagnostics.warnings);
    try {
      rebuild_tracks();
    } catch (...) {
      files_.pop_back();  // what was open stays as it was
      read_warnings_ = std::move(read_before);
      rebuild_tracks();
      throw;
    }
  } catch (const std::exception& e) {
    // What the reader warned of tells where a file went wrong (cut short at line N...).
    std::string message = e.what();
    for (const std::string& w : diagnostics.warnings) message += "\n" + w;
    return message;
  }
  if (!camera_moved_) place_camera();
  dirty_ = true;
  return {};
}

std::string PageViewer::set_option(std::string_view name, std::string_view value) {
  // The page's own: the picture alone, without the panels and what lies over it (an embedded
  // view, a picture to compare with `render`).
  if (name == "no-panels") {
    if (!value.empty() && value != "true" && value != "1") return "no-panels takes no value";
    panels_ = false;
    std::erase_if(given_options_, [&](const auto& kv) { return kv.first == name; });
    given_options_.emplace_back(name, "");
    ui_frames_ = kUiFramesAfterInput;
    return {};
  }
  const PageOptions before = options_;
  const OptionOutcome outcome = apply_page_option(options_, name, value);
  if (!outcome.effect) return outcome.error;
  try {
    if (*outcome.effect == OptionEffect::tracks) rebuild_tracks();
    if (*outcome.effect == OptionEffect::terrain) open_terrain();
    if (*outcome.effect == OptionEffect::camera) {
      camera_moved_ = true;
      place_camera();
    }
  } catch (const std::exception& e) {
    options_ = before;
    rebuild_tracks();
    return std::string(name) + "=" + std::string(value) + ": " + e.what();
  }
  std::erase_if(given_options_, [&](const auto& kv) {
    const auto reset = options_reset_by(name);
    return kv.first == name || std::find(reset.begin(), reset.end(), kv.first) != reset.end();
  });
  if (*outcome.effect != OptionEffect::camera) given_options_.emplace_back(name, value);
  if (*outcome.effect == OptionEffect::style) legend_dirty_ = true;
  // The panels show and edit what the options say.
  model_.settings.style = options_.style;
  dirty_ = true;
  return {};
}

std::string PageViewer::set_served_pins(std::string_view json) {
  try {
    ServedPins pins = served_pins(json, recorded_.lowest_or_sea_level());
    model_.waypoints.points = std::move(pins.points);
    ++model_.waypoints.revision;
    first_photo_ = pins.first_photo;
    large_urls_ = std::move(pins.large_urls);
    large_in_.assign(large_urls_.size(), false);
    photos_in_ = 0;
  } catch (const std::exception& e) {
    return e.what();
  }
  dirty_ = true;
  return {};
}

std::string PageViewer::set_photo_picture(int index, bool large, std::string_view bytes) {
  if (index < 0 || static_cast<std::size_t>(index) >= large_urls_.size())
    return fmt::format("photo {}: there are {} photos", index, large_urls_.size());
  scene::Waypoint& w = model_.waypoints.points[first_photo_ + static_cast<std::size_t>(index)];
  try {
    // The larger picture stands in for the thumbnail from then on: the atlas keeps it by its id.
    w.thumbnail = decode_photo_bytes(bytes);
  } catch (const terrain::TileDecodeError& e) {
    return fmt::format("{}: {}", w.name, e.what());
  }
  if (large)
    large_in_[static_cast<std::size_t>(index)] = true;
  else
    ++photos_in_;
  ++model_.waypoints.revision;
  dirty_ = true;
  return {};
}

void PageViewer::rebuild_tracks() {
  recorded_ = scene::recorded_points(files_);
  model_.neutral_ground_m = recorded_.lowest_or_sea_level();
  scene::TrackBuildOptions build;
  build.neutral_ground_m = recorded_.lowest_or_sea_level();
  // As the desktop viewer builds them (app/view/track_loading): each track's summary, which the
  // Statistics panel shows, and its flights' analysis (the panel's flight lines).
  build.inspect = true;
  build.analysis = model_.analysis;
  scene::CollectedDiagnostics diagnostics;
  ui::LoadedTracks built;
  built.tracks = scene::build_tracks(files_, options_.style.tracks, build, diagnostics);
  // The last file's reader's warnings, then those of building the tracks (as the desktop's).
  built.warnings = read_warnings_;
  for (std::string& w : diagnostics.warnings) built.warnings.push_back(std::move(w));
  session_.replace_tracks(std::move(built));
  legend_dirty_ = true;
}

scene::Lens PageViewer::lens() const {
  scene::Lens lens;
  lens.width_px = std::max<std::uint32_t>(width_px_, 1);
  lens.height_px = std::max<std::uint32_t>(height_px_, 1);
  return lens;
}

void PageViewer::place_camera() {
  // The first view every front end makes (ui/first_camera.hpp): the options' camera, else the
  // tracks framed where the panels and the legend leave room (none yet: no camera).
  const ui::CameraRequest request{options_.camera, options_.look_at};
  if (!request.placement && !request.look_at && model_.tracks.empty()) return;
  try {
    session_.place_first_camera(request, lens());
  } catch (const ui::FirstCameraError& e) {
    throw std::runtime_error(e.why());
  }
}

ui::FramingRoom PageViewer::framing_room(const scene::Lens& l) {
  scene::Scene legend_scene;
  legend_scene.tracks = &model_.tracks;
  legend_scene.style = options_.style;
  legend_scene.color_range = scene::color_range(model_.tracks, options_.style);
  legend_scene.overlay_legend = options_.overlay_legend;
  const scene::KeptClearCorner legend =
      scene::legend_clearance(scene::scene_legend_panel(l.width_px, l.height_px, legend_scene), l.height_px);
  return panels_ ? page_framing_room(model_.settings, l, legend, pixel_ratio_) : ui::FramingRoom{legend, std::nullopt};
}

void PageViewer::take_camera_moves() {
  if (session_.camera_moves() == camera_moves_seen_) return;
  camera_moves_seen_ = session_.camera_moves();
  camera_moved_ = dirty_ = true;
}

void PageViewer::orbit(double dx, double dy) {
  session_.orbit(dx, dy);
  take_camera_moves();
}
void PageViewer::pan(double x0, double y0, double x1, double y1) {
  session_.pan(x0, y0, x1, y1);
  take_camera_moves();
}
void PageViewer::zoom(double steps, double x, double y) {
  session_.zoom(steps, x, y);
  take_camera_moves();
}

bool PageViewer::frame(std::uint32_t width_px, std::uint32_t height_px, double pixel_ratio, double seconds) {
  if (width_px == 0 || height_px == 0) return false;
  if (width_px != width_px_ || height_px != height_px_ || pixel_ratio != pixel_ratio_) {
    pixel_ratio_ = pixel_ratio > 0.0 ? pixel_ratio : 1.0;
    width_px_ = width_px;
    height_px_ = height_px;
    if (session_.has_camera())
      session_.camera().set_image_size(width_px, height_px);
    else if (!model_.tracks.empty() || options_.look_at || options_.camera)
      place_camera();
    dirty_ = legend_dirty_ = true;
  }
  if (session_.has_camera() && session_.camera().animating()) {
    session_.update(seconds);
    dirty_ = true;
  }
  since_drawn_s_ += seconds;
  // Tiles the view wants beyond those on their way are asked for by the next frame's request:
  // while any are missing, a frame now and then (each arrival also asks for one).
  if (terrain_report_.progress.pending() > 0 && since_drawn_s_ > 0.25) dirty_ = true;
  const bool interface_due = ui_frames_ > 0 || input_.pending() || model_.clock.playing();
  if (!dirty_ && !interface_due) return false;
  if (ui_frames_ > 0) --ui_frames_;
  if (interface_frame(width_px, height_px, pixel_ratio, seconds)) dirty_ = legend_dirty_ = true;
  // The scene again only when it changed; else the last picture under the new interface.
  if (dirty_ || !target_.show_kept()) draw_scene(width_px, height_px, pixel_ratio);
  imgui_.render();
  // This frame's interface was drawn with the tile figures of the scene drawn before: when this
  // frame's scene changed them (tiles came, or the view wants others), the interface is drawn
  // again with them, so "Loading terrain" goes away once the last tile is in, view moving or not.
  const terrain::LoadProgress& now = terrain_report_.progress;
  const terrain::LoadProgress& shown = shown_progress_;
  if (panels_ && session_.has_camera() &&
      (now.wanted != shown.wanted || now.loaded != shown.loaded || now.no_data != shown.no_data ||
       now.failed != shown.failed))
    ui_frames_ = std::max(ui_frames_, 1);
  return true;
}

bool PageViewer::interface_frame(std::uint32_t width_px, std::uint32_t height_px, double pixel_ratio, double seconds) {
  ImGuiIO& io = ImGui::GetIO();
  const float ratio = static_cast<float>(pixel_ratio > 0.0 ? pixel_ratio : 1.0);
  io.DisplaySize = ImVec2(static_cast<float>(width_px) / ratio, static_cast<float>(height_px) / ratio);
  io.DisplayFramebufferScale = ImVec2(ratio, ratio);
  io.DeltaTime = static_cast<float>(std::clamp(seconds, 1e-3, 1.0));
  const bool pressed = input_.apply(io);
  if (pressed || input_.moved()) ui_frames_ = std::max(ui_frames_, kUiFramesAfterInput);
  model_.settings.sun_time_unix = sun_time();  // what the shading panel starts from
  imgui_.begin_frame();
  if (session_.has_camera() && !io.WantCaptureKeyboard && handle_keys(seconds)) ui_frames_ = std::max(ui_frames_, 1);
  // A click on a photo's pin in the picture (not on a panel; with or without the panels) shows it
  // larger and flies to it, as its line in the Tracks panel does. (Drags, the wheel and pinches
  // come from the page's JavaScript as gestures: orbit, pan, zoom.)
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.WantCaptureMouse)
    if (const auto at = input_.position()) {
      const std::uint64_t photos = model_.waypoints.revision;
      session_.click(at->x * ratio, at->y * ratio);
      if (model_.waypoints.revision != photos) dirty_ = true;
      take_camera_moves();
    }
  if (!panels_) return false;  // nothing drawn: the frame's draw data is empty
  if (!panels_placed_) {
    // Their first places for the window's size (page_panels: folded on a small window).
    const float bar = ImGui::GetFrameHeight();
    const std::string placement = panel_settings_ini(
        page_panel_layout(io.DisplaySize.x, io.DisplaySize.y, model_.settings.show_menu ? bar : 0.0f, bar));
    ImGui::LoadIniSettingsFromMemory(placement.c_str(), placement.size());
    panels_placed_ = true;
  }
  const ui::PanelActions actions = ui::draw_panels(model_, seconds);
  if (panel_keeper_.keep_in_view(model_)) ui_frames_ = std::max(ui_frames_, 2);
  // An edit in the panels (a click, a key, the wheel over them, or a slider dragged: an item held
  // while the pointer moves, not a panel being moved) may have changed the scene.
  const bool dragging = ImGui::IsAnyItemActive() && input_.moved() && !ImGui::GetCurrentContext()->MovingWindow;
  const bool edited = (pressed && (io.WantCaptureMouse || io.WantCaptureKeyboard)) || dragging;
  if (edited) {
    // Into the address like the options they stand for, so a copied link keeps them.
    for (auto& change : style_option_changes(options_.style, model_.settings.style)) {
      std::erase_if(given_options_, [&](const auto& kv) { return kv.first == change.first; });
      given_options_.push_back(std::move(change));
    }
    options_.style = model_.settings.style;
    // The shading panel's time of day: the `time` option.
    const double sun = model_.settings.sun_time_unix;
    if (!std::isnan(sun) && sun != sun_time()) {
      options_.time_unix_s = sun;
      std::erase_if(given_options_, [](const auto& kv) { return kv.first == "time"; });
      given_options_.emplace_back("time", track::format_iso_time(std::round(sun)));
    }
  }
  const std::uint64_t photos = model_.waypoints.revision;
  session_.apply(actions);
  if (model_.waypoints.revision != photos) dirty_ = true;  // a photo shown larger
  // The replay's camera follow: the scene is drawn again each frame it moves the camera.
  session_.follow_replay();
  take_camera_moves();
  if (session_.has_camera()) {
    // The hover follows the pointer over the picture (not over a panel), in device pixels.
    if (input_.moved() && !io.WantCaptureMouse) {
      if (const auto at = input_.position())
        session_.hover_at(at->x * ratio, at->y * ratio);
      else
        session_.clear_hover();
    }
    scene::CameraController& controller = session_.camera();
    const ui::OverlayState overlay{
        model_, controller.camera(), terrain_report_.progress, status_line_, controller.view().heading_deg, std::nullopt};
    shown_progress_ = terrain_report_.progress;
    if (ui::draw_overlays(overlay)) controller.reset_north();
  }
  return edited;
}

bool PageViewer::handle_keys(double seconds) {
  // The DOM's key codes (page_input.hpp): letters as upper case, 37-40 the arrows, 33/34 page up
  // and down, 187/189 for =/- (107/109 keypad).
  using ui::ViewerKey;
  ui::KeyInput keys;
  const auto held = [&](ViewerKey key, std::initializer_list<int> codes) {
    for (const int code : codes)
      if (ImGui::IsKeyDown(code)) keys.hold(key);
  };
  const auto pressed = [&](ViewerKey key, int code) {
    if (ImGui::IsKeyPressed(code, false)) keys.press(key);
  };
  held(ViewerKey::forward, {'W', 38});
  held(ViewerKey::back, {'S', 40});
  held(ViewerKey::right, {'D', 39});
  held(ViewerKey::left, {'A', 37});
  held(ViewerKey::orbit_left, {'Q'});
  held(ViewerKey::orbit_right, {'E'});
  held(ViewerKey::tilt_up, {33});
  held(ViewerKey::tilt_down, {34});
  held(ViewerKey::zoom_in, {187, 107});
  held(ViewerKey::zoom_out, {189, 109});
  pressed(ViewerKey::north, 'N');
  pressed(ViewerKey::fly_to_selected, 'F');
  pressed(ViewerKey::play_pause, ' ');
  const bool held_any = session_.keys(keys, seconds);
  take_camera_moves();
  return held_any;
}

bool PageViewer::draw_picture() {
  if (width_px_ == 0 || height_px_ == 0) return false;
  if (dirty_ || !target_.show_kept()) draw_scene(width_px_, height_px_, pixel_ratio_);
  ui_frames_ = kUiFramesAfterInput;
  return true;
}

double PageViewer::sun_time() const {
  if (options_.time_unix_s) return *options_.time_unix_s;
  return model_.tracks.empty() ? noon_today(kOverviewLonDeg) : scene::default_sun_time(recorded_);
}

bool PageViewer::wants_mouse() const { return imgui_.wants_mouse(); }
bool PageViewer::wants_keyboard() const { return imgui_.wants_keyboard(); }

void PageViewer::draw_scene(std::uint32_t width_px, std::uint32_t height_px, double pixel_ratio) {
  dirty_ = false;
  since_drawn_s_ = 0.0;
  scene::Scene scene;
  scene.tracks = &model_.tracks;
  scene.style = options_.style;
  // The robust range sorts every value: only when the tracks or the style changed (what also
  // changes the legend), not for each camera move.
  if (legend_dirty_) color_range_ = scene::color_range(model_.tracks, options_.style);
  scene.color_range = color_range_;
  scene.overlay_legend = options_.overlay_legend;
  scene.sun_time_unix_s = sun_time();
  scene.terrain = terrain_view_.get();
  if (!model_.waypoints.points.empty()) scene.waypoints = &model_.waypoints;
  // Where the terrain has no tiles the ground lies at the lowest terrain loaded; before any has
  // come (or without terrain, or offline), at the tracks' lowest point.
  const bool terrain_came = terrain_view_ && terrain_report_.progress.loaded > 0;
  scene.neutral_ground_m = terrain_came ? std::numeric_limits<double>::quiet_NaN() : recorded_.lowest_or_sea_level();
  target_.pixel_ratio = pixel_ratio;
  target_.window_width_px = static_cast<int>(width_px);
  target_.window_height_px = static_cast<int>(height_px);
  if (session_.has_camera()) {
    terrain_report_ = renderer_.draw(scene, session_.camera().camera(), target_).terrain;
  } else {
    // Nothing to look at yet: the neutral ground from above a place, so the page is not black.
    scene::LookAt overview;
    overview.target = {46.6, kOverviewLonDeg, 0.0};
    overview.distance_m = 20000.0;
    scene::CameraController start(overview, lens());
    terrain_report_ = renderer_.draw(scene, start.camera(), target_).terrain;
  }
  model_.loading = terrain_report_.progress.pending() > 0;
  if (legend_dirty_) {
    legend_ = page_legend(scene, width_px, height_px);
    legend_dirty_ = false;
    ++legend_version_;
  }
  ++frames_drawn_;
}

std::string PageViewer::run_script(std::string_view text) {
  nlohmann::json result = {{"output", ""}, {"error", nullptr}};
  std::string printed;
  try {
    const ui::ViewScript script = ui::parse_view_script(text, "script");
    std::optional<glm::dvec2> cursor;  // the last `hover`: the desktop hovers there each frame
    for (const ui::ScriptCommand& c : script.commands) {
      using Kind = ui::ScriptCommand::Kind;
      if (c.kind == Kind::print_hover && cursor) session_.hover_at(cursor->x, cursor->y);
      if (const std::optional<std::string> out = ui::run_session_command(session_, c, script.file)) {
        printed += *out;
      } else if (c.kind == Kind::hover) {
        cursor = glm::dvec2(c.x, c.y);
      } else if (c.kind == Kind::hide_panels) {
        panels_ = false;
      } else if (c.kind != Kind::wait) {
        throw ui::ScriptError(fmt::format("{}:{}: the page has no pictures, frame times or films of its own to "
                                          "script (the desktop's `view --script` has)",
                                          script.file, c.line));
      }
      if (cursor) session_.hover_at(cursor->x, cursor->y);
    }
  } catch (const std::exception& e) {
    result["error"] = e.what();
  }
  result["output"] = printed;
  take_camera_moves();
  dirty_ = legend_dirty_ = true;
  ui_frames_ = kUiFramesAfterInput;
  return result.dump();
}

std::string PageViewer::view_state() const {
  std::string out;
  if (session_.has_camera()) {
    const scene::LookAt& v = session_.camera().view();
    out = fmt::format("look-at={:.6f},{:.6f},{:.1f}&distance={:.1f}&heading={:.2f}&pitch={:.2f}", v.target.lat_deg,
                      v.target.lon_deg, v.target.height_m, v.distance_m, v.heading_deg, v.pitch_deg);
  }
  for (const auto& [name, value] : given_options_)
    out += (out.empty() ? "" : "&") + name + (value.empty() ? "" : "=" + address_value(value));
  return out;
}

std::string PageViewer::status_json() const {
  nlohmann::json j;
  j["tracks"] = nlohmann::json::array();
  for (const scene::Track& t : model_.tracks.tracks()) {
    const glm::vec3 c = t.color_srgb;
    const auto byte = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    j["tracks"].push_back({{"name", t.name},
                           {"points", t.point_count()},
                           {"color", fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b))}});
  }
  if (color_range_) j["color_range"] = {color_range_->min, color_range_->max};
  j["warnings"] = session_.warnings();
  const terrain::LoadProgress& p = terrain_report_.progress;
  j["tiles"] = {{"wanted", p.wanted}, {"loaded", p.loaded}, {"no_data", p.no_data}, {"failed", p.failed}};
  // Fetched tiles held until the loader takes them (those that arrived after the view moved on
  // are never taken), and the bytes they hold.
  std::size_t kept = 0, kept_bytes = 0, dropped = 0;
  for (const auto& f : fetched_) {
    kept += f->kept();
    kept_bytes += f->kept_bytes();
    dropped += f->dropped();
  }
  j["tiles"]["kept"] = kept;
  j["tiles"]["kept_bytes"] = kept_bytes;
  j["tiles"]["dropped"] = dropped;  // let go at the bound (FetchedTiles)
  j["tile_failures"] = terrain_report_.failures;
  // The sources in use and the page's defaults, for its "Terrain & imagery" form.
  const auto sources = [](const PageOptions& o) {
    const auto encoding = o.terrain.encoding.value_or(terrain::HeightEncoding::terrarium);
    return nlohmann::json{{"terrain", o.terrain.source},
                          {"terrain_encoding", std::string(terrain::to_string(encoding))},
                          {"imagery", o.imagery.source}};
  };
  j["sources"] = sources(options_);
  static const PageOptions defaults;
  j["default_sources"] = sources(defaults);
  j["frames_drawn"] = frames_drawn_;
  // serve's pins: the photos (their thumbnails in, the one enlarged, the larger picture it wants:
  // the page fetches it) and the place labels.
  nlohmann::json photos = {{"count", large_urls_.size()}, {"thumbnails", photos_in_}, {"enlarged", -1},
                           {"wanted", nullptr}, {"names", nlohmann::json::array()}};
  std::size_t places = 0;
  nlohmann::json place_names = nlohmann::json::array();
  for (std::size_t i = 0; i < model_.waypoints.points.size(); ++i) {
    const scene::Waypoint& w = model_.waypoints.points[i];
    if (w.kind == scene::WaypointKind::Place) {
      ++places;
      if (place_names.size() < 50) place_names.push_back(w.name);
    }
    if (w.kind != scene::WaypointKind::Photo || i < first_photo_ || i - first_photo_ >= large_urls_.size()) continue;
    const std::size_t photo = i - first_photo_;
    photos["names"].push_back(w.name);
    if (!w.enlarged) continue;
    photos["enlarged"] = photo;
    if (!large_in_[photo] && !large_urls_[photo].empty()) photos["wanted"] = {{"index", photo}, {"url", large_urls_[photo]}};
  }
  j["photos"] = photos;
  j["places"] = {{"count", places}, {"names", place_names}};
  // What a viewer shows, as the desktop's `print-state` prints it; what the pointer is over (a track
  // point, a pin or an airspace wall, with its tooltip's lines) also as "hover".
  j["session"] = nlohmann::json::parse(ui::session_state_json(session_));
  j["hover"] = j["session"]["hover"];
  // What the Statistics panel shows for its track, and the profile's range selection (the same
  // lines the panels draw).
  nlohmann::json statistics = {{"track", model_.selected_track}, {"lines", nlohmann::json::array()}};
  if (model_.selected_track >= 0 && model_.selected_track < static_cast<int>(model_.tracks.size()))
    statistics["lines"] =
        ui::statistics_lines(model_.tracks[static_cast<std::size_t>(model_.selected_track)].summary.clean);
  j["statistics"] = statistics;
  // The tile figures the interface was last drawn with (its "Loading terrain: N/M tiles" line and
  // the Tracks panel's "loading terrain...", shown while tiles are pending).
  j["interface"] = {{"wants_mouse", wants_mouse()},
                    {"wants_keyboard", wants_keyboard()},
                    {"tiles_shown",
                     {{"wanted", shown_progress_.wanted},
                      {"loaded", shown_progress_.loaded},
                      {"no_data", shown_progress_.no_data},
                      {"failed", shown_progress_.failed}}}};
  // The panels as they are now, in CSS pixels (height: unfolded; content: what their contents
  // need, scroll: how much of it lies out of sight).
  nlohmann::json panels = nlohmann::json::object();
  for (const char* name : kPanelNames) {
    const ImGuiWindow* w = panels_ ? ImGui::FindWindowByName(name) : nullptr;
    if (w == nullptr || !w->Active) continue;
    panels[name] = {{"x", w->Pos.x},
                    {"y", w->Pos.y},
                    {"width", w->SizeFull.x},
                    {"height", w->SizeFull.y},
                    {"collapsed", w->Collapsed},
                    {"content_height", w->ContentSize.y},
                    {"scroll_max", w->ScrollMax.y}};
  }
  j["panels"] = panels;
  j["selection"] = model_.selection.statistics ? ui::statistics_lines(*model_.selection.statistics)
                                               : std::vector<std::string>{};
  j["legend"] = {{"x", legend_.rect.x},
                 {"y", legend_.rect.y},
                 {"width", legend_.rgba.empty() ? 0 : legend_.rect.width},
                 {"height", legend_.rgba.empty() ? 0 : legend_.rect.height},
                 {"version", legend_version_}};
  return j.dump();
}

}  // namespace trailray::web
