// A thermal's climb figures and the wind its drift implies; a glide's distance and glide ratio.
#include <algorithm>
#include <cmath>

#include "geo/geodesic.hpp"
#include "track/flight/flight_samples.hpp"

namespace trailray::track::flight::detail {
namespace {

struct Centre {
  double t, e, n;
};

// Time-means of the position over every full turn starting at each sample (the air mass's circle
// centre at the turn's mid-time). Positions relative to the thermal's first sample.
std::vector<Centre> turn_centres(const std::vector<Sample>& s, const Run& run, const std::vector<double>& c) {
  const std::size_t n = run.last - run.first + 1;
  std::vector<EastNorth> pos(n);
  std::vector<double> ie(n, 0.0), in(n, 0.0);  // integral of the position from the first sample
  const Sample& s0 = s[run.first];
  for (std::size_t k = 0; k < n; ++k) {
    pos[k] = east_north(s0.lat, s0.lon, s[run.first + k].lat, s[run.first + k].lon);
    if (k > 0) {
      const double dt = s[run.first + k].time - s[run.first + k - 1].time;
      ie[k] = ie[k - 1] + 0.5 * (pos[k].e + pos[k - 1].e) * dt;
      in[k] = in[k - 1] + 0.5 * (pos[k].n + pos[k - 1].n) * dt;
    }
  }
  std::vector<Centre> out;
  std::size_t j = 1;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double target = c[i] + 360.0;
    j = std::max(j, i + 1);
    while (j > i + 1 && c[j - 1] >= target) --j;
    while (j < n && c[j] < target) ++j;
    if (j >= n) break;  // no full turn left
    // The turn ends between samples j-1 and j, where the heading has changed by exactly 360.
    const double f = (target - c[j - 1]) / (c[j] - c[j - 1]);
    const double ta = s[run.first + j - 1].time, tb = s[run.first + j].time;
    const double tj = ta + f * (tb - ta);
    const double ej = pos[j - 1].e + f * (pos[j].e - pos[j - 1].e);
    const double nj = pos[j - 1].n + f * (pos[j].n - pos[j - 1].n);
    const double ti = s[run.first + i].time;
    const double te = ie[j - 1] - ie[i] + 0.5 * (pos[j - 1].e + ej) * (tj - ta);
    const double tn = in[j - 1] - in[i] + 0.5 * (pos[j - 1].n + nj) * (tj - ta);
    out.push_back({0.5 * (ti + tj), te / (tj - ti), tn / (tj - ti)});
  }
  return out;
}

// Least-squares velocity (slope in time) of the centres; false when they span too little time.
bool fit_velocity(const std::vector<Centre>& c, double min_span_s, double& ve, double& vn) {
  if (c.size() < 2 || c.back().t - c.front().t < min_span_s) return false;
  double mt = 0, me = 0, mn = 0;
  for (const Centre& x : c) {
    mt += x.t;
    me += x.e;
    mn += x.n;
  }
  const double k = static_cast<double>(c.size());
  mt /= k;
  me /= k;
  mn /= k;
  double stt = 0, ste = 0, stn = 0;
  for (const Centre& x : c) {
    stt += (x.t - mt) * (x.t - mt);
    ste += (x.t - mt) * (x.e - me);
    stn += (x.t - mt) * (x.n - mn);
  }
  if (!(stt > 0)) return false;
  ve = ste / stt;
  vn = stn / stt;
  return true;
}

}  // namespace

Thermal thermal_figures(const std::vector<Sample>& s, const Run& run, const std::vector<double>& heading_sum,
                        std::size_t flight_first, const FlightOptions& o) {
  Thermal t;
  const Sample& a = s[run.first];
  const Sample& b = s[run.last];
  t.start = place_of(a);
  t.end = place_of(b);
  t.direction = run.phase;
  t.duration_s = b.time - a.time;
  t.gain_m = b.alt - a.alt;
  t.mean_climb_ms = t.duration_s > 0 ? t.gain_m / t.duration_s : kMissing;
  // Best climb: over every stretch from a fix to the first fix at least the window later.
  t.best_climb_ms = kMissing;
  std::size_t j = run.first;
  for (std::size_t i = run.first; i <= run.last; ++i) {
    j = std::max(j, i);
    while (j < run.last && s[j].time < s[i].time + o.best_climb_window_s) ++j;
    if (s[j].time < s[i].time + o.best_climb_window_s) break;
    const double climb = (s[j].alt - s[i].alt) / (s[j].time - s[i].time);
    if (std::isnan(t.best_climb_ms) || climb > t.best_climb_ms) t.best_climb_ms = climb;
  }
  if (std::isnan(t.best_climb_ms)) t.best_climb_ms = t.mean_climb_ms;
  // Heading change since the thermal's start, positive in its own turning direction.
  const double sign = run.phase == Phase::CirclingLeft ? -1.0 : 1.0;
  std::vector<double> c(run.last - run.first + 1);
  for (std::size_t k = 0; k < c.size(); ++k)
    c[k] = sign * (heading_sum[run.first + k - flight_first] - heading_sum[run.first - flight_first]);
  t.turns = std::max(0.0, c.back() / 360.0);
  double ve = 0, vn = 0;
  if (t.turns >= 2.0 && fit_velocity(turn_centres(s, run, c), 0.0, ve, vn)) {
    t.wind_from_centres = true;
  } else if (t.duration_s > 0) {
    const EastNorth d = east_north(a.lat, a.lon, b.lat, b.lon);
    ve = d.e / t.duration_s;
    vn = d.n / t.duration_s;
  }
  t.wind_speed_ms = std::hypot(ve, vn);
  t.drift_m = t.wind_speed_ms * t.duration_s;
  t.drift_to_deg = bearing_deg(ve, vn);
  t.wind_from_deg = bearing_deg(-ve, -vn);
  return t;
}

Glide glide_figures(const std::vector<Sample>& s, const Run& run) {
  Glide g;
  const Sample& a = s[run.first];
  const Sample& b = s[run.last];
  g.start = place_of(a);
  g.end = place_of(b);
  g.duration_s = b.time - a.time;
  for (std::size_t k = run.first + 1; k <= run.last; ++k)
    g.distance_m += geo::geodesic_distance_m(s[k - 1].lat, s[k - 1].lon, s[k].lat, s[k].lon);
  g.height_lost_m = a.alt - b.alt;
  g.glide_ratio = g.height_lost_m > 0 ? g.distance_m / g.height_lost_m : kMissing;
  g.mean_speed_ms = g.duration_s > 0 ? g.distance_m / g.duration_s : 0.0;
  return g;
}

}  // namespace trailray::track::flight::detail
