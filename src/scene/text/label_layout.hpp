#pragma once
// Where the names of a scene go on the picture: the labels of waypoints, of place labels and of
// tracks (at their start), laid out in screen space each frame for a camera, GL-free; the
// renderer's labels pass (render/passes/label_pass.hpp) draws what this places.
//
// The layout, in order:
//   1. candidates from the scene (label_candidates): every visible waypoint and place with a
//      name, anchored at its marker and kept clear of its pin's ball above it; every visible
//      track with a name, at its first point;
//   2. projected with the camera: a candidate behind the camera, beyond its far plane, or whose
//      anchor falls outside the picture is dropped;
//   3. faded with distance: full opacity up to `fade.full_m` from the camera, none from
//      `fade.zero_m` (linear between); by default these are 2.5 and 5 times the subject
//      distance, the median distance of the candidates in view (what the picture is about), so
//      a close-up keeps its labels and a view to the horizon thins out the far ones. A label
//      faded below 2 % is dropped;
//   4. sorted by priority: the kind first (track names, then waypoints, thermals, places), then the
//      waypoint's own priority (higher first), then the nearer first;
//   5. placed greedily: each label tries a few boxes around its anchor (above, above right,
//      above left, right, left, below) and takes the first that lies inside the picture, keeps a
//      margin from every label placed before it and stays out of the keep-out rectangles (the
//      legend) and off every pin in view; a label that finds no room is dropped. So no two labels ever overlap, and
//      where two compete the more important, then the nearer, wins.
// Boxes are measured with the font the pass draws with (scene/text/text_raster.hpp) at the label
// size times the pixel ratio, halo included: what is placed is what is drawn.

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/camera/camera.hpp"
#include "scene/pictures/image_paint.hpp"
#include "scene/pins/photo_image.hpp"
#include "scene/scene.hpp"
#include "scene/text/text_raster.hpp"

namespace trailray::scene {

// In priority order: a track's name wins over a photo's thumbnail, which wins over a waypoint's
// name, which wins over a thermal's, which wins over a place's.
enum class LabelKind { track, photo, waypoint, thermal, place };

struct LabelCandidate {
  std::string text;  // UTF-8, one line
  LabelKind kind = LabelKind::waypoint;
  int priority = 0;  // within a kind: higher first
  glm::dvec3 anchor_ecef{0.0};
  glm::u8vec3 color{255, 255, 255};  // the text's colour (sRGB); the halo is dark
  // What stands above the anchor on the picture and must stay visible (a pin): max(clear_px,
  // clear_m seen from the camera) pixels above the anchor, max(clear_width_px, clear_width_m)
  // wide. No label covers it, this one's or another's.
  double clear_px = 0.0, clear_m = 0.0;
  double clear_width_px = 0.0, clear_width_m = 0.0;
  // A photo's thumbnail drawn in place of the text (kind photo): its long side `image_px` at
  // pixel ratio 1, in a white frame; it goes above its pin only (above, above right, above left).
  // The scene owns the image for the frame.
  const PhotoImage* image = nullptr;
  double image_px = 0.0;
};

// How far above a waypoint's (or place's) marker its pin reaches on the picture (the ball's lift
// plus its radius) and how wide it is (the ball), in pixels and at least metres, from the pins' style.
struct PinClearance {
  double px = 0.0, m = 0.0, width_px = 0.0, width_m = 0.0;
};
PinClearance pin_clearance(WaypointKind kind, const PinStyle& pins);

// The scene's labels: visible named waypoints and places, visible named tracks at their first
// point (in the track's colour), visible photos' thumbnails. With style.labels.enabled off only
// the thumbnails (`--no-labels` takes the names away, not the photos the user asked for).
std::vector<LabelCandidate> label_candidates(const Scene& scene);

// Opacity by distance from the camera: 1 up to full_m, 0 from zero_m.
struct LabelFade {
  double full_m = 0.0, zero_m = 0.0;
};
float label_fade_alpha(double distance_m, const LabelFade& fade);
inline constexpr double kFadeFullSubjects = 2.5, kFadeZeroSubjects = 5.0;

struct LabelLayoutOptions {
  int size_px = 13;                 // the em size at pixel ratio 1
  double pixel_ratio = 1.0;         // device pixels per size pixel (a high-DPI window: 2)
  std::vector<PixelRect> keep_out;  // picture areas no label may touch (the legend)
  std::optional<LabelFade> fade;    // nullopt: from the subject distance (see above)
};

struct PlacedLabel {
  std::size_t candidate = 0;  // its index in the candidates
  std::string text;
  const PhotoImage* image = nullptr;  // a photo's thumbnail instead of the text, scaled into `box` inside its frame
  int frame_px = 0;                   // the photo's white frame, inside `box`
  LabelKind kind = LabelKind::waypoint;
  glm::u8vec3 color{255, 255, 255};
  FontWeight weight = FontWeight::regular;
  int font_px = 0;                 // the size drawn, in picture pixels (size_px * pixel_ratio)
  int halo_px = 0;                 // the dark outline's width around the glyphs
  PixelRect box;                   // the text with its halo, picture pixels (y down): nothing is drawn outside it
  int pen_x = 0, baseline_y = 0;   // where the text starts, in picture pixels
  glm::dvec2 anchor_px{0.0};       // the anchor's pixel (continuous, y down)
  double anchor_distance_m = 0.0;  // from the camera to the anchor
  // How far the label's own pin reaches up from the anchor (metres): a surface that much nearer
  // than the anchor may be that pin, seen from above, and must not hide its label.
  double pin_reach_m = 0.0;
  float alpha = 1.0f;  // from the distance fade (the pass adds the terrain's occlusion)
};

// The white frame around a photo's thumbnail whose long side is `long_px` picture pixels.
int photo_frame_px(int long_px);

// The halo around glyphs and the gaps around labels at a font size in picture pixels.
int label_halo_px(int font_px);
int label_margin_px(int font_px);  // kept free between two labels' boxes
int label_lift_px(int font_px);    // between the anchor and the nearest edge of its box

// Lays labels out; keeps the font (FreeType) and the measured text between calls, so a viewer
// lays out its frames without measuring the same names again.
class LabelLayouter {
 public:
  LabelLayouter() = default;

  std::vector<PlacedLabel> layout(const std::vector<LabelCandidate>& candidates, const Camera& camera,
                                  const LabelLayoutOptions& options);

  TextRasterizer& text() { return text_; }

 private:
  TextExtent measure(const std::string& text, int font_px, FontWeight weight);

  TextRasterizer text_;
  std::unordered_map<std::string, TextExtent> extents_;  // by size, weight and text
};

}  // namespace trailray::scene
