// The viewer's tracks: build_track_scene for what is drawn, plus the cleaned track, its metrics
// and flat per-point arrays for the chart, the tooltip and the replay.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "app/view/viewer_model.hpp"

namespace trailray::app::view {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double as_double(float v) { return std::isnan(v) ? kNaN : static_cast<double>(v); }

}  // namespace

std::optional<double> ViewerTrack::start_time() const {
  for (double t : time_unix_s)
    if (!std::isnan(t)) return t;
  return std::nullopt;
}

std::optional<double> ViewerTrack::end_time() const {
  for (auto it = time_unix_s.rbegin(); it != time_unix_s.rend(); ++it)
    if (!std::isnan(*it)) return *it;
  return std::nullopt;
}

std::size_t ViewerTrack::segment_of(std::size_t point) const {
  const auto it = std::upper_bound(segment_first.begin(), segment_first.end(), point);
  return it == segment_first.begin() ? 0 : static_cast<std::size_t>(it - segment_first.begin()) - 1;
}

void fill_point_arrays(ViewerTrack& t, const std::vector<std::vector<double>>& ground_m) {
  if (t.metrics.segments.size() != t.cleaned.segments.size())
    throw std::invalid_argument(fmt::format("track '{}': metrics for {} segments, the track has {}", t.name,
                                            t.metrics.segments.size(), t.cleaned.segments.size()));
  if (!ground_m.empty() && ground_m.size() != t.cleaned.segments.size())
    throw std::invalid_argument(fmt::format("track '{}': ground heights for {} segments, the track has {}", t.name,
                                            ground_m.size(), t.cleaned.segments.size()));
  const std::size_t n = t.cleaned.point_count();
  t.segment_first.clear();
  for (auto* v : {&t.distance_m, &t.time_unix_s, &t.elapsed_s, &t.altitude_m, &t.ground_m, &t.speed_kmh, &t.vspeed_ms,
                  &t.heart_rate_bpm}) {
    v->clear();
    v->reserve(n);
  }
  for (std::size_t s = 0; s < t.cleaned.segments.size(); ++s) {
    const auto& points = t.cleaned.segments[s].points;
    const track::SegmentMetrics& m = t.metrics.segments[s];
    if (m.size() != points.size())
      throw std::invalid_argument(fmt::format("track '{}' segment {}: metrics for {} points, it has {}", t.name, s + 1,
                                              m.size(), points.size()));
    if (!ground_m.empty() && ground_m[s].size() != points.size())
      throw std::invalid_argument(fmt::format("track '{}' segment {}: ground heights for {} points, it has {}", t.name,
                                              s + 1, ground_m[s].size(), points.size()));
    if (points.empty()) continue;
    t.segment_first.push_back(t.distance_m.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const track::TrackPoint& p = points[i];
      t.distance_m.push_back(m.distance_m[i]);
      t.time_unix_s.push_back(p.time);
      t.elapsed_s.push_back(m.elapsed_s[i]);
      t.altitude_m.push_back(p.ele);
      t.ground_m.push_back(ground_m.empty() ? kNaN : ground_m[s][i]);
      t.speed_kmh.push_back(m.speed_ms[i] * 3.6);
      t.vspeed_ms.push_back(m.vspeed_ms[i]);
      t.heart_rate_bpm.push_back(as_double(p.heart_rate));
    }
  }
}

