#pragma once
// The page's viewer: the tracks opened in the page (files dropped or picked, or fetched from
// `?track=` URLs, handed over as bytes), drawn with the desktop's renderer into the page's
// WebGL 2 canvas. What a viewer is (the model, the camera, hover, keys, fly-to, the first view)
// is ui::ViewerSession, the desktop's too: this shell hands it the page's input and time.
// The page's JavaScript (page/app.js) owns the DOM: it passes files, options and gestures in
// through page_api.cpp and asks for a frame each animation frame; a frame is drawn only when
// something changed.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/frame_target.hpp"
#include "render/platform/imgui_layer.hpp"
#include "render/renderer.hpp"
#include "scene/camera/camera_controller.hpp"
#include "scene/terrain_view.hpp"
#include "scene/tracks/track_files.hpp"
#include "scene/tracks/track_set.hpp"
#include "ui/viewer_model.hpp"
#include "ui/viewer_session.hpp"
#include "web/fetched_tiles.hpp"
#include "web/page_input.hpp"
#include "web/page_legend.hpp"
#include "web/page_options.hpp"
#include "web/page_panels.hpp"
#include "web/page_pins.hpp"

namespace trailray::web {

class PageViewer {
 public:
  // Draws into the page's current WebGL 2 context (page_api.cpp makes it).
  PageViewer();

  // Reads a track file given by name and bytes (any format the readers know, gzip too). "" when
  // it opened, else the error naming the file and the position; what was open stays open.
  std::string open_track(const std::string& name, std::string_view bytes);
  // An option by the command line's name (page_options.hpp); "" or the error.
  std::string set_option(std::string_view name, std::string_view value);
  // `trailray serve`'s photos and places (its /api/config.json: page_pins.hpp) as the scene's
  // pins, replacing any given before; "" or the error.
  std::string set_served_pins(std::string_view json);
  // Photo `index`'s picture (JPEG, PNG or WebP bytes) for its pin: its thumbnail, or (`large`)
  // the larger one shown while it is enlarged; "" or the error.
  std::string set_photo_picture(int index, bool large, std::string_view bytes);

  // Gestures, in canvas pixels (device pixels, y down).
  void orbit(double dx_px, double dy_px);
  void pan(double from_x, double from_y, double to_x, double to_y);
  void zoom(double steps, double x_px, double y_px);

  // The pointer, wheel and keys for the panels (and the hover); the gestures above move the camera
  // when the panels do not want them (wants_mouse, wants_keyboard: as of the last frame).
  PageInput& input() {
    ui_frames_ = kUiFramesAfterInput;
    return input_;
  }
  bool wants_mouse() const;
  bool wants_keyboard() const;
  // The scene's picture alone in the canvas (the screenshot's: no panels); the next frame draws
  // the interface over it again. False before the first frame.
  bool draw_picture();

  // Draws a frame into the canvas of `width_px` x `height_px` device pixels (`pixel_ratio` of
  // them per CSS pixel) when anything changed since the last, or a camera flight is under way.
  // The panels and what lies over the picture (tooltip, markers, compass) are drawn with it; when
  // only they changed, the last picture of the scene is shown again under them. Returns whether
  // it drew.
  bool frame(std::uint32_t width_px, std::uint32_t height_px, double pixel_ratio, double seconds_since_last);

  // Runs a script of the desktop's `view --script` commands (ui/view_script.hpp) on the viewer:
  // the session's as the desktop runs them (ui/script_session.hpp), `hover X Y` at once (and again
  // after each later command, as the desktop's cursor stays), `hide-panels`; `wait` draws nothing
  // (the page draws its frames as they come); pictures and films are the desktop's (an error).
  // JSON: {"output": what the prints printed, "error": null or "script:LINE: ..."}.
  std::string run_script(std::string_view text);
  // The view as option text for the fragment ("look-at=LAT,LON,ALT&distance=M&heading=D&pitch=D"
  // plus the style options given), so a copied address reproduces it.
  std::string view_state() const;
  // What the page shows beside the picture, as JSON: the tracks (name, points, colour), the colour
  // scale, the warnings of the last file opened (reading it and building the tracks), the frames
  // drawn, the tiles (wanted, in, and the fetched ones kept), what the panels show (the Statistics
  // panel's and the range selection's lines, the tile figures the interface was drawn with, each
  // panel's place), and under "session" what a viewer shows (ui/session_state.hpp: the same JSON
  // as the desktop's `print-state`).
  std::string status_json() const;
  // The legend drawn with the last frame (its place is in status_json, with a version that
  // changes whenever it does).
  const PageLegend& legend() const { return legend_; }

