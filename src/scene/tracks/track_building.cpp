#include "scene/tracks/track_building.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>

#include "geo/wgs84.hpp"
#include "scene/camera/camera.hpp"
#include "scene/pictures/colormap.hpp"
#include "scene/tracks/track_density.hpp"
#include "terrain/height_sampler.hpp"
#include "track/clean.hpp"
#include "track/cover.hpp"
#include "track/flight/phase_values.hpp"

namespace trailray::scene {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double as_double(float v) { return std::isnan(v) ? kNaN : static_cast<double>(v); }

// A file's tracks and routes (a route as a track of one segment), with the names they are shown by.
struct NamedTrack {
  std::string name;
  const track::Track* track = nullptr;
  track::Track route_as_track;
  bool is_route() const { return track == nullptr; }
  const track::Track& raw() const { return track != nullptr ? *track : route_as_track; }
};

std::vector<NamedTrack> tracks_of(const LoadedTrackFile& loaded) {
  std::vector<NamedTrack> out;
  const std::string stem = std::filesystem::path(loaded.path).filename().string();
  std::size_t number = 0;
  const auto name_for = [&](const std::string& own) {
    ++number;
    if (!own.empty()) return own;
    return number == 1 && loaded.file.tracks.size() + loaded.file.routes.size() == 1
               ? stem
               : fmt::format("{} #{}", stem, number);
  };
  for (const track::Track& t : loaded.file.tracks) out.push_back({name_for(t.name), &t, {}});
  for (const track::Route& r : loaded.file.routes) {
    NamedTrack named{name_for(r.name), nullptr, {}};
    named.route_as_track.name = r.name;
    named.route_as_track.segments.push_back({r.points});
    out.push_back(std::move(named));
  }
  return out;
}

bool needs_ground(const track::Track& t, const TrackStyle& style) {
  if (style.color_by == track::ColorMetric::agl || style.curtain) return true;
  for (const auto& s : t.segments)
    for (const auto& p : s.points)
      if (!p.has_ele()) return true;
  return false;
}

// The metres along each segment of a route: its "values", which the track pass dashes it by.
std::vector<std::vector<float>> distances_along(const track::TrackMetrics& metrics) {
  std::vector<std::vector<float>> out;
  for (const track::SegmentMetrics& m : metrics.segments) {
    out.emplace_back();
    for (double d : m.distance_m) out.back().push_back(static_cast<float>(d));
  }
  return out;
}

// The drawn polylines: each point in ECEF (on the ground, or the neutral ground, without an
// elevation), the metric's values, curtain heights.
void fill_geometry(Track& t, const std::vector<std::vector<double>>& ground,
                   const std::vector<std::vector<float>>& values, const TrackStyle& style, double neutral_ground_m) {
  for (std::size_t s = 0; s < t.cleaned.segments.size(); ++s) {
    const auto& points = t.cleaned.segments[s].points;
    if (points.empty()) continue;
    TrackPolyline line;
    line.points_ecef.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const track::TrackPoint& p = points[i];
      double under = ground.empty() ? kNaN : ground[s][i];
      if (std::isnan(under)) under = neutral_ground_m;
      const double height = p.has_ele() ? p.ele : under;
      line.points_ecef.push_back(ecef_from({p.lat, p.lon, height}));
      if (style.curtain) line.heights_above_ground_m.push_back(static_cast<float>(height - under));
    }
    if (!values.empty()) line.values = values[s];
    t.geometry.segments.push_back(std::move(line));
  }
}

// The colour values of a recorded track for a metric: phase from its flight analysis, the others
// from its points and metrics (density and thermals: none yet, apply_neighbour_counts on all the
// tracks gives them).
std::vector<std::vector<float>> values_for(const Track& t, const track::TrackMetrics& metrics,
                                           track::ColorMetric metric, const std::vector<std::vector<double>>* ground) {
  if (metric == track::ColorMetric::cover) {
    if (t.cover.empty())
      throw std::invalid_argument("--color-by cover needs --surface (a surface model beside --terrain)");
    std::vector<std::vector<float>> values;
    std::size_t flat = 0;
    for (const track::Segment& s : t.cleaned.segments) {
      values.emplace_back();
      for (std::size_t i = 0; i < s.points.size(); ++i, ++flat)
        values.back().push_back(t.cover[flat] == Track::kNoCover ? std::numeric_limits<float>::quiet_NaN()
                                                                  : static_cast<float>(t.cover[flat]));
    }
    return values;
  }
  if (metric != track::ColorMetric::phase) return track::color_values(t.cleaned, metrics, metric, ground);
  if (!t.flights) throw std::invalid_argument("track '" + t.name + "' has no flight analysis to colour by phase");
  return track::flight::phase_color_values(t.cleaned, *t.flights);
}

