#pragma once
// What the track render tests share: polylines built in a local east-north-up frame (straight,
// turning), cameras looking straight down or along a direction, scene options that keep a
// geometric check sharp (no SSAO, no haze, no shadows unless asked), and the pixel classifier.
//
// The classifier: the tests draw tracks in pure red (sRGB 1,0,0) over the grey neutral ground.
// Lit red has no green or blue, and the overlay (ghosts, anti-aliased fringe) is blended in the
// frame's sRGB values, so a pixel's green relative to the same pixel of the picture without
// tracks is 1 - alpha: the track's coverage times its opacity, whatever the lighting of the
// tube. An opaque tube pixel reads 1, a ghost the occluded alpha, a ghost blended twice
// 1 - (1 - a)^2 > a.

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "scene/camera/camera.hpp"
#include "render/gl/framebuffer_readback.hpp"
#include "scene/scene.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene_test_support.hpp"

namespace trailray::render::test {

inline constexpr glm::vec3 kTrackRed{1.0f, 0.0f, 0.0f};

// An east-north-up frame at a geodetic position: points as metres east, north and up from it.
struct LocalFrame {
  glm::dvec3 origin;
  scene::EnuAxes axes;

  explicit LocalFrame(const scene::GeoPosition& at)
      : origin(scene::ecef_from(at)), axes(scene::enu_axes_at(at.lat_deg, at.lon_deg)) {}
  glm::dvec3 point(double east_m, double north_m, double up_m) const {
    return origin + east_m * axes.east + north_m * axes.north + up_m * axes.up;
  }
  glm::dvec3 point(const glm::dvec3& enu) const { return point(enu.x, enu.y, enu.z); }
};

// A segment through the frame's points (east, north, up), optionally with values.
inline scene::TrackPolyline polyline(const LocalFrame& frame, const std::vector<glm::dvec3>& enu,
                              std::vector<float> values = {}) {
  scene::TrackPolyline line;
  for (const glm::dvec3& p : enu) line.points_ecef.push_back(frame.point(p));
  line.values = std::move(values);
  return line;
}

inline scene::TrackGeometry geometry_of(std::initializer_list<scene::TrackPolyline> segments) {
  scene::TrackGeometry g;
  g.segments.assign(segments.begin(), segments.end());
  return g;
}

// A level path (east, north, up) from `start` heading `heading_deg` (clockwise from north): a leg
// of `leg_m`, then after each turn (degrees, positive to the right) another leg.
inline std::vector<glm::dvec3> turning_path(const glm::dvec3& start, double heading_deg, double leg_m,
                                            std::initializer_list<double> turns_deg) {
  std::vector<glm::dvec3> points{start};
  double heading = heading_deg;
  const auto advance = [&] {
    const double h = heading * M_PI / 180.0;
    points.push_back(points.back() + leg_m * glm::dvec3(std::sin(h), std::cos(h), 0.0));
  };
  advance();
  for (const double turn : turns_deg) {
    heading += turn;
    advance();
  }
  return points;
}

// The focal length in pixels: (height / 2) / tan(vfov / 2).
inline double focal_length_px(const scene::Lens& lens) {
  return 0.5 * lens.height_px / std::tan(0.5 * lens.vertical_fov_deg * M_PI / 180.0);
}

// A camera at `at` looking straight down (north is up in the image for heading 0).
inline scene::Camera looking_down(const scene::GeoPosition& at, const scene::Lens& lens, double near_m = 1.0, double far_m = 1.0e5) {
  return scene::Camera(scene::ecef_from(at), 0.0, -90.0, lens, scene::DepthRange{near_m, far_m});
}

// A scene for a geometric check over the flat neutral ground at `ground_m`: the sun high in the
// south, no SSAO, no atmosphere (flat sky, no haze), no shadows.
inline scene::Scene plain_scene(const scene::GeoPosition& place, double ground_m) {
  scene::Scene s = lit_scene(sun_from(place.lat_deg, place.lon_deg, 180.0, 60.0), ground_m);
  s.style.shading.ssao = false;
  s.style.shading.atmosphere = false;
  s.style.shading.shadows = false;
  return s;
}

// A track of a scene: its geometry, drawn in a solid colour or by its values.
inline scene::Track track_of(scene::TrackGeometry geometry, const glm::vec3& color_srgb = kTrackRed,
                             bool by_value = false) {
  scene::Track t;
  t.geometry = std::move(geometry);
  t.color_srgb = color_srgb;
  t.by_value = by_value;
  return t;
}

// A set of tracks, drawn in this order.
inline scene::TrackSet track_set(std::initializer_list<scene::Track> tracks) {
  scene::TrackSet set;
  for (const scene::Track& t : tracks) set.add(t);
  return set;
}

// The red track's alpha at a pixel (see the file comment): 1 - green / green without tracks,
// from green and blue together. 0 where the background is too dark to tell.
inline double track_alpha(const scene::RgbaImage& with, const scene::RgbaImage& without, std::uint32_t x, std::uint32_t y) {
  const auto p = with.pixel(x, y), q = without.pixel(x, y);
  const double base = static_cast<double>(q[1]) + q[2];
  if (base < 20.0) return 0.0;
  return std::clamp(1.0 - (static_cast<double>(p[1]) + p[2]) / base, 0.0, 1.0);
}

// The alpha summed down one column (a tube crossing it: its width in pixels, fringe included).
inline double column_alpha(const scene::RgbaImage& with, const scene::RgbaImage& without, std::uint32_t x) {
  double sum = 0.0;
  for (std::uint32_t y = 0; y < with.height; ++y) sum += track_alpha(with, without, x, y);
  return sum;
}

// The alpha summed along one row.
inline double row_alpha(const scene::RgbaImage& with, const scene::RgbaImage& without, std::uint32_t y) {
  double sum = 0.0;
  for (std::uint32_t x = 0; x < with.width; ++x) sum += track_alpha(with, without, x, y);
  return sum;
}

// The pixel a point projects to, clamped into the image; false when behind the camera or off it.
inline bool pixel_of(const scene::Camera& camera, const glm::dvec3& ecef, std::uint32_t& x, std::uint32_t& y) {
  const auto p = camera.project(ecef);
  if (!p || p->x_px < 0.0 || p->y_px < 0.0 || p->x_px >= camera.lens().width_px || p->y_px >= camera.lens().height_px)
    return false;
  x = static_cast<std::uint32_t>(p->x_px);
  y = static_cast<std::uint32_t>(p->y_px);
  return true;
}

// Draws the scene without tracks and with them (the same scene otherwise).
struct WithAndWithout {
  scene::RgbaImage with, without;
};
inline WithAndWithout render_both(SceneDrawer& drawer, const scene::Camera& camera, scene::Scene scene,
                                  const scene::TrackSet& tracks) {
  WithAndWithout out;
  scene.tracks = nullptr;
  out.without = drawer.draw(camera, scene).image;
  scene.tracks = &tracks;
  out.with = drawer.draw(camera, scene).image;
  return out;
}

// A point of a track where the CPU decided whether the terrain hides it: its pixel, the answer,
// and a label for failure messages.
struct VisibilitySample {
  std::uint32_t x = 0, y = 0;
  bool hidden = false;
  std::string where;
};
struct VisibilityCount {
  int opaque = 0, ghost = 0, wrong = 0;
};

// Checks each sample's pixel: the opaque tube (alpha > 0.9) where the CPU sees it, a ghost of
// `ghost_alpha` (+- `tolerance`) where the terrain hides it. Samples within `boundary_px` of a
// pixel where the CPU's answer changes are left out (the GPU's terrain and the CPU's differ a
// little there). Reports the first few mismatches as test failures.
inline VisibilityCount check_visibility(const std::vector<VisibilitySample>& samples, const WithAndWithout& images,
                                        double ghost_alpha, double tolerance, double boundary_px) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> boundaries;
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i].hidden != samples[i - 1].hidden) boundaries.emplace_back(samples[i].x, samples[i].y);
  const auto near_boundary = [&](const VisibilitySample& s) {
    return std::any_of(boundaries.begin(), boundaries.end(), [&](const auto& b) {
      return std::hypot(static_cast<double>(s.x) - b.first, static_cast<double>(s.y) - b.second) < boundary_px;
    });
  };
  VisibilityCount count;
  for (const VisibilitySample& s : samples) {
    if (near_boundary(s)) continue;
    const double a = track_alpha(images.with, images.without, s.x, s.y);
    const bool ok = s.hidden ? std::abs(a - ghost_alpha) < tolerance : a > 0.9;
    (s.hidden ? count.ghost : count.opaque) += 1;
    if (!ok && ++count.wrong <= 8)
      ADD_FAILURE() << s.where << ", pixel (" << s.x << ", " << s.y << "): alpha " << a << ", expected "
                    << (s.hidden ? "a ghost" : "the opaque tube");
  }
  return count;
}

}  // namespace trailray::render::test
