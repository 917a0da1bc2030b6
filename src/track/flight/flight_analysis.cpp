#include "track/flight/flight_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "geo/geodesic.hpp"
#include "track/flight/flight_samples.hpp"

namespace trailray::track::flight {
namespace {

using detail::Sample;

// The duration-weighted mean wind vector of the thermals in each altitude band (by the thermal's
// mean altitude), of those whose wind came from their circle centres.
std::vector<WindBand> wind_bands(const std::vector<Thermal>& thermals, double band_m) {
  struct Sum {
    double e = 0, n = 0, w = 0;
    int count = 0;
  };
  std::map<long, Sum> bands;
  for (const Thermal& t : thermals) {
    const double mid = 0.5 * (t.start.alt + t.end.alt);
    if (!t.wind_from_centres || !std::isfinite(mid) || !std::isfinite(t.wind_speed_ms) || !(t.duration_s > 0) ||
        !(band_m > 0))
      continue;
    const double to = t.drift_to_deg * geo::wgs84::kRadPerDeg;
    Sum& s = bands[static_cast<long>(std::floor(mid / band_m))];
    s.e += t.wind_speed_ms * std::sin(to) * t.duration_s;
    s.n += t.wind_speed_ms * std::cos(to) * t.duration_s;
    s.w += t.duration_s;
    ++s.count;
  }
  std::vector<WindBand> out;
  for (const auto& [band, s] : bands) {
    WindBand b;
    b.floor_m = static_cast<double>(band) * band_m;
    b.ceiling_m = b.floor_m + band_m;
    const double e = s.e / s.w, n = s.n / s.w;
    b.speed_ms = std::hypot(e, n);
    b.from_deg = detail::bearing_deg(-e, -n);
    b.thermals = s.count;
    out.push_back(b);
  }
  return out;
}

Flight analyse_one(const std::vector<Sample>& s, const detail::FlightRange& range, const FlightOptions& o) {
  Flight f;
  f.takeoff = detail::place_of(s[range.takeoff]);
  f.landing = detail::place_of(s[range.landing]);
  f.duration_s = f.landing.time - f.takeoff.time;
  for (std::size_t k = range.takeoff; k <= range.landing; ++k) {
    if (k > range.takeoff) f.distance_m += geo::geodesic_distance_m(s[k - 1].lat, s[k - 1].lon, s[k].lat, s[k].lon);
    if (std::isfinite(s[k].alt)) {
      f.max_alt_m = std::isnan(f.max_alt_m) ? s[k].alt : std::max(f.max_alt_m, s[k].alt);
      f.min_alt_m = std::isnan(f.min_alt_m) ? s[k].alt : std::min(f.min_alt_m, s[k].alt);
    }
  }
  const detail::TurnPhases tp = detail::turn_phases(s, range.takeoff, range.landing, o);
  double gain = 0, climb_time = 0;
  for (const detail::Run& r : tp.runs) {
    PhaseSpan span;
    span.phase = r.phase;
    span.start = detail::place_of(s[r.first]);
    span.end = detail::place_of(s[r.last]);
    const double d = span.duration_s();
    const std::size_t index = f.phases.size();
    f.phases.push_back(span);
    switch (r.phase) {
      case Phase::CirclingLeft:
      case Phase::CirclingRight: {
        (r.phase == Phase::CirclingLeft ? f.circling_left_s : f.circling_right_s) += d;
        Thermal t = detail::thermal_figures(s, r, tp.heading_sum, range.takeoff, o);
        t.phase = index;
        // Circling down is not a thermal: it would be pinned on the map and drag the mean climb.
        if (!(t.gain_m >= o.min_thermal_gain_m)) break;
        if (std::isfinite(t.gain_m)) {
          gain += t.gain_m;
          climb_time += t.duration_s;
        }
        if (std::isfinite(t.best_climb_ms) && !(t.best_climb_ms <= f.best_climb_ms)) f.best_climb_ms = t.best_climb_ms;
        f.thermals.push_back(t);
        break;
      }
      case Phase::Gliding: {
        f.gliding_s += d;
        Glide g = detail::glide_figures(s, r);
        g.phase = index;
        f.glides.push_back(g);
        break;
      }
      default:
        f.unknown_s += d;
    }
  }
  f.circling_s = f.circling_left_s + f.circling_right_s;
  f.circling_share = f.duration_s > 0 ? f.circling_s / f.duration_s : 0.0;
  if (climb_time > 0) f.mean_thermal_climb_ms = gain / climb_time;
  for (std::size_t k = 0; k < f.glides.size(); ++k) {
    const Glide& g = f.glides[k];
    if (f.longest_glide < 0 || g.distance_m > f.glides[static_cast<std::size_t>(f.longest_glide)].distance_m)
      f.longest_glide = static_cast<int>(k);
    if (g.distance_m >= o.best_glide_min_m && g.height_lost_m >= o.best_glide_min_loss_m &&
        (f.best_glide < 0 || g.glide_ratio > f.glides[static_cast<std::size_t>(f.best_glide)].glide_ratio))
      f.best_glide = static_cast<int>(k);
  }
  f.wind = wind_bands(f.thermals, o.wind_band_m);
  return f;
}

}  // namespace

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::Ground:
      return "ground";
    case Phase::CirclingLeft:
      return "circling-left";
    case Phase::CirclingRight:
      return "circling-right";
    case Phase::Gliding:
      return "gliding";
    case Phase::Unknown:
      return "unknown";
  }
  return "unknown";
}

FlightAnalysis analyse_flights(const Track& track, const FlightOptions& options) {
  FlightAnalysis out;
  out.points = track.point_count();
  const detail::Samples samples = detail::collect_samples(track, options.max_gap_s);
  out.points_used = samples.list.size();
  out.has_altitude = samples.has_altitude;
  if (samples.list.size() < 2 || !samples.has_altitude) return out;
  for (const detail::FlightRange& r : detail::find_flight_ranges(samples.list))
    out.flights.push_back(analyse_one(samples.list, r, options));
  return out;
}

std::vector<Phase> phase_per_point(const Track& track, const FlightAnalysis& analysis) {
  std::vector<Phase> out(track.point_count(), Phase::Ground);
  for (const Flight& f : analysis.flights) {
    for (const PhaseSpan& p : f.phases)
      for (std::size_t k = p.start.point; k < p.end.point && k < out.size(); ++k) out[k] = p.phase;
    if (!f.phases.empty() && f.landing.point < out.size()) out[f.landing.point] = f.phases.back().phase;
  }
  return out;
}

}  // namespace trailray::track::flight
