#include "app/pictures/bench_datasets.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>

#include "geo/local_frame.hpp"
#include "track/clean.hpp"
#include "track/io/load.hpp"

namespace trailray::app {
namespace {

// The walks' centre: the Inn valley at Innsbruck, 600 m.
constexpr double kWalkLat = 47.26, kWalkLon = 11.39, kWalkGround = 600.0;
constexpr double kWalkRadiusM = 2000.0;
constexpr double kWalkMaxHeightM = 1500.0;

void add_point(BenchDataset& d, scene::TrackPolyline& segment, const scene::GeoPosition& p) {
  d.positions.push_back(p);
  segment.points_ecef.push_back(scene::ecef_from(p));
}

}  // namespace

namespace {

// One walk of `points` points around (centre_east, centre_north) of the walks' frame, into `d`
// as a segment of its own.
void add_walk(BenchDataset& d, std::size_t points, std::uint64_t seed, double centre_east, double centre_north) {
  scene::TrackPolyline segment;
  segment.points_ecef.reserve(points);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> turn(0.0, 0.25), climb_change(0.0, 0.08);
  std::uniform_real_distribution<double> step_length(2.0, 6.0);
  const geo::LocalFrame frame(kWalkLat, kWalkLon, kWalkGround);
  double east = 0.0, north = 0.0, up = 0.0, heading = 0.0, climb = 0.0;
  for (std::size_t i = 0; i < points; ++i) {
    double lat = 0.0, lon = 0.0, height = 0.0;
    frame.to_geodetic({centre_east + east, centre_north + north, up}, lat, lon, height);
    add_point(d, segment, {lat, lon, height});
    heading += turn(random);
    // Beyond the radius, turn back towards the centre (a walk that stays a few km across).
    if (std::hypot(east, north) > kWalkRadiusM) {
      const double home = std::atan2(-north, -east);
      heading += 0.2 * std::remainder(home - heading, 2.0 * std::numbers::pi);
    }
    const double step = step_length(random);
    east += step * std::cos(heading);
    north += step * std::sin(heading);
    climb = std::clamp(climb + climb_change(random), -1.0, 1.0);
    up = std::clamp(up + climb, 0.0, kWalkMaxHeightM);
    if (up == 0.0 || up == kWalkMaxHeightM) climb = -0.5 * climb;
  }
  d.geometry.segments.push_back(std::move(segment));
}

}  // namespace

BenchDataset make_random_walk(std::size_t points) {
  BenchDataset d;
  d.name = "walk-" + std::to_string(points);
  d.kind = "random_walk";
  d.ground_height_m = kWalkGround;
  d.positions.reserve(points);
  // Seeded by the size: each size is its own walk, the same on every run.
  add_walk(d, points, 0x7261696c ^ points, 0.0, 0.0);
  return d;
}

BenchDataset make_many_walks(std::size_t tracks, std::size_t points) {
  BenchDataset d;
  d.name = "walks-" + std::to_string(tracks) + "x" + std::to_string(points);
  d.kind = "many_walks";
  d.ground_height_m = kWalkGround;
  d.positions.reserve(tracks * points);
  std::mt19937_64 random(0x6d616e79 ^ (tracks * 1000003u + points));
  std::uniform_real_distribution<double> place(-0.5 * kManyWalksSpanM, 0.5 * kManyWalksSpanM);
  for (std::size_t t = 0; t < tracks; ++t) {
    const double east = place(random), north = place(random);
    add_walk(d, points, random(), east, north);
  }
  return d;
}

namespace {

// The cleaned segments of a file's tracks and routes, or why there are none.
std::string add_file(const std::filesystem::path& path, std::vector<BenchDataset>& out) {
  const track::ReadResult read = track::load_track_file(path.string());
  if (read.error) return read.error->to_string();
  std::vector<track::Track> tracks = read.file.tracks;
  for (const track::Route& route : read.file.routes) {
    track::Track t;
    t.segments.push_back({route.points});
    tracks.push_back(std::move(t));
  }
  std::vector<track::Segment> segments;
  track::CleanReport report;
  for (const track::Track& t : tracks)
    for (track::Segment& s : track::clean_track(t, {}, report).segments)
      if (!s.points.empty()) segments.push_back(std::move(s));
  double lowest = std::numeric_limits<double>::infinity();
  std::size_t count = 0;
  for (const track::Segment& s : segments)
    for (const track::TrackPoint& p : s.points) {
      ++count;
      if (std::isfinite(p.ele)) lowest = std::min(lowest, p.ele);
    }
  if (count < 2) return "fewer than 2 points after cleaning";
  if (!std::isfinite(lowest)) lowest = 0.0;
  BenchDataset d;
  d.name = path.filename().string();
  d.kind = "track";
  d.ground_height_m = lowest;
  for (const track::Segment& s : segments) {
    scene::TrackPolyline polyline;
    for (const track::TrackPoint& p : s.points)
      add_point(d, polyline, {p.lat, p.lon, std::isfinite(p.ele) ? p.ele : lowest});
    d.geometry.segments.push_back(std::move(polyline));
  }
  out.push_back(std::move(d));
  return {};
}

}  // namespace

RealTracks load_real_tracks(const std::filesystem::path& data_dir) {
  RealTracks r;
  std::error_code error;
  if (!std::filesystem::is_directory(data_dir, error)) {
    r.skipped.push_back(data_dir.string() + ": no such folder, no real tracks");
    return r;
  }
  std::vector<std::filesystem::path> files;
  for (const char* kind : {"gpx", "igc"}) {
    const std::filesystem::path folder = data_dir / kind;
    if (!std::filesystem::is_directory(folder, error)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
      if (entry.is_regular_file(error) && entry.path().extension() == std::string(".") + kind)
        files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end(),
            [](const auto& a, const auto& b) { return a.filename().string() < b.filename().string(); });
  for (const std::filesystem::path& file : files)
    if (std::string why = add_file(file, r.datasets); !why.empty())
      r.skipped.push_back(file.filename().string() + ": " + why);
  return r;
}

}  // namespace trailray::app
