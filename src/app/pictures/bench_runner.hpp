#pragma once
// The measuring half of `trailray bench tracks`: one headless GL context, a G-buffer the size of
// the picture, and for each dataset a camera framing it over a flat ground; then each technique
// (the capsules of render/track_pass.hpp, the reference ribbon and tube of render/reference/)
// draws the same track at the same width in pixels for a few warm-up frames and then the timed
// ones. The ground is drawn every frame but not timed: only the track passes are.
//
// Time per pass is the GPU's (EXT_disjoint_timer_query) where the context offers it, else the
// CPU's around the draw and a glFinish (llvmpipe renders on the CPU: its wall time is its GPU
// time). Each figure is the median over the timed frames.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "app/pictures/bench_datasets.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::app {

struct BenchSettings {
  scene::Lens lens;  // the picture's size (and field of view)
  int frames = 20;   // timed frames per technique
  int warmup_frames = 2;
  double width_px = 5.0;  // the tube's diameter on screen (the capsules' default width)
  // The overlay as the renderer draws it (only capsules the terrain may hide are traced), or
  // false: every capsule traced (TrackSceneSettings::terrain_top_m unset), to compare.
  bool split_overlay = true;
  // The tube mesh takes 384 bytes a point (CPU copy and GPU): above this many points it is left
  // out (its figures NaN), so that 10,000 tracks x 1,000 points do not ask for 8 GB.
  std::size_t max_tube_points = 2'000'000;
  // The capsules' level of detail (TrackSceneSettings::level_of_detail); false: every capsule.
  bool level_of_detail = true;
};

struct BenchRow {
  std::string name, kind;
  std::size_t points = 0, segments = 0;
  double capsule_ms = 0.0;          // the visible pass (into the G-buffer)
  double capsule_overlay_ms = 0.0;  // the overlay pass (occluded ghosts, silhouette fringe)
  double capsule_total_ms = 0.0;    // the two medians added
  std::size_t capsules_drawn = 0;   // by the visible pass in the last frame (the segments without LOD)
  double capsule_upload_ms = 0.0;   // making the TrackBuffer (the LOD hierarchy included), CPU time
  // Many tracks: the capsules' total with a buffer (and draws) per track instead of one for all
  // (0: not measured).
  double capsule_per_track_total_ms = 0.0;
  double ribbon_ms = 0.0, tube_ms = 0.0;
  std::size_t capsule_bytes = 0, ribbon_bytes = 0, tube_bytes = 0;
  double tube_radius_m = 0.0;    // the tube's radius: width_px wide at the framing distance
  double view_distance_m = 0.0;  // the camera's distance from the framed centre
  bool gpu_timed = false;        // every figure of the row from GPU timer queries
};

class TrackBench {
 public:
  // Creates the GL context and compiles the passes. Throws RenderError / ShaderError.
  explicit TrackBench(const BenchSettings& settings);
  ~TrackBench();
  TrackBench(const TrackBench&) = delete;
  TrackBench& operator=(const TrackBench&) = delete;

  // "llvmpipe (LLVM 15.0.6, 256 bits)", as GL_RENDERER names it.
  std::string renderer() const;
  // Whether the context has GPU timer queries (else every time is CPU time with glFinish).
  bool gpu_timing() const;

  // Measures one dataset. `progress` hears each technique's name as it starts. Throws
  // std::runtime_error when the dataset cannot be framed, RenderError from GL.
  BenchRow run(const BenchDataset& dataset, const std::function<void(const std::string&)>& progress);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace trailray::app
