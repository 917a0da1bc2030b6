#include "render/passes/shadow_cache.hpp"

#include <cstring>
#include <utility>

namespace trailray::render {
namespace {

class KeyWriter {
 public:
  explicit KeyWriter(ShadowMapKey& key) : key_(key) {}
  void add(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    key_.push_back(bits);
  }
  void add(const glm::dvec3& v) {
    add(v.x);
    add(v.y);
    add(v.z);
  }
  void add(const void* pointer) { key_.push_back(reinterpret_cast<std::uintptr_t>(pointer)); }
  void add_int(std::uint64_t v) { key_.push_back(v); }

 private:
  ShadowMapKey& key_;
};

}  // namespace

ShadowMapKey shadow_map_key(const ShadowCascades& cascades, const scene::Camera& camera, const ShadowCasters& casters) {
  ShadowMapKey key;
  KeyWriter w(key);
  w.add(cascades.sun_direction_ecef());
  const ShadowCascadeSettings& s = cascades.settings();
  for (const double v : {s.split_lambda, s.max_distance_m, static_cast<double>(s.map_size_px), s.caster_height_span_m,
                         s.min_sun_elevation_deg, s.constant_bias_texels, s.slope_bias_texels, s.normal_offset_texels})
    w.add(v);
  // The camera: the cascades' bounds follow from it, and so do the tubes' radii.
  w.add(camera.position());
  w.add(camera.axes().forward);
  w.add(camera.axes().right);
  w.add(camera.axes().up);
  w.add(camera.lens().vertical_fov_deg);
  w.add_int(camera.lens().width_px);
  w.add_int(camera.lens().height_px);
  w.add(camera.depth_range().near_m);
  w.add(camera.depth_range().far_m);
  for (const ShadowCascade& c : cascades.cascades()) {
    w.add(c.centre_ecef);
    w.add(c.eye_ecef);
    w.add(c.radius_m);
    w.add(c.depth_extent_m);
  }
  w.add_int(casters.tiles.size());
  for (const TerrainDrawItem& item : casters.tiles) w.add(item.mesh);
  const bool tracks_cast = casters.track_settings != nullptr && casters.track_settings->cast_shadows;
  w.add_int(tracks_cast ? 1 : 0);
  if (!tracks_cast) return key;
  const TrackSceneSettings& t = *casters.track_settings;
  w.add(t.width.value);
  w.add_int(static_cast<std::uint64_t>(t.width.unit));
  w.add(t.min_width_px);
  w.add_int(t.curtain ? 1 : 0);
  w.add_int(casters.tracks.size());
  for (const TrackDraw& d : casters.tracks) {
    w.add(d.buffer);
    // A buffer of many tracks casts the shown ones only.
    w.add_int(d.track_styles.size());
    for (const TrackDrawStyle& style : d.track_styles) w.add_int(style.visible ? 1 : 0);
    const CapsuleShape& shape = d.shape;
    w.add(shape.width ? shape.width->value : -1.0);
    w.add_int(shape.width ? static_cast<std::uint64_t>(shape.width->unit) : 9);
    w.add(shape.min_width_px.value_or(-1.0));
    w.add(static_cast<double>(shape.dash_px));
    w.add(static_cast<double>(shape.lift_px));
    w.add(static_cast<double>(shape.lift_m));
    w.add_int(static_cast<std::uint64_t>(shape.capsules));
    w.add_int(d.is_pin ? 1 : 0);
  }
  return key;
}

bool ShadowMapCache::holds_sun(const glm::dvec3& sun_direction_ecef) const {
  // Within rounding: the cascades keep the direction normalised their own way.
  return valid_ && glm::length(cascades_->sun_direction_ecef() - glm::normalize(sun_direction_ecef)) < 1e-12;
}

void ShadowMapCache::store(ShadowMapKey key, const ShadowCascades& cascades) {
  key_ = std::move(key);
  cascades_ = cascades;
  valid_ = true;
}

}  // namespace trailray::render
