// The viewer's camera: the first view, flights to a track, the replay's follow, and where a
// framing may put the tracks (clear of the panels and the legend).
#include <algorithm>
#include <cmath>
#include <limits>

#include "app/view/legend_overlay.hpp"
#include "app/view/viewer_shell.hpp"
#include "scene/photo_decode.hpp"
#include "app/view/viewer_ui.hpp"
#include "scene/legend_content.hpp"
#include "ui/framing_room.hpp"
#include "ui/panel_layout.hpp"
#include "ui/replay_follow.hpp"
#include "ui/waypoint_view.hpp"

namespace trailray::app::view {

// The first view: the options' camera, else framed on the tracks where the panels and the
// legend leave the window free; the pivot on the ground.
scene::CameraController first_view(const ViewerOptions& o, const scene::TrackSet& tracks,
                                   const scene::WaypointSet& waypoints, terrain::HeightSource* heights, double neutral,
                                   const FramingRoom& room, scene::Diagnostics* diagnostics) {
  if (o.camera.look_at) return scene::CameraController(*o.camera.look_at, o.lens);
  if (tracks.empty() && waypoints.points.empty() && !o.camera.placement)
    throw std::runtime_error("no track could be read and no camera was given (--camera or --look-at)");
  const scene::Camera camera =
      initial_camera(o.camera, o.lens, tracks, neutral, heights, room.keep_clear, room.area, &waypoints, diagnostics);
  // The pivot where the view's centre meets the tracks' lowest level (no tile read for it).
  return scene::CameraController(scene::CameraController::look_at_from_camera(camera, neutral), o.lens);
}

void ViewerApp::fly_to_track(int index) {
  if (index < 0 || index >= static_cast<int>(model_.tracks.size())) return;
  const scene::Track& t = model_.tracks[static_cast<std::size_t>(index)];
  scene::FramingOptions framing;
  framing.lens = controller_.lens();
  framing.preferred_heading_deg = controller_.view().heading_deg;
  const FramingRoom room = framing_room(framing.lens);
  framing.keep_clear = room.keep_clear;
  framing.area = room.area;
  // The ground under the track when no terrain is in memory: its lowest recorded point, else the
  // neutral ground.
  framing.ground_height_m = t.lowest_altitude();
  if (std::isnan(framing.ground_height_m)) framing.ground_height_m = neutral_;
  const scene::Track* const one[] = {&t};
  const auto framed = scene::frame_tracks(one, framing);
  if (!framed.ok()) return;
  double ground = terrain_.height_in_memory(framed.value->look_at.target.lat_deg, framed.value->look_at.target.lon_deg);
  if (std::isnan(ground)) ground = framed.value->ground_height_m;
  controller_.fly_to(scene::CameraController::look_at_from_camera(framed.value->camera, ground));
}

void ViewerApp::fly_to_waypoint(int index) {
  if (index < 0 || index >= static_cast<int>(model_.waypoints.points.size())) return;
  if (model_.waypoints.points[static_cast<std::size_t>(index)].kind == scene::WaypointKind::Photo) enlarge_photo(index);
  const scene::LookAt& now = controller_.view();
  controller_.fly_to(
      look_at_waypoint(model_.waypoints.points[static_cast<std::size_t>(index)], now.heading_deg, now.pitch_deg));
}

void ViewerApp::enlarge_photo(int index) {
  for (std::size_t i = 0; i < model_.waypoints.points.size(); ++i) {
    scene::Waypoint& w = model_.waypoints.points[i];
    w.enlarged = static_cast<int>(i) == index && w.kind == scene::WaypointKind::Photo && w.thumbnail != nullptr;
    if (!w.enlarged) continue;
    // The thumbnail has 128 texels on its long side; drawn four times larger it wants more.
    const int long_side = static_cast<int>(model_.settings.style.pins.photo_px * scene::kEnlargedPhotoScale * 2.0);
    if (std::max(w.thumbnail->pixels.width, w.thumbnail->pixels.height) >= static_cast<std::uint32_t>(long_side / 2))
      continue;
    try {
      // The orientation is in the pixels already: the file's own, read again with them.
      const auto orientation = photo_orientations_.find(w.source);
      w.thumbnail = scene::make_photo_image(scene::decode_photo(
          w.source, long_side, orientation != photo_orientations_.end() ? orientation->second : 1));
    } catch (const scene::PhotoDecodeError& e) {
      diagnostics_.warning(e.what());
    }
  }
  ++model_.waypoints.revision;
}

void ViewerApp::follow_replay() { ui::follow_replay(model_, controller_); }

// The corner a framing keeps the tracks out of: the legend's, large enough for the legend window
// (where it first appears, in the bottom-left corner) and for the legend of screenshots (drawn
// there too), whichever is larger. Nothing when no legend is shown.
scene::KeptClearCorner ViewerApp::legend_corner(const scene::Lens& lens) {
  if (!model_.settings.style.legend) return {};
  const scene::Scene s = scene();
  const scene::KeptClearCorner picture =
      scene::legend_clearance(scene::scene_legend_panel(lens.width_px, lens.height_px, s), lens.height_px);
  if (!panels_) return picture;  // `hide-panels`: no legend window
  const scene::KeptClearCorner window = scene::legend_clearance(
      legend_overlay_rect(scene::color_legend_for(s.style.tracks, s.color_range),
                          scene::track_key_for(s.style.tracks, model_.tracks), static_cast<float>(lens.width_px),
                          static_cast<float>(lens.height_px)),
      lens.height_px);
  return {scene::ImageCorner::bottom_left, std::max(picture.width_px, window.width_px),
          std::max(picture.height_px, window.height_px)};
}

// With the panels shown, the part of the window their first layout leaves free (right of the
// panel column, below the menu, above the chart), clear of the replay panel's corner; the legend
// window lies under the column, outside that area (if a wide key reaches into it, the area ends
// above it). Without panels (`hide-panels`), the whole window clear of the legend.
FramingRoom ViewerApp::framing_room(const scene::Lens& lens) {
  const scene::KeptClearCorner legend = legend_corner(lens);
  if (!panels_) return {legend, std::nullopt};
  return panel_framing_room(model_.settings, lens, legend);
}

}  // namespace trailray::app::view
