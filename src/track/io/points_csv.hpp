#pragma once
// Points files for place labels (`--labels FILE`): a CSV of named places (peaks, huts), or any
// track file that carries waypoints (GPX wpt, GeoJSON Point features, KML Point placemarks, FIT
// course points), each point a track::Waypoint of the result's file.
//
// The CSV: a header row naming the columns in any order (case-insensitive): name, lat or
// latitude, lon, lng or longitude (required), ele, elevation, alt or altitude, desc or description
// (optional; other columns are ignored); fields separated by commas, semicolons or tabs (the
// header's first separator decides); fields may be double-quoted ("" inside for a quote).
// Blank lines and lines starting with '#' are skipped. A row whose coordinates are not numbers
// or out of range is an error naming FILE:LINE (a labels file is written by hand: a wrong line
// is better fixed than dropped); an empty elevation is none.

#include <string>
#include <string_view>

#include "track/diagnostics.hpp"

namespace trailray::track {

// Reads CSV text; `name` is the file's name in messages.
ReadResult read_points_csv(std::string_view text, const std::string& name);

// Whether a path names a CSV points file (.csv, .tsv or .txt, any case, also gzipped).
bool is_points_csv_path(const std::string& path);

// A points file: CSV by its name (is_points_csv_path), else through load_track_file (every
// format that carries waypoints). The result's file.waypoints are the points.
ReadResult load_points_file(const std::string& path, const ReadOptions& options = {});

}  // namespace trailray::track
