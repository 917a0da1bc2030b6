#pragma once
// The fix list that XC scoring works on: the B records of an IGC log with fix validity 'A', in
// file order, minus every fix whose time equals the time of the previous kept fix. This is the
// list igc-xc-score (the reference scorer of the rule sets) optimises over, so turnpoint indexes
// are comparable with its output. Turnpoints are always fixes of this list.

#include <optional>
#include <string>
#include <vector>

#include "track/model.hpp"

namespace trailray::track::scoring {

struct Fix {
  double lat = 0.0;      // degrees
  double lon = 0.0;      // degrees
  double time = 0.0;     // seconds since 1970-01-01 UTC (midnight rollovers resolved)
  int gnss_alt = 0;      // metres, 0 when the recorder gives none
  int pressure_alt = 0;  // metres, 0 when the recorder gives none
};

struct FixList {
  std::vector<Fix> fixes;
  std::size_t b_records = 0;         // B records read (before filtering)
  std::optional<std::string> error;  // "FILE:LINE: what" or "FILE: what"
};

// Reads the fixes of IGC text. `name` is used in messages. Never throws.
FixList parse_scoring_fixes(const std::string& text, const std::string& name);

// Reads a file (plain or gzip is not supported: IGC logs are plain text). Never throws.
FixList read_scoring_fixes(const std::string& path);

// A track's timed points as fixes, one per second at most, as the scorer keeps them: its GNSS and
// pressure altitudes where it has them (an IGC track), else its elevation as the GNSS altitude.
// b_records counts the timed points.
FixList fixes_of_track(const Track& track);

// Any track file: an IGC log's B records as read_scoring_fixes reads them (by its name, *.igc),
// another format's (GPX, FIT, TCX, KML, GeoJSON) track with the most timed points. Never throws.
FixList read_any_scoring_fixes(const std::string& path);

}  // namespace trailray::track::scoring
