#pragma once
// Reading tasks: XCTrack .xctsk files (JSON version 1, or the compact version 2 of its QR codes,
// with or without the "XCTSK:" prefix), XCSoar .tsk files (XML) and IGC task declarations (C
// records). The format is told from the content. Never throws: errors name the file and where (the JSON path, e.g.
// "turnpoints[3].waypoint.lat", or line:column for syntax; the line for IGC).

#include <string>
#include <string_view>
#include <vector>

#include "track/task/task.hpp"

namespace trailray::track::task {

// Files bigger than this are not tasks (the largest real ones are a few kilobytes).
inline constexpr std::size_t kMaxTaskBytes = 4u << 20;

TaskReadResult read_task_file(const std::string& path);
// `file` names the input in messages.
TaskReadResult read_task_text(std::string_view text, const std::string& file);

// The formats, for callers that know which they have.
TaskReadResult read_xctsk(std::string_view text, const std::string& file);  // JSON v1 or v2, "XCTSK:" allowed
TaskReadResult read_igc_declaration(std::string_view text, const std::string& file);
TaskReadResult read_xcsoar_task(std::string_view text, const std::string& file);  // <Task> XML

// Google's polyline encoding as XCTrack's QR form uses it: each value on its own (not a
// difference from the one before). Returns the integers decoded (coordinates are degrees
// times 1e5, altitude and radius metres), or nothing when `text` is not a complete encoding.
std::optional<std::vector<long long>> decode_polyline_values(std::string_view text);

}  // namespace trailray::track::task
