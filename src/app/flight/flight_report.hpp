#pragma once
// What `trailray flight` prints for one file: a readable report (summary, thermals, glides, wind
// per altitude band, per flight of each track) or the same content as JSON (shape in
// flight_report.cpp and in `trailray flight --help`).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/flight/task_report.hpp"
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
  std::vector<std::string> warnings;     // "file:line:col: message"
  std::optional<std::string> error;      // set when the file could not be read
  std::optional<TaskFlightReport> task;  // with --task: the turnpoints its fixes reached
};

// A task to check every file against (`flight --task`), measured once.
struct FlightTask {
  std::string path;
  track::task::Task task;
  track::task::TaskDistances distances;
  double tolerance = 0.0;  // fraction of a radius
};

// Reads one file and analyses every track of it; with a task, also which turnpoints it reached.
FileFlights analyse_flight_file(const std::string& path, const track::ReadOptions& read,
                                const track::flight::FlightOptions& options = {}, const FlightTask* task = nullptr);

// The median time step between consecutive timed points of a track; 0 with fewer than two.
double median_fix_interval(const track::Track& t);

// Fixes this far apart or more cannot resolve a thermalling circle (20 to 30 s): the report
// says that circling is undercounted.
inline constexpr double kCoarseFixInterval = 7.0;

// Why a track has no flight ("no times: ..."), or an empty string when it has one.
std::string no_flight_reason(const track::flight::FlightAnalysis& a);

// With the task the file was checked against (its "task": the turnpoints reached).
nlohmann::json flight_file_json(const FileFlights& f, const FlightTask* task = nullptr);
// The analysis constants, for the document's "settings".
nlohmann::json flight_settings_json(const track::flight::FlightOptions& o);
std::string flight_file_text(const FileFlights& f, const FlightTask* task = nullptr);

}  // namespace trailray::app