std::vector<ViewerTrack> build_viewer_tracks(const std::vector<LoadedTrackFile>& files, const TrackStyle& style,
                                             TrackSceneInputs inputs,
                                             const std::function<void(const std::string&)>& warn) {
  inputs.keep_analysis = true;
  TrackScene scene = build_track_scene(files, style, inputs, warn);
  std::vector<ViewerTrack> out;
  out.reserve(scene.tracks.size());
  // build_track_scene's order: each file's tracks, then its routes.
  std::vector<std::string> sources;
  for (const LoadedTrackFile& loaded : files)
    sources.insert(sources.end(), loaded.file.tracks.size() + loaded.file.routes.size(), loaded.path);
  if (sources.size() != scene.tracks.size())
    throw std::logic_error(fmt::format("build_viewer_tracks: {} tracks in the files, build_track_scene made {}",
                                       sources.size(), scene.tracks.size()));
  for (std::size_t i = 0; i < scene.tracks.size(); ++i) {
    SceneTrack& drawn = scene.tracks[i];
    ViewerTrack t;
    t.name = drawn.name;
    t.source = sources[i];
    t.summary = std::move(drawn.summary);
    t.cleaned = std::move(drawn.cleaned);
    t.metrics = std::move(drawn.metrics);
    fill_point_arrays(t, drawn.ground_m);
    t.geometry = std::move(drawn.geometry);
    for (const auto& line : t.geometry.segments)
      t.ecef.insert(t.ecef.end(), line.points_ecef.begin(), line.points_ecef.end());
    if (t.ecef.size() != t.point_count())
      throw std::logic_error(fmt::format("build_viewer_tracks: track '{}' drawn with {} points, measured with {}",
                                         t.name, t.ecef.size(), t.point_count()));
    t.color_srgb = drawn.color_srgb;
    out.push_back(std::move(t));
  }
  return out;
}

void set_ground_heights(ViewerTrack& t, terrain::HeightSource& heights) {
  std::size_t flat = 0;
  for (const auto& g : sample_ground_heights(t.cleaned, &heights))
    for (double h : g) t.ground_m.at(flat++) = h;
}

void apply_color_metric(std::vector<ViewerTrack>& tracks, track::ColorMetric metric) {
  for (ViewerTrack& t : tracks) {
    std::vector<std::vector<double>> ground;
    if (metric == track::ColorMetric::agl) {
      std::size_t flat = 0;
      for (const auto& s : t.cleaned.segments) {
        ground.emplace_back();
        for (std::size_t i = 0; i < s.points.size(); ++i) ground.back().push_back(t.ground_m.at(flat++));
      }
    }
    const auto values = track::color_values(t.cleaned, t.metrics, metric, ground.empty() ? nullptr : &ground);
    std::size_t line = 0;
    for (std::size_t s = 0; s < t.cleaned.segments.size(); ++s) {
      if (t.cleaned.segments[s].points.empty()) continue;
      auto& target = t.geometry.segments.at(line++).values;
      if (metric == track::ColorMetric::solid)
        target.clear();
      else
        target = values[s];
    }
    ++t.geometry_revision;
  }
}

void apply_curtain(std::vector<ViewerTrack>& tracks, bool on) {
  for (ViewerTrack& t : tracks) {
    for (std::size_t line = 0; line < t.geometry.segments.size() && line < t.segment_first.size(); ++line) {
      auto& heights = t.geometry.segments[line].heights_above_ground_m;
      heights.clear();
      if (!on) continue;
      const std::size_t first = t.segment_first[line];
      const std::size_t count = t.geometry.segments[line].points_ecef.size();
      for (std::size_t i = first; i < first + count && i < t.point_count(); ++i)
        heights.push_back(static_cast<float>(t.altitude_m[i] - t.ground_m[i]));
    }
    ++t.geometry_revision;
  }
}

track::Track cut_track(const ViewerTrack& t, std::size_t first, std::size_t last) {
  track::Track out;
  out.name = t.name;
  std::size_t flat = 0;
  for (const auto& s : t.cleaned.segments) {
    track::Segment piece;
    for (const auto& p : s.points) {
      if (flat >= first && flat <= last) piece.points.push_back(p);
      ++flat;
    }
    if (!piece.points.empty()) out.segments.push_back(std::move(piece));
  }
  return out;
}

std::optional<track::Statistics> range_statistics(const ViewerTrack& t, std::size_t first, std::size_t last,
                                                  const track::AnalysisOptions& analysis) {
  if (t.point_count() == 0) return std::nullopt;
  last = std::min(last, t.point_count() - 1);
  if (first > last) return std::nullopt;
  const track::Track cut = cut_track(t, first, last);
  return track::track_statistics(cut, track::compute_metrics(cut, analysis.metrics), analysis.statistics);
}

}  // namespace trailray::app::view