// Recorded tracks from --color or the palette; routes in the route colour (not counted).
void assign_colors(std::vector<Track>& tracks, const TrackStyle& style, std::size_t first_palette_index) {
  const auto& colors = style.colors;
  std::size_t recorded = 0;
  for (const Track& t : tracks) recorded += t.is_route ? 0 : 1;
  if (!colors.empty() && colors.size() != 1 && colors.size() != recorded)
    throw std::runtime_error(fmt::format("--color was given {} times for {} tracks: give it once, or once per track",
                                         colors.size(), recorded));
  std::size_t i = 0;
  for (Track& t : tracks) {
    if (t.is_route) {
      t.color_srgb = style.route_color;
      continue;
    }
    t.color_srgb = colors.empty()       ? palette_color(first_palette_index + i)
                   : colors.size() == 1 ? colors.front()
                                        : colors[i];
    ++i;
  }
}

// Each point's class against the terrain (`ground`) and the surface, per segment and point.
void fill_cover(Track& t, const std::vector<std::vector<double>>& ground,
                const std::vector<std::vector<double>>& surface) {
  t.cover.clear();
  for (std::size_t s = 0; s < t.cleaned.segments.size(); ++s) {
    const auto& points = t.cleaned.segments[s].points;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::optional<track::Cover> c = track::classify_cover(points[i].ele, ground[s][i], surface[s][i]);
      t.cover.push_back(c ? static_cast<std::uint8_t>(*c) : Track::kNoCover);
    }
  }
}

}  // namespace

void fill_point_arrays(Track& t, const std::vector<std::vector<double>>& ground) {
  fill_point_arrays(t, track::compute_metrics(t.cleaned, t.metrics_options), ground);
}

