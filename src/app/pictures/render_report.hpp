#pragma once
// What `trailray render` says about a picture it made: warnings (tiles that timed out or failed,
// no terrain in view, the sun below the horizon) and, with --verbose, the camera, sun, tiles and
// GPU memory; with --profile, the passes' times.

#include <string>

#include "app/pictures/render_options.hpp"
#include "render/renderer.hpp"
#include "scene/camera/camera.hpp"
#include "scene/diagnostics.hpp"
#include "scene/scene.hpp"
#include "terrain/loading/tile_loader.hpp"

namespace trailray::app {

// "tiles: 12/40 loaded, 1 failed".
std::string tiles_status(const terrain::LoadProgress& progress);

void report_render(const render::FrameReport& report, const scene::Camera& camera, const scene::Scene& scene,
                   terrain::HeightSource* heights, const RenderArgs& args, scene::Diagnostics& diagnostics);

// Draws `frames` more frames (the tiles are loaded by now) timing each pass, and prints the
// table to standard error; `picture` receives the last frame.
void profile_frames(render::Renderer& renderer, const scene::Scene& scene, const scene::Camera& camera, int frames,
                    render::ImageTarget& picture);

}  // namespace trailray::app
