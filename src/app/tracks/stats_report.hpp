#pragma once
// What `trailray stats` prints, for one file: JSON and a human-readable table.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/tracks/stats_photos.hpp"
#include "track/diagnostics.hpp"
#include "track/places/summits.hpp"
#include "track/summary.hpp"

namespace trailray::app {

struct FileStats {
  std::string path;  // as given on the command line ("-" for stdin)
  std::optional<track::Format> format;
  std::vector<track::TrackSummary> tracks;
  std::size_t routes = 0;
  std::size_t waypoints = 0;
  std::vector<std::string> warnings;  // "file:line:col: message"
  std::optional<std::string> error;   // set when the file could not be read
  // --places: per track (parallel to `tracks`), the summits reached and the huts passed, of the
  // track as recorded; empty without --places.
  bool with_places = false;
  std::vector<track::places::PlacesVisited> places_visited;
  // --photos: the photos placed on this file's cleaned tracks (PlacedPhoto::track: the track's
  // index in the file) and the others' reasons; absent without --photos or when not read.
  std::optional<track::PhotoPlacement> photos;
  std::size_t photo_count = 0;  // photos read (placed here or not)
};

// Reads, cleans and measures one file; with `places` (--places: summits and huts), the ones each
// track reached; with `photos` (--photos), where they were taken on its cleaned tracks.
FileStats compute_file_stats(const std::string& path, const track::ReadOptions& read,
                             const track::AnalysisOptions& analysis,
                             const std::vector<track::places::Place>* places = nullptr,
                             const StatsPhotos* photos = nullptr);

nlohmann::json statistics_json(const track::Statistics& s);
nlohmann::json file_stats_json(const FileStats& f);

// The table for one file (clean figures), ending in a newline.
std::string file_stats_table(const FileStats& f);

}  // namespace trailray::app
