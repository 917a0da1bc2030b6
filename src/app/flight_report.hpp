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

// Why a track has no flight ("no times: ..."), or an empty string when it has one.
std::string no_flight_reason(const track::flight::FlightAnalysis& a);

nlohmann::json flight_file_json(const FileFlights& f);
// The analysis constants, for the document's "settings".
nlohmann::json flight_settings_json(const track::flight::FlightOptions& o);
std::string flight_file_text(const FileFlights& f);

}  // namespace trailray::app
