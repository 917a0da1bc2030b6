// The viewer's camera as the window sees it: the first view, where a framing may put the tracks
// (clear of the panels and the legend), and a photo decoded larger; the flights, the follow and the
// rest are the session's (ui/viewer_session.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <CLI/CLI.hpp>  // the camera options' error, as the other commands' first camera

#include "app/view/legend_overlay.hpp"
#include "app/view/viewer_shell.hpp"
#include "scene/pins/photo_decode.hpp"
#include "app/view/viewer_ui.hpp"
#include "scene/text/legend_content.hpp"
#include "ui/first_camera.hpp"
#include "ui/framing_room.hpp"
#include "ui/panel_layout.hpp"

namespace trailray::app::view {

// The first view: ui::first_view, as the page's, with the heights under a requested camera read
// from the terrain (tiles loaded for it).
scene::LookAt first_view(const ViewerOptions& o, const scene::TrackSet& tracks, const scene::WaypointSet& waypoints,
                         terrain::HeightSource* heights, double neutral, const FramingRoom& room,
                         scene::Diagnostics* diagnostics) {
  ui::CameraRequest request{o.camera.placement, o.camera.look_at};
  const ui::GroundHeight ground = [heights](double lat, double lon) { return ground_height_at(heights, lat, lon); };
  std::optional<scene::LookAt> view;
  try {
    view = ui::first_view(request, o.lens, tracks, waypoints, neutral, ground, room, diagnostics);
  } catch (const ui::FirstCameraError& e) {
    if (e.option().empty()) throw std::runtime_error(e.what());
    throw CLI::ValidationError(e.option(), e.why());
  }
  if (!view) throw std::runtime_error("no track could be read and no camera was given (--camera or --look-at)");
  return *view;
}

void ViewerApp::decode_larger_photo(scene::Waypoint& w, int long_side_px) {
  try {
    // The orientation is in the pixels already: the file's own, read again with them.
    const auto orientation = photo_orientations_.find(w.source);
    w.thumbnail = scene::make_photo_image(scene::decode_photo(
        w.source, long_side_px, orientation != photo_orientations_.end() ? orientation->second : 1));
  } catch (const scene::PhotoDecodeError& e) {
    diagnostics_.warning(e.what());
  }
}

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
