#pragma once
// The picture `trailray render` makes, up to the file: the scene of the options (terrain, tracks,
// airspace, camera), drawn headless through EGL with its legend. The command writes it as a PNG;
// the Python module (src/python/) hands it over as an array, from tracks it read itself.

#include <vector>

#include "app/pictures/render_options.hpp"
#include "scene/diagnostics.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/tracks/track_files.hpp"

namespace trailray::app {

// The tracks of `args.tracks` (paths) read, then `more` (files already read) after them.
// Throws what the command reports: CLI::ValidationError for options that contradict each other,
// std::runtime_error naming a file that cannot be read, the terrain's and the GL context's errors.
scene::RgbaImage render_picture(const RenderArgs& args, scene::Diagnostics& diagnostics,
                                std::vector<scene::LoadedTrackFile> more = {});

}  // namespace trailray::app