 private:
  void rebuild_tracks();
  void open_terrain();  // the sources of options_.terrain / .imagery, fetched by the page
  void place_camera();
  scene::Lens lens() const;
  // The panels and overlays (ImGui) for this frame; true when an edit may have changed the scene.
  bool interface_frame(std::uint32_t width_px, std::uint32_t height_px, double pixel_ratio, double seconds);
  // The DOM's key codes as the session's keys (ui/viewer_keys.hpp), from ImGui's key state: true
  // while one that moves the camera is held (frames must go on).
  bool handle_keys(double seconds);
  // The room the panels (at their first places) and the legend leave for a framing.
  ui::FramingRoom framing_room(const scene::Lens& lens);
  // After the session moved the camera: drawn again, and opening a track keeps the view.
  void take_camera_moves();
  // The sun's time: the `time` option (or the shading panel's), else the tracks' day at noon, or
  // today's noon where the page looks before any track is open.
  double sun_time() const;
  void draw_scene(std::uint32_t width_px, std::uint32_t height_px, double pixel_ratio);

  // Frames of the interface drawn after an input (ImGui settles hover and active items over a
  // few), without drawing the scene again.
  static constexpr int kUiFramesAfterInput = 3;

  std::vector<std::shared_ptr<FetchedTiles>> fetched_;  // the sources' tiles (for the status)
  std::unique_ptr<terrain::HeightSource> heights_;
  std::unique_ptr<terrain::ImagerySource> imagery_;
  std::unique_ptr<scene::TerrainView> terrain_view_;  // after the sources: goes before them
  scene::TerrainReport terrain_report_;               // of the last frame
  terrain::LoadProgress shown_progress_;              // what the interface last showed of it
  double since_drawn_s_ = 0.0;
  render::Renderer renderer_;
  render::KeptFrameTarget target_;
  render::ImGuiLayer imgui_;
  PageInput input_;
  int ui_frames_ = kUiFramesAfterInput;
  bool panels_ = true;  // false: `no-panels`
  bool panels_placed_ = false;  // their first places given (page_panels)
  PanelKeeper panel_keeper_;
  PageOptions options_;
  std::vector<std::pair<std::string, std::string>> given_options_;  // as given, for view_state
  std::vector<scene::LoadedTrackFile> files_;
  ui::ViewerSession session_;            // the tracks, the panels' settings, hover, selection, replay, camera
  ui::ViewerModel& model_ = session_.model();  // the session's model by its short name
  std::uint64_t camera_moves_seen_ = 0;  // session_.camera_moves() as last taken
  std::vector<std::string> read_warnings_;  // of the last file opened (its reader's)
  // serve's photos: photo i is waypoint first_photo_ + i; its larger picture's URL, and whether
  // it is in (the thumbnail replaced by it).
  std::size_t first_photo_ = 0;
  std::vector<std::string> large_urls_;
  std::vector<bool> large_in_;
  int photos_in_ = 0;  // thumbnails arrived
  scene::RecordedPoints recorded_;
  bool camera_moved_ = false;  // by a gesture or an option: opening another track keeps the view
  bool dirty_ = true;
  std::uint32_t width_px_ = 0, height_px_ = 0;
  double pixel_ratio_ = 1.0;
  std::string status_line_;  // the overlay's line at the bottom (nothing to say yet)
  std::uint64_t frames_drawn_ = 0;
  PageLegend legend_;
  bool legend_dirty_ = true;                      // tracks, style or size changed
  std::optional<track::ValueRange> color_range_;  // of the last frame
  std::uint64_t legend_version_ = 0;
  int files_opened_ = 0;
};

}  // namespace trailray::web
