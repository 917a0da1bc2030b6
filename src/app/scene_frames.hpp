#pragma once
// Bridge while render::SceneRenderer still takes SceneRenderOptions and track buffers: turns a
// scene::Scene into them, keeping one TrackBuffer per (track id, revision). Goes away when the
// renderer draws scenes itself.

#include <map>
#include <memory>
#include <utility>

#include "render/legacy_scene_renderer.hpp"
#include "scene/scene.hpp"

namespace trailray::app {

class SceneFrames {
 public:
  // The options drawing `scene` (GL context current: uploads new or changed tracks).
  render::SceneRenderOptions options_for(const scene::Scene& scene);

 private:
  std::map<scene::TrackId, std::pair<std::uint64_t, std::unique_ptr<render::TrackBuffer>>> buffers_;
};

}  // namespace trailray::app
