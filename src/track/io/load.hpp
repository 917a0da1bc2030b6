#pragma once
// The one entry point the app uses: open a path ("-" = stdin, gzip or plain), detect the
// format from content, read it.

#include <optional>
#include <string>

#include "track/diagnostics.hpp"
#include "track/io/byte_source.hpp"

namespace trailray::track {

ReadResult load_track_file(const std::string& path, const ReadOptions& options = {});

// The same from a source already open (a file, or bytes in memory): `format` read as given, else
// detected from the content (and `path`'s extension where the content leaves it open).
ReadResult read_track_source(ByteSource& source, const std::string& path, const ReadOptions& options = {},
                             std::optional<Format> format = std::nullopt);

}  // namespace trailray::track