void fill_point_arrays(Track& t, const track::TrackMetrics& metrics, const std::vector<std::vector<double>>& ground) {
  if (metrics.segments.size() != t.cleaned.segments.size())
    throw std::invalid_argument(fmt::format("track '{}': metrics for {} segments, the track has {}", t.name,
                                            metrics.segments.size(), t.cleaned.segments.size()));
  if (!ground.empty() && ground.size() != t.cleaned.segments.size())
    throw std::invalid_argument(fmt::format("track '{}': ground heights for {} segments, the track has {}", t.name,
                                            ground.size(), t.cleaned.segments.size()));
  const std::size_t n = t.cleaned.point_count();
  t.segment_first.clear();
  for (auto* v :
       {&t.distance_m, &t.time_unix_s, &t.altitude_m, &t.pressure_altitude_m, &t.gnss_altitude_m,
        &t.ground_m, &t.speed_kmh, &t.vspeed_ms, &t.heart_rate_bpm, &t.cadence_rpm, &t.power_w}) {
    v->clear();
    v->reserve(n);
  }
  for (std::size_t s = 0; s < t.cleaned.segments.size(); ++s) {
    const auto& points = t.cleaned.segments[s].points;
    const track::SegmentMetrics& m = metrics.segments[s];
    if (m.size() != points.size())
      throw std::invalid_argument(fmt::format("track '{}' segment {}: metrics for {} points, it has {}", t.name, s + 1,
                                              m.size(), points.size()));
    if (!ground.empty() && ground[s].size() != points.size())
      throw std::invalid_argument(fmt::format("track '{}' segment {}: ground heights for {} points, it has {}", t.name,
                                              s + 1, ground[s].size(), points.size()));
    if (points.empty()) continue;
    t.segment_first.push_back(t.distance_m.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const track::TrackPoint& p = points[i];
      t.distance_m.push_back(m.distance_m[i]);
      t.time_unix_s.push_back(p.time);
      t.altitude_m.push_back(p.ele);
      t.pressure_altitude_m.push_back(as_double(p.pressure_altitude));
      t.gnss_altitude_m.push_back(as_double(p.gnss_altitude));
      t.ground_m.push_back(ground.empty() ? kNaN : ground[s][i]);
      t.speed_kmh.push_back(m.speed_ms[i] * 3.6);
      t.vspeed_ms.push_back(m.vspeed_ms[i]);
      t.heart_rate_bpm.push_back(as_double(p.heart_rate));
      t.cadence_rpm.push_back(as_double(p.cadence));
      t.power_w.push_back(as_double(p.power));
    }
  }
  // Channels no point recorded take no memory (the accessors answer NaN): most tracks have no
  // heart rate, cadence, power or IGC altitudes, and a season of them is millions of points.
  for (auto* v : {&t.pressure_altitude_m, &t.gnss_altitude_m, &t.heart_rate_bpm, &t.cadence_rpm, &t.power_w})
    if (std::none_of(v->begin(), v->end(), [](double x) { return std::isfinite(x); })) std::vector<double>().swap(*v);
  if (n > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument(fmt::format("track '{}' has {} points: more than a track can hold", t.name, n));
  t.timed_points.clear();
  t.times_rise = true;
  for (std::size_t i = 0; i < t.time_unix_s.size(); ++i) {
    if (std::isnan(t.time_unix_s[i])) continue;
    if (!t.timed_points.empty() && t.time_unix_s[i] < t.time_unix_s[t.timed_points.back()]) t.times_rise = false;
    t.timed_points.push_back(static_cast<std::uint32_t>(i));
  }
  t.timed_points.shrink_to_fit();
  t.time_origin_s = t.timed_points.empty() ? kNaN : t.time_unix_s[t.timed_points.front()];
}

std::vector<std::vector<double>> sample_ground_heights(const track::Track& t, terrain::HeightSource* heights) {
  std::vector<std::vector<double>> out;
  std::unique_ptr<terrain::HeightSampler> sampler;
  if (heights != nullptr) sampler = std::make_unique<terrain::HeightSampler>(*heights);
  for (const auto& s : t.segments) {
    if (!sampler) {
      out.emplace_back(s.points.size(), kNaN);
      continue;
    }
    std::vector<geo::LatLon> points;
    points.reserve(s.points.size());
    for (const auto& p : s.points) points.push_back({p.lat, p.lon});
    out.push_back(sampler->sample(points));
  }
  return out;
}

std::vector<Track> build_file_tracks(const LoadedTrackFile& loaded, const TrackStyle& style,
                                     const TrackBuildOptions& options) {
  if (style.color_by == track::ColorMetric::agl && options.heights == nullptr)
    throw std::runtime_error("--color-by agl needs terrain heights: give --terrain (a DEM, tiles or a URL)");
  if (style.color_by == track::ColorMetric::cover && (options.surface == nullptr || options.heights == nullptr))
    throw std::runtime_error("--color-by cover needs --surface (a surface model beside --terrain)");
  const bool by_value = style.color_by != track::ColorMetric::solid;
  std::vector<Track> tracks;
  for (const NamedTrack& named : tracks_of(loaded)) {
    Track t;
    t.name = named.name;
    t.source = loaded.path;
    track::CleanReport report;
    // A route's points are planned places, not noisy fixes: smoothing would pull its corners in.
    track::CleanOptions clean = options.analysis.clean;
    if (named.is_route()) clean.smooth = false;
    t.cleaned = track::clean_track(named.raw(), clean, report);
    t.metrics_options = options.analysis.metrics;
    const track::TrackMetrics metrics = track::compute_metrics(t.cleaned, t.metrics_options);
    std::vector<std::vector<double>> ground;
    const bool with_surface = options.surface != nullptr && options.heights != nullptr;
    if (needs_ground(t.cleaned, style) || (options.inspect && options.heights != nullptr) || with_surface)
      ground = sample_ground_heights(t.cleaned, options.heights);
    if (with_surface) fill_cover(t, ground, sample_ground_heights(t.cleaned, options.surface));
    t.is_route = named.is_route();
    t.by_value = !t.is_route;
    if (!t.is_route && (options.analyse_flights || options.inspect || style.color_by == track::ColorMetric::phase ||
                        style.color_by == track::ColorMetric::thermals))
      t.flights = std::make_shared<const track::flight::FlightAnalysis>(track::flight::analyse_flights(named.raw()));
    std::vector<std::vector<float>> values;
    if (t.is_route)
      values = distances_along(metrics);
    else if (by_value)
      values = values_for(t, metrics, style.color_by, ground.empty() ? nullptr : &ground);
    fill_geometry(t, ground, values, style, options.neutral_ground_m);
    // Ground heights are kept only where they were sampled for every point of a source.
    fill_point_arrays(t, metrics, options.heights != nullptr ? ground : std::vector<std::vector<double>>{});
    if (options.inspect)
      t.summary = track::summarize_cleaned_track(named.raw(), t.cleaned, report, metrics, options.analysis);
    tracks.push_back(std::move(t));
  }
  return tracks;
}

void finish_tracks(std::vector<Track>& tracks, const TrackStyle& style, Diagnostics& diagnostics,
                   std::size_t first_palette_index, const track::ParallelFor& parallel) {
  assign_colors(tracks, style, first_palette_index);
  if (track::counts_neighbours(style.color_by)) {
    const std::size_t sources = apply_neighbour_counts(tracks, style.color_by, neighbour_radius_m(style), parallel);
    if (style.color_by == track::ColorMetric::thermals && sources == 0 && !tracks.empty())
      diagnostics.warning(
          "--color-by thermals: no flight climbed in a thermal (it needs flights with times and altitudes that "
          "circled): every point counts 0");
  }
  std::size_t points_with_value = 0;
  for (const Track& t : tracks)
    if (!t.is_route) points_with_value += t.points_with_value();
  const bool by_value = style.color_by != track::ColorMetric::solid;
  if (by_value && !style.range && points_with_value == 0)
    diagnostics.warning(
        fmt::format("no point has a value for --color-by {} ({}): the tracks are drawn in the neutral colour",
                    track::color_metric_name(style.color_by),
                    style.color_by == track::ColorMetric::phase ? "no flight with a thermal was found"
                                                                : "e.g. no times, or no such sensor"));
}

std::vector<Track> build_tracks(const std::vector<LoadedTrackFile>& files, const TrackStyle& style,
                                const TrackBuildOptions& options, Diagnostics& diagnostics,
                                std::size_t first_palette_index) {
  if (style.color_by == track::ColorMetric::agl && options.heights == nullptr)
    throw std::runtime_error("--color-by agl needs terrain heights: give --terrain (a DEM, tiles or a URL)");
  std::vector<Track> tracks;
  for (const LoadedTrackFile& loaded : files)
    for (Track& t : build_file_tracks(loaded, style, options)) tracks.push_back(std::move(t));
  finish_tracks(tracks, style, diagnostics, first_palette_index);
  return tracks;
}

void set_ground_heights(Track& t, terrain::HeightSource& heights) {
  std::size_t flat = 0;
  for (const auto& g : sample_ground_heights(t.cleaned, &heights))
    for (double h : g) t.ground_m.at(flat++) = h;
}

void apply_color_metric(Track& t, track::ColorMetric metric) {
  if (t.is_route) return;  // never by value: its values are the dashes' distances
  std::vector<std::vector<double>> ground;
  if (metric == track::ColorMetric::agl) {
    std::size_t flat = 0;
    for (const auto& s : t.cleaned.segments) {
      ground.emplace_back();
      for (std::size_t i = 0; i < s.points.size(); ++i) ground.back().push_back(t.ground_m.at(flat++));
    }
  }
  // Worked out again: a track keeps no metrics (Track::metrics_options).
  const track::TrackMetrics metrics =
      metric == track::ColorMetric::solid ? track::TrackMetrics{} : track::compute_metrics(t.cleaned, t.metrics_options);
  const auto values = metric == track::ColorMetric::solid ? std::vector<std::vector<float>>{}
                                                          : values_for(t, metrics, metric, ground.empty() ? nullptr : &ground);
  std::size_t line = 0;
  for (std::size_t s = 0; s < t.cleaned.segments.size(); ++s) {
    if (t.cleaned.segments[s].points.empty()) continue;
    auto& target = t.geometry.segments.at(line++).values;
    if (metric == track::ColorMetric::solid)
      target.clear();
    else
      target = values[s];
  }
  t.bump_revision();
}

void apply_curtain(Track& t, bool on, double neutral_ground_m) {
  for (std::size_t line = 0; line < t.geometry.segments.size() && line < t.segment_first.size(); ++line) {
    auto& heights = t.geometry.segments[line].heights_above_ground_m;
    heights.clear();
    if (!on) continue;
    const std::size_t first = t.segment_first[line];
    const std::size_t count = t.geometry.segments[line].points_ecef.size();
    for (std::size_t i = first; i < first + count && i < t.point_count(); ++i)
      heights.push_back(
          static_cast<float>(t.altitude_m[i] - (std::isnan(t.ground_m[i]) ? neutral_ground_m : t.ground_m[i])));
  }
  t.bump_revision();
}

track::Track cut_track(const Track& t, std::size_t first, std::size_t last) {
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

std::optional<track::Statistics> range_statistics(const Track& t, std::size_t first, std::size_t last,
                                                  const track::AnalysisOptions& analysis) {
  if (t.point_count() == 0) return std::nullopt;
  last = std::min(last, t.point_count() - 1);
  if (first > last) return std::nullopt;
  const track::Track cut = cut_track(t, first, last);
  return track::track_statistics(cut, track::compute_metrics(cut, analysis.metrics), analysis.statistics);
}

}  // namespace trailray::scene
