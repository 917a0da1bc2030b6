#include "app/pictures/elevation_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace trailray::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Centimetres are far below any DEM's accuracy; more digits would only be noise in the output.
nlohmann::ordered_json metres(double v) {
  if (std::isnan(v)) return nullptr;
  return std::round(v * 100.0) / 100.0;
}

std::string csv_number(double v, int decimals) { return std::isnan(v) ? "" : fmt::format("{:.{}f}", v, decimals); }

}  // namespace

ElevationSummary summarize(const std::vector<ElevationPoint>& points) {
  ElevationSummary s;
  s.points = points.size();
  std::vector<double> offsets;
  double sum = 0.0, squares = 0.0;
  for (const auto& p : points) {
    s.with_elevation += std::isnan(p.ele_m) ? 0 : 1;
    s.with_terrain += std::isnan(p.terrain_m) ? 0 : 1;
    if (const std::optional<track::Cover> c = p.cover()) {
      s.open += *c == track::Cover::open ? 1 : 0;
      s.covered += *c == track::Cover::covered ? 1 : 0;
      s.cover_below_ground += *c == track::Cover::below_ground ? 1 : 0;
    }
    const double d = p.agl_m();
    if (std::isnan(d)) continue;
    offsets.push_back(d);
    sum += d;
    squares += d * d;
    s.points_below_ground += d < 0.0 ? 1 : 0;
  }
  s.compared = offsets.size();
  if (offsets.empty()) {
    s.mean_offset_m = s.median_offset_m = s.rmse_m = s.min_offset_m = s.max_offset_m = kNaN;
    return s;
  }
  const auto n = static_cast<double>(offsets.size());
  s.mean_offset_m = sum / n;
  s.rmse_m = std::sqrt(squares / n);
  std::sort(offsets.begin(), offsets.end());
  const std::size_t mid = offsets.size() / 2;
  s.median_offset_m = offsets.size() % 2 ? offsets[mid] : (offsets[mid - 1] + offsets[mid]) / 2.0;
  s.min_offset_m = offsets.front();
  s.max_offset_m = offsets.back();
  return s;
}

double ElevationSummary::covered_share() const {
  const std::size_t classed = open + covered + cover_below_ground;
  return classed == 0 ? kNaN : static_cast<double>(covered) / static_cast<double>(classed);
}

nlohmann::ordered_json elevation_json(const ElevationReport& r) {
  const bool surface = !r.surface.empty();
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const auto& p : r.points) {
    nlohmann::ordered_json point = {{"lat", p.lat},
                                    {"lon", p.lon},
                                    {"ele_m", metres(p.ele_m)},
                                    {"terrain_m", metres(p.terrain_m)},
                                    {"agl_m", metres(p.agl_m())}};
    if (surface) {
      point["surface_m"] = metres(p.surface_m);
      point["canopy_m"] = metres(p.canopy_m());
      const std::optional<track::Cover> c = p.cover();
      point["cover"] = c ? nlohmann::ordered_json(std::string(track::cover_name(*c))) : nlohmann::ordered_json(nullptr);
    }
    point["track"] = p.track;
    point["segment"] = p.segment;
    points.push_back(std::move(point));
  }
  nlohmann::ordered_json doc = {{"path", r.path}, {"terrain", r.terrain}};
  if (surface) doc["surface"] = r.surface;
  doc["points"] = std::move(points);
  doc["summary"] = elevation_summary_json(r.summary, surface);
  return doc;
}

nlohmann::ordered_json elevation_summary_json(const ElevationSummary& s, bool with_surface) {
  nlohmann::ordered_json out = {{"points", s.points},
          {"points_with_elevation", s.with_elevation},
          {"points_with_terrain", s.with_terrain},
          {"mean_offset_m", metres(s.mean_offset_m)},
          {"median_offset_m", metres(s.median_offset_m)},
          {"rmse_m", metres(s.rmse_m)},
          {"min_offset_m", metres(s.min_offset_m)},
          {"max_offset_m", metres(s.max_offset_m)},
          {"points_below_ground", s.points_below_ground}};
  if (with_surface) {
    const double share = s.covered_share();
    out["points_open"] = s.open;
    out["points_covered"] = s.covered;
    out["points_cover_below_ground"] = s.cover_below_ground;
    out["covered_share"] = std::isnan(share) ? nlohmann::ordered_json(nullptr)
                                             : nlohmann::ordered_json(std::round(share * 10000.0) / 10000.0);
  }
  return out;
}

std::string elevation_csv(const ElevationReport& r) {
  const bool surface = !r.surface.empty();
  std::string out = surface ? "track,segment,lat,lon,ele_m,terrain_m,agl_m,surface_m,canopy_m,cover\n"
                            : "track,segment,lat,lon,ele_m,terrain_m,agl_m\n";
  for (const auto& p : r.points) {
    out += fmt::format("{},{},{:.7f},{:.7f},{},{},{}", p.track, p.segment, p.lat, p.lon, csv_number(p.ele_m, 2),
                       csv_number(p.terrain_m, 2), csv_number(p.agl_m(), 2));
    if (surface) {
      const std::optional<track::Cover> c = p.cover();
      out += fmt::format(",{},{},{}", csv_number(p.surface_m, 2), csv_number(p.canopy_m(), 2),
                         c ? track::cover_name(*c) : std::string_view());
    }
    out += '\n';
  }
  return out;
}

std::string elevation_table(const ElevationReport& r) {
  const ElevationSummary& s = r.summary;
  auto m = [](double v) { return std::isnan(v) ? std::string("-") : fmt::format("{:.1f} m", v); };
  std::string out = fmt::format("{}\n  terrain            {}\n", r.path, r.terrain);
  out += fmt::format("  points             {} ({} with elevation, {} with terrain)\n", s.points, s.with_elevation,
                     s.with_terrain);
  out += "  recorded - terrain (height above ground)\n";
  out += fmt::format("    mean             {}\n    median           {}\n    RMSE             {}\n", m(s.mean_offset_m),
                     m(s.median_offset_m), m(s.rmse_m));
  out += fmt::format("    lowest           {}\n    highest          {}\n", m(s.min_offset_m), m(s.max_offset_m));
  out += fmt::format("  below ground       {} point{}\n", s.points_below_ground, s.points_below_ground == 1 ? "" : "s");
  if (!r.surface.empty()) {
    const double share = s.covered_share();
    out += fmt::format("  surface            {}\n", r.surface);
    out += fmt::format("  under cover        {} ({} open, {} covered, {} below the ground)\n",
                       std::isnan(share) ? std::string("-") : fmt::format("{:.1f} %", 100.0 * share), s.open, s.covered,
                       s.cover_below_ground);
  }
  return out;
}

}  // namespace trailray::app
