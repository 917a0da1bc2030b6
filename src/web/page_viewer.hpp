#pragma once
// The page's viewer: the tracks opened in the page (files dropped or picked, or fetched from
// `?track=` URLs, handed over as bytes), drawn with the desktop's renderer into the page's
// WebGL 2 canvas, from a camera the person moves (scene::CameraController, as on the desktop).
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

  // The view as option text for the fragment ("look-at=LAT,LON,ALT&distance=M&heading=D&pitch=D"
  // plus the style options given), so a copied address reproduces it.
  std::string view_state() const;
  // What the page shows beside the picture, as JSON: the tracks (name, points, colour), the colour
  // scale, the warnings of the last file opened, the frames drawn, the tiles (wanted, in, and the
  // fetched ones kept), and what the panels show (the Statistics panel's and the range
  // selection's lines, the tile figures the interface was drawn with, each panel's place).
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
  void update_hover(double x_px, double y_px);
  // The desktop viewer's keys (app/view/viewer_input.cpp) from ImGui's key state: true while one
  // that moves the camera is held (frames must go on).
  bool handle_keys(double seconds);
  // The sun's time: the `time` option (or the shading panel's), else the tracks' day at noon, or
  // today's noon where the page looks before any track is open.
  double sun_time() const;
  void fly_to_track(int index);
  // A waypoint clicked (its pin, or its line in the Tracks panel): the camera flies to it; a
  // photo is shown larger too.
  void fly_to_waypoint(int index);
  // A photo's pin (index into the model's waypoints) shown larger (the others back to their
  // size), as the desktop viewer's click on it; its larger picture is asked for (status_json's
  // "photos"."wanted") until it arrives.
  void enlarge_photo(int waypoint);
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
  ui::ViewerModel model_;  // the tracks, the panels' settings, hover, selection, replay
  // serve's photos: photo i is waypoint first_photo_ + i; its larger picture's URL, and whether
  // it is in (the thumbnail replaced by it).
  std::size_t first_photo_ = 0;
  std::vector<std::string> large_urls_;
  std::vector<bool> large_in_;
  int photos_in_ = 0;  // thumbnails arrived
  scene::RecordedPoints recorded_;
  std::optional<scene::CameraController> camera_;
  bool camera_moved_ = false;  // by a gesture or an option: opening another track keeps the view
  bool dirty_ = true;
  std::uint32_t width_px_ = 0, height_px_ = 0;
  double pixel_ratio_ = 1.0;
  std::vector<std::string> warnings_;
  std::string status_line_;  // the overlay's line at the bottom (nothing to say yet)
  std::uint64_t frames_drawn_ = 0;
  PageLegend legend_;
  bool legend_dirty_ = true;                      // tracks, style or size changed
  std::optional<track::ValueRange> color_range_;  // of the last frame
  std::uint64_t legend_version_ = 0;
  int files_opened_ = 0;
};

}  // namespace trailray::web
