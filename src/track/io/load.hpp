#pragma once
// The one entry point the app uses: open a path ("-" = stdin, gzip or plain), detect the
// format from content, read it.

#include <string>

#include "track/diagnostics.hpp"

namespace trailray::track {

ReadResult load_track_file(const std::string& path, const ReadOptions& options = {});

}  // namespace trailray::track
