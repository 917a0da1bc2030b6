#include "app/track_scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "geo/web_mercator.hpp"
#include "scene/camera.hpp"
#include "terrain/height_sampler.hpp"
#include "track/clean.hpp"
#include "track/metrics.hpp"

namespace trailray::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct NamedTrack {
  std::string name;
  const track::Track* track = nullptr;
  track::Track route_as_track;  // routes: one segment
};

std::vector<NamedTrack> tracks_of(const LoadedTrackFile& loaded) {
  std::vector<NamedTrack> out;
  const std::string stem = std::filesystem::path(loaded.path).filename().string();
  std::size_t number = 0;
  const auto name_for = [&](const std::string& own) {
    ++number;
    if (!own.empty()) return own;
    return number == 1 && loaded.file.tracks.size() + loaded.file.routes.size() == 1 ? stem
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
  if (style.metric == track::ColorMetric::agl || style.settings.curtain) return true;
  for (const auto& s : t.segments)
    for (const auto& p : s.points)
      if (!p.has_ele()) return true;
  return false;
}

}  // namespace

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

TrackScene build_track_scene(const std::vector<LoadedTrackFile>& files, const TrackStyle& style,
                             const TrackSceneInputs& inputs, const std::function<void(const std::string&)>& warn) {
  if (style.metric == track::ColorMetric::agl && inputs.heights == nullptr)
    throw std::runtime_error("--color-by agl needs terrain heights: give --terrain (a DEM, tiles or a URL)");
  TrackScene scene;
  const bool by_value = style.metric != track::ColorMetric::solid;
  std::vector<std::vector<float>> all_values;
  for (const LoadedTrackFile& loaded : files) {
    for (NamedTrack& named : tracks_of(loaded)) {
      const track::Track& raw = named.track != nullptr ? *named.track : named.route_as_track;
      track::CleanReport report;
      track::Track cleaned = track::clean_track(raw, inputs.analysis.clean, report);
      track::TrackMetrics metrics = track::compute_metrics(cleaned, inputs.analysis.metrics);
      std::vector<std::vector<double>> ground;
      if (needs_ground(cleaned, style) || (inputs.keep_analysis && inputs.heights != nullptr))
        ground = sample_ground_heights(cleaned, inputs.heights);
      std::vector<std::vector<float>> values;
      if (by_value) values = track::color_values(cleaned, metrics, style.metric, ground.empty() ? nullptr : &ground);

      SceneTrack out;
      out.name = named.name;
      for (std::size_t s = 0; s < cleaned.segments.size(); ++s) {
        const auto& points = cleaned.segments[s].points;
        if (points.empty()) continue;
        scene::TrackPolyline line;
        line.points_ecef.reserve(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
          const track::TrackPoint& p = points[i];
          double under = ground.empty() ? kNaN : ground[s][i];
          if (std::isnan(under)) under = inputs.neutral_ground_m;
          const double height = p.has_ele() ? p.ele : under;
          line.points_ecef.push_back(scene::to_dvec3(scene::ecef_from({p.lat, p.lon, height})));
          if (style.settings.curtain) line.heights_above_ground_m.push_back(static_cast<float>(height - under));
        }
        if (by_value) {
          line.values = values[s];
          for (float v : line.values)
            if (!std::isnan(v)) ++out.points_with_value;
          all_values.push_back(values[s]);
        }
        scene.points += points.size();
        out.geometry.segments.push_back(std::move(line));
      }
      if (inputs.keep_analysis) {
        out.summary = track::summarize_cleaned_track(raw, cleaned, report, metrics, inputs.analysis);
        if (inputs.heights != nullptr) out.ground_m = std::move(ground);
        out.cleaned = std::move(cleaned);
        out.metrics = std::move(metrics);
      }
      scene.tracks.push_back(std::move(out));
    }
  }

  // Colours: --color once for all, once per track, else the palette.
  if (!style.colors.empty() && style.colors.size() != 1 && style.colors.size() != scene.tracks.size())
    throw std::runtime_error(fmt::format("--color was given {} times for {} tracks: give it once, or once per track",
                                         style.colors.size(), scene.tracks.size()));
  for (std::size_t i = 0; i < scene.tracks.size(); ++i)
    scene.tracks[i].color_srgb = style.colors.empty()      ? scene::palette_color(i)
                                 : style.colors.size() == 1 ? style.colors.front()
                                                            : style.colors[i];

  if (by_value) {
    scene.range = style.range ? style.range
                              : track::robust_range(all_values, track::color_metric_is_signed(style.metric));
    if (!scene.range)
      warn(fmt::format("no point has a value for --color-by {} (e.g. no times, or no such sensor): the tracks are "
                       "drawn in the neutral colour",
                       track::color_metric_name(style.metric)));
  }
  return scene;
}

}  // namespace trailray::app
