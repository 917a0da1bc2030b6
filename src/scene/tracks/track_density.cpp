#include "scene/tracks/track_density.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace trailray::scene {
namespace {

// The cleaned points of `t` during the thermals of `flight` that gained height, as lines (a
// thermal's points in one segment; a gap in the recording splits it).
std::vector<track::PointLine> climbing_lines(const Track& t, const track::flight::Flight& flight) {
  std::vector<track::PointLine> lines;
  for (const track::Segment& segment : t.cleaned.segments) {
    const std::vector<track::TrackPoint>& points = segment.points;
    std::size_t thermal = 0, begin = 0;
    bool open = false;
    const auto close = [&](std::size_t end) {
      if (open && end > begin) lines.emplace_back(points.data() + begin, end - begin);
      open = false;
    };
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double time = points[i].time;
      // Thermals are in time order, and so are a cleaned segment's points.
      while (thermal < flight.thermals.size() && time > flight.thermals[thermal].end.time) {
        close(i);
        ++thermal;
      }
      const bool climbing = thermal < flight.thermals.size() && time >= flight.thermals[thermal].start.time &&
                            flight.thermals[thermal].gain_m > 0.0;
      if (climbing && !open) {
        begin = i;
        open = true;
      } else if (!climbing) {
        close(i);
      }
    }
    close(points.size());
  }
  return lines;
}

std::vector<track::PointLine> segment_lines(const Track& t) {
  std::vector<track::PointLine> lines;
  for (const track::Segment& s : t.cleaned.segments)
    if (!s.points.empty()) lines.emplace_back(s.points);
  return lines;
}

}  // namespace

std::size_t apply_neighbour_counts(std::vector<Track>& tracks, track::ColorMetric metric, double radius_m,
                                   const track::ParallelFor& parallel) {
  if (!track::counts_neighbours(metric))
    throw std::invalid_argument(
        fmt::format("apply_neighbour_counts: {} is not a count of tracks nearby", track::color_metric_name(metric)));
  std::vector<track::NeighbourSource> sources;
  std::vector<std::vector<track::PointLine>> targets;
  std::vector<Track*> coloured;
  for (Track& t : tracks) {
    if (t.is_route) continue;
    coloured.push_back(&t);
    // The lines in the order of the geometry's polylines (the non-empty segments).
    targets.push_back(segment_lines(t));
    if (metric == track::ColorMetric::density) {
      sources.push_back({targets.back()});
      continue;
    }
    if (!t.flights)
      throw std::invalid_argument("track '" + t.name + "' has no flight analysis to find where it climbed");
    for (const track::flight::Flight& flight : t.flights->flights) {
      std::vector<track::PointLine> lines = climbing_lines(t, flight);
      if (!lines.empty()) sources.push_back({std::move(lines)});
    }
  }
  const auto counts = track::neighbour_counts(sources, targets, radius_m, parallel);
  for (std::size_t i = 0; i < coloured.size(); ++i) {
    Track& t = *coloured[i];
    for (std::size_t line = 0; line < t.geometry.segments.size() && line < counts[i].size(); ++line)
      t.geometry.segments[line].values = counts[i][line];
    t.bump_revision();
  }
  return sources.size();
}

std::string radius_text(double radius_m) {
  return radius_m >= 1000.0 ? fmt::format("{:g} km", radius_m / 1000.0) : fmt::format("{:g} m", radius_m);
}

std::string neighbour_legend_title(track::ColorMetric metric, double radius_m) {
  const char* what = metric == track::ColorMetric::thermals ? "Flights climbing" : "Tracks";
  return fmt::format("{} within {} (own included)", what, radius_text(radius_m));
}

}  // namespace trailray::scene
