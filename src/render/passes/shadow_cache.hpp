#pragma once
// When the shadow maps must be rendered again. Their contents depend on the sun, the cascades'
// bounds (from the camera and the terrain's height span), the casters (tiles, tracks and their
// style) and the camera (a tube keeps the radius the camera sees it with, so its shadow follows
// the camera's distance). A frame whose key equals the last rendered one's reuses the maps: a
// still camera with the replay cursor moving, or a redraw for the interface, renders no cascade.
//
// The key is a list of numbers (doubles by their bits, pointers by value): equal keys mean the
// same inputs. A tile or track buffer is named by its address; one freed and another made at the
// same address between two frames would need every other input equal, and the frame that frees
// a tile or a buffer has already changed the key (the list of casters differs).

#include <cstdint>
#include <optional>
#include <vector>

#include "render/passes/shadow_cascades.hpp"
#include "render/passes/shadow_pass.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::render {

using ShadowMapKey = std::vector<std::uint64_t>;

// The key of the maps `cascades` would render for `camera` from `casters`.
ShadowMapKey shadow_map_key(const ShadowCascades& cascades, const scene::Camera& camera, const ShadowCasters& casters);

// The shadow maps' last contents: what they were rendered for.
class ShadowMapCache {
 public:
  // Whether maps rendered for `key` are what the frame needs.
  bool holds(const ShadowMapKey& key) const { return valid_ && key == key_; }
  // Whether there are maps at all, and for this sun (a moving frame may reuse maps rendered for
  // another camera, never for another sun).
  bool holds_sun(const glm::dvec3& sun_direction_ecef) const;
  // The cascades the maps were rendered with.
  const ShadowCascades& cascades() const { return *cascades_; }

  void store(ShadowMapKey key, const ShadowCascades& cascades);
  void clear() { valid_ = false; }

 private:
  bool valid_ = false;
  ShadowMapKey key_;
  std::optional<ShadowCascades> cascades_;
};

}  // namespace trailray::render
