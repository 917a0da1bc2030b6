#pragma once
// The OpenAir airspace format (Winpilot's, as used by XCSoar, SeeYou, XCTrack, flyland.ch and the
// DAeC): AC class, AN name, AL/AH floor and ceiling, DP points, V X= centre, V D= direction,
// DA/DB arcs, DC circles. Known records that carry nothing we use (AR/AF radio, AY type, AG, AT
// label positions, SP/SB pens, V W=/Z=) are accepted silently; unknown records are warned and
// counted; malformed coordinates, heights or arcs are errors naming FILE:LINE.
//
// Encodings: UTF-8 (with or without BOM); a file that is not valid UTF-8 is read as Latin-1
// (ISO-8859-1, as the DAeC files are), its names converted to UTF-8. CRLF or LF.

#include <string>
#include <string_view>

#include "track/airspace/airspace.hpp"

namespace trailray::track::airspace {

// Reads `bytes` (a whole file); `display_name` names it in diagnostics.
AirspaceReadResult read_openair(std::string_view bytes, const std::string& display_name,
                                const ReadOptions& options = {});

// Opens `path` ("-" = standard input, gzip too) and reads it.
AirspaceReadResult load_openair_file(const std::string& path, const ReadOptions& options = {});

}  // namespace trailray::track::airspace
