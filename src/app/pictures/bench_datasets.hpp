#pragma once
// What `trailray bench tracks` draws: seeded random walks of a requested size (reproducible run
// to run, so figures from two machines compare), and the real tracks of a data folder (the .gpx
// and .igc files of ../shared/data), read and cleaned as `trailray render` would.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "render/passes/track_buffer.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::app {

struct BenchDataset {
  std::string name;  // "walk-100000", or the file's name
  std::string kind;  // "random_walk" or "track"
  scene::TrackGeometry geometry;
  std::vector<scene::GeoPosition> positions;  // the same points, for framing
  double ground_height_m = 0.0;               // the flat ground: the lowest point's height

  std::size_t point_count() const { return positions.size(); }
};

// A walk of `points` points (at least 2) in one segment: steps of 2-6 m in a heading that
// drifts, kept within about 2 km of a place in the Tyrol (so it folds over itself like a long
// hike or a thermal flight), climbing and sinking by up to a metre a step within 0..1500 m above
// the ground. The same `points` always gives the same walk.
BenchDataset make_random_walk(std::size_t points);

// `tracks` walks of `points` points each, one segment each in one geometry (a season of flights, a
// city's runs): each a walk as make_random_walk makes them (its own seed), each around its own
// centre, the centres spread uniformly over a square kManyWalksSpanM across, so they cross and
// overlap as many tracks of one region do. The same sizes always give the same walks.
inline constexpr double kManyWalksSpanM = 30000.0;
BenchDataset make_many_walks(std::size_t tracks, std::size_t points);

struct RealTracks {
  std::vector<BenchDataset> datasets;
  std::vector<std::string> skipped;  // "<file>: why" for files left out
};

// Every gpx/*.gpx and igc/*.igc under `data_dir` (sorted by name), tracks and routes, cleaned
// with the default options (track/clean.hpp); points without an elevation are placed at the
// track's lowest one (0 m without any). A file that does not read, or keeps fewer than two
// points, is skipped with the reason. A missing folder gives no datasets and one note.
RealTracks load_real_tracks(const std::filesystem::path& data_dir);

}  // namespace trailray::app
