#pragma once
// What `trailray flight` prints for one file: a readable report (summary, thermals, glides, wind
// per altitude band, per flight of each track) or the same content as JSON (shape in
// flight_report.cpp and in `trailray flight --help`).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/flight/flight_analysis.hpp"

namespace trailray::app {

struct TrackFlights {
  std::string name;
  std::size_t index = 0;  // the track's position in the file
  track::flight::FlightAnalysis analysis;
  double fix_interval_s = 0.0;  // median time between consecutive timed points (0: fewer than two)
};

struct FileFlights {
  std::string path;  // as given on the command line ("-" for stdin)
  std::optional<track::Format> format;
  std::vector<TrackFlights> tracks;
  std::vector<std::string> warnings;  // "file:line:col: message"
  std::optional<std::string> error;   // set when the file could not be read
};

// Reads one file and analyses every track of it.
FileFlights analyse_flight_file(const std::string& path, const track::ReadOptions& read,
                                const track::flight::FlightOptions& options = {});

// The median time step between consecutive timed points of a track; 0 with fewer than two.
double median_fix_interval(const track::Track& t);

// Fixes this far apart or more cannot resolve a thermalling circle (20 to 30 s): the report
// says that circling is undercounted.
inline constexpr double kCoarseFixInterval = 7.0;

// Why a track has no flight ("no times: ..."), or an empty string when it has one.
std::string no_flight_reason(const track::flight::FlightAnalysis& a);

nlohmann::json flight_file_json(const FileFlights& f);
// The analysis constants, for the document's "settings".
nlohmann::json flight_settings_json(const track::flight::FlightOptions& o);
std::string flight_file_text(const FileFlights& f);

}  // namespace trailray::app
