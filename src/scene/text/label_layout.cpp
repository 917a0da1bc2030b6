#include "scene/text/label_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "scene/volumes/volume_shapes.hpp"

namespace trailray::scene {
namespace {

// Below this opacity a label is not worth the room it takes from others.
constexpr float kMinAlpha = 0.02f;

glm::u8vec3 to_bytes(const glm::vec3& srgb) {
  return glm::u8vec3(glm::round(glm::clamp(srgb, glm::vec3(0.0f), glm::vec3(1.0f)) * 255.0f));
}

// A track's colour as a label's text: lifted towards white until it is light enough to read on
// the dark halo (a navy track gets a pale blue name), hue kept.
glm::u8vec3 track_label_color(const glm::vec3& srgb) {
  glm::vec3 c = srgb;
  // Luma of the sRGB values (Rec. 709 weights): cheap, and monotonic in the mix.
  for (int step = 0; step < 10 && glm::dot(c, glm::vec3(0.2126f, 0.7152f, 0.0722f)) < 0.6f; ++step)
    c = glm::mix(c, glm::vec3(1.0f), 0.2f);
  return to_bytes(c);
}

constexpr glm::u8vec3 kWaypointColor{255, 255, 255};
constexpr glm::u8vec3 kPlaceColor{255, 240, 200};    // warm: a place is not one of the files' points
constexpr glm::u8vec3 kThermalColor{255, 205, 140};  // the thermal markers' orange, lifted to read on the halo

struct Projected {
  std::size_t index;
  glm::dvec2 pixel;
  double distance_m;
};

PixelRect inflated(const PixelRect& r, int by) { return {r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by}; }

// The boxes a label of size (w, h) tries around its anchor, in order of preference.
// The boxes a label of size (w, h) tries around its anchor, in order of preference; `clear` pixels
// above the anchor belong to its pin (the boxes above and beside go around them).
std::array<PixelRect, 6> boxes_around(glm::dvec2 anchor, int w, int h, int lift, int clear) {
  const int ax = static_cast<int>(std::floor(anchor.x)), ay = static_cast<int>(std::floor(anchor.y));
  const int top = ay - clear;  // the top of the pin (the anchor itself without one)
  const int above = top - lift - h, beside = top - h / 2;
  return {{
      {ax - w / 2, above, w, h},     // above
      {ax + lift / 2, above, w, h},  // above right
      {ax - lift / 2 - w, above, w, h},
      {ax + lift, beside, w, h},  // right
      {ax - lift - w, beside, w, h},
      {ax - w / 2, ay + lift, w, h},  // below
  }};
}

bool rank_before(const LabelCandidate& a, double da, const LabelCandidate& b, double db) {
  if (a.kind != b.kind) return static_cast<int>(a.kind) < static_cast<int>(b.kind);
  if (a.priority != b.priority) return a.priority > b.priority;
  return da < db;
}

LabelFade subject_fade(std::vector<double> distances) {
  if (distances.empty()) return {};
  const auto middle = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
  std::nth_element(distances.begin(), middle, distances.end());
  return {kFadeFullSubjects * *middle, kFadeZeroSubjects * *middle};
}

}  // namespace

PinClearance pin_clearance(WaypointKind kind, const PinStyle& pins) {
  // The pins' ball is centred its lift above the marker and a diameter across: its top, and two
  // pixels of air (a metre near the camera).
  const bool place = kind == WaypointKind::Place;
  const double ball_px = place ? pins.place_marker_px : pins.marker_px;
  const double ball_m = place ? pins.place_marker_m : pins.marker_m;
  const double lift_px = place ? pins.place_lift_px : pins.lift_px;
  const double lift_m = place ? pins.place_lift_m : pins.lift_m;
  return {lift_px + 0.5 * ball_px + 2.0, lift_m + 0.5 * ball_m + 0.0, ball_px + 1.0, ball_m + 0.5};
}

std::vector<LabelCandidate> label_candidates(const Scene& scene) {
  std::vector<LabelCandidate> out;
  // Photos' thumbnails whatever --no-labels says: they are not names.
  if (scene.waypoints != nullptr)
    for (const Waypoint& w : scene.waypoints->points) {
      if (!w.visible || w.kind != WaypointKind::Photo || w.thumbnail == nullptr) continue;
      const PinClearance pin = pin_clearance(w.kind, scene.style.pins);
      LabelCandidate c{w.name, LabelKind::photo, w.enlarged ? w.priority + 1000 : w.priority, w.marker_ecef,
                       kWaypointColor, pin.px, pin.m, pin.width_px, pin.width_m};
      c.image = w.thumbnail.get();
      c.image_px = scene.style.pins.photo_px * (w.enlarged ? kEnlargedPhotoScale : 1.0);
      out.push_back(std::move(c));
    }
  if (!scene.style.labels.enabled) return out;
  if (scene.tracks != nullptr)
    for (const Track& t : scene.tracks->tracks()) {
      if (!t.visible || t.name.empty()) continue;
      const auto first = std::find_if(t.geometry.segments.begin(), t.geometry.segments.end(),
                                      [](const TrackPolyline& s) { return !s.points_ecef.empty(); });
      if (first == t.geometry.segments.end()) continue;
      out.push_back({t.name, LabelKind::track, 0, first->points_ecef.front(), track_label_color(t.color_srgb)});
    }
  if (scene.waypoints != nullptr)
    for (const Waypoint& w : scene.waypoints->points) {
      if (!w.visible || w.name.empty() || (w.kind == WaypointKind::Photo && w.thumbnail != nullptr)) continue;
      const bool place = w.kind == WaypointKind::Place, thermal = w.kind == WaypointKind::Thermal;
      const PinClearance pin = pin_clearance(w.kind, scene.style.pins);
      out.push_back({w.name,
                     place     ? LabelKind::place
                     : thermal ? LabelKind::thermal
                               : LabelKind::waypoint,
                     w.priority, w.marker_ecef,
                     place     ? kPlaceColor
                     : thermal ? kThermalColor
                               : kWaypointColor,
                     pin.px, pin.m, pin.width_px, pin.width_m});
    }
  // Airspaces' names after every point's (as places of the lowest priority), in their class's
  // colour: where the volume's middle is, halfway up.
  if (scene.volumes != nullptr)
    for (const VolumeLabel& v : airspace_labels(*scene.volumes))
      out.push_back({v.text, LabelKind::place, 0, v.anchor_ecef, track_label_color(v.color_srgb)});
  return out;
}

float label_fade_alpha(double distance_m, const LabelFade& fade) {
  if (!(distance_m > fade.full_m)) return 1.0f;
  if (!(distance_m < fade.zero_m)) return 0.0f;
  return static_cast<float>((fade.zero_m - distance_m) / (fade.zero_m - fade.full_m));
}

int photo_frame_px(int long_px) { return std::max(2, static_cast<int>(std::lround(long_px / 36.0))); }

int label_halo_px(int font_px) { return std::max(1, static_cast<int>(std::lround(font_px / 7.0))); }
int label_margin_px(int font_px) { return std::max(1, static_cast<int>(std::lround(font_px / 5.0))); }
int label_lift_px(int font_px) { return std::max(2, static_cast<int>(std::lround(font_px * 0.6))); }

TextExtent LabelLayouter::measure(const std::string& text, int font_px, FontWeight weight) {
  std::string key = std::to_string(font_px);
  key += weight == FontWeight::bold ? 'b' : 'r';
  key += text;
  const auto found = extents_.find(key);
  if (found != extents_.end()) return found->second;
  // A viewer that meets endless new names (a long session) must not grow without bound.
  if (extents_.size() > 20000) extents_.clear();
  const TextExtent extent = text_.measure(text, font_px, weight);
  extents_.emplace(std::move(key), extent);
  return extent;
}

std::vector<PlacedLabel> LabelLayouter::layout(const std::vector<LabelCandidate>& candidates, const Camera& camera,
                                               const LabelLayoutOptions& options) {
  std::vector<PlacedLabel> placed;
  const double ratio = std::isfinite(options.pixel_ratio) && options.pixel_ratio > 0.0 ? options.pixel_ratio : 1.0;
  const int font_px = std::clamp(static_cast<int>(std::lround(options.size_px * ratio)), 1, 512);
  const auto width = static_cast<double>(camera.lens().width_px), height = static_cast<double>(camera.lens().height_px);
  const PixelRect picture{0, 0, static_cast<int>(width), static_cast<int>(height)};

  // 2. In view: in front of the camera, before the far plane, the anchor inside the picture.
  // A pin can reach into the picture from an anchor just outside it: those are kept for 5.
  std::vector<Projected> in_view, in_front;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto p = camera.project(candidates[i].anchor_ecef);
    if (!p || p->depth_m > camera.depth_range().far_m) continue;
    const Projected projected{i, {p->x_px, p->y_px}, glm::length(candidates[i].anchor_ecef - camera.position())};
    in_front.push_back(projected);
    if (p->x_px >= 0.0 && p->x_px < width && p->y_px >= 0.0 && p->y_px < height) in_view.push_back(projected);
  }
  // 3. Faded by distance.
  std::vector<double> distances;
  for (const Projected& p : in_view) distances.push_back(p.distance_m);
  const LabelFade fade = options.fade ? *options.fade : subject_fade(distances);
  std::vector<std::pair<Projected, float>> shown;
  for (const Projected& p : in_view) {
    const float alpha = label_fade_alpha(p.distance_m, fade);
    if (alpha >= kMinAlpha) shown.emplace_back(p, alpha);
  }
  // 4. By priority.
  std::stable_sort(shown.begin(), shown.end(), [&](const auto& a, const auto& b) {
    return rank_before(candidates[a.first.index], a.first.distance_m, candidates[b.first.index], b.first.distance_m);
  });
  // 5. Greedy placement, off the pins in view.
  const double tan_half_fov = std::tan(0.5 * camera.lens().vertical_fov_deg * M_PI / 180.0);
  const auto metres_per_px = [&](double distance_m) { return 2.0 * distance_m * tan_half_fov / height; };
  const auto pin_height = [&](const LabelCandidate& c, double distance_m) {
    return static_cast<int>(std::lround(std::max(c.clear_px, c.clear_m / metres_per_px(distance_m))));
  };
  std::vector<std::pair<std::size_t, PixelRect>> pins;  // candidate index, the pin's rectangle
  for (const Projected& p : in_front) {
    const LabelCandidate& c = candidates[p.index];
    if (c.clear_px <= 0.0 && c.clear_m <= 0.0) continue;
    const int h = pin_height(c, p.distance_m);
    const int w =
        static_cast<int>(std::lround(std::max(c.clear_width_px, c.clear_width_m / metres_per_px(p.distance_m))));
    pins.emplace_back(p.index, PixelRect{static_cast<int>(std::floor(p.pixel.x)) - w / 2,
                                         static_cast<int>(std::floor(p.pixel.y)) - h, w, h + 1});
  }
  const int halo = label_halo_px(font_px), margin = label_margin_px(font_px), lift = label_lift_px(font_px);
  std::vector<PixelRect> taken;  // placed boxes grown by the margin
  for (const auto& [p, alpha] : shown) {
    const LabelCandidate& c = candidates[p.index];
    const FontWeight weight = c.kind == LabelKind::track ? FontWeight::bold : FontWeight::regular;
    // A photo: its thumbnail at the style's size in picture pixels, aspect kept, in its frame.
    const bool photo = c.image != nullptr && c.image->pixels.width > 0 && c.image->pixels.height > 0;
    TextExtent extent;
    int frame = 0, w = 0, h = 0;
    if (photo) {
      // An enlarged photo still fits above its pin: at most 45 % of the picture's short side.
      const int most = std::max(8, static_cast<int>(0.45 * std::min(width, height)));
      const int long_px = std::clamp(static_cast<int>(std::lround(c.image_px * ratio)), 8, std::min(1024, most));
      const double aspect = static_cast<double>(c.image->pixels.width) / c.image->pixels.height;
      frame = photo_frame_px(long_px);
      w = (aspect >= 1.0 ? long_px : std::max(1, static_cast<int>(std::lround(long_px * aspect)))) + 2 * frame;
      h = (aspect >= 1.0 ? std::max(1, static_cast<int>(std::lround(long_px / aspect))) : long_px) + 2 * frame;
    } else {
      extent = measure(c.text, font_px, weight);
      if (extent.width <= 0) continue;
      w = extent.width + 2 * halo;
      h = extent.height() + 2 * halo;
    }
    const auto boxes = boxes_around(p.pixel, w, h, lift, pin_height(c, p.distance_m));
    // A thumbnail stays over its pin: the boxes above it only.
    for (std::size_t b = 0; b < (photo ? 3u : boxes.size()); ++b) {
      const PixelRect& box = boxes[b];
      if (!picture.contains(box)) continue;
      const auto overlaps = [&](const PixelRect& r) { return r.intersects(box); };
      if (std::any_of(taken.begin(), taken.end(), overlaps)) continue;
      if (std::any_of(options.keep_out.begin(), options.keep_out.end(), overlaps)) continue;
      if (std::any_of(pins.begin(), pins.end(), [&](const auto& pin) { return overlaps(pin.second); })) continue;
      taken.push_back(inflated(box, margin));
      PlacedLabel label;
      label.candidate = p.index;
      label.text = c.text;
      label.image = photo ? c.image : nullptr;
      label.frame_px = frame;
      label.kind = c.kind;
      label.color = c.color;
      label.weight = weight;
      label.font_px = font_px;
      label.halo_px = halo;
      label.box = box;
      label.pen_x = box.x + halo;
      label.baseline_y = box.y + halo + extent.ascent;
      label.anchor_px = p.pixel;
      label.anchor_distance_m = p.distance_m;
      if (c.clear_px > 0.0 || c.clear_m > 0.0)
        label.pin_reach_m = pin_height(c, p.distance_m) * metres_per_px(p.distance_m);
      label.alpha = alpha;
      placed.push_back(std::move(label));
      break;
    }
  }
  return placed;
}

}  // namespace trailray::scene
