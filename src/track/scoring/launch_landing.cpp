#include "track/scoring/launch_landing.hpp"

#include <cmath>

#include "track/scoring/metric.hpp"

namespace trailray::track::scoring {
namespace {

constexpr double kHalfWindow = 5.0;  // s: half the moving-average period
constexpr double kFlightTime = 60.0, kFlightStartH = 5.0, kFlightStartV = 0.9, kFlightKeepH = 1.5, kFlightKeepV = 0.05;
constexpr double kGroundTime = 20.0, kGroundH = 2.5, kGroundV = 0.1;

}  // namespace

MotionAverages motion_averages(const std::vector<Fix>& fixes) {
  const int n = static_cast<int>(fixes.size());
  MotionAverages out;
  out.ground_speed.assign(static_cast<std::size_t>(n), 0.0);
  out.vertical_speed.assign(static_cast<std::size_t>(n), 0.0);
  if (n < 2) return out;
  std::vector<double> h(static_cast<std::size_t>(n), 0.0), v(static_cast<std::size_t>(n), 0.0);
  auto alt = [&](int i) {
    const Fix& f = fixes[static_cast<std::size_t>(i)];
    return (f.pressure_alt == 0 || f.pressure_alt < -1000) ? f.gnss_alt : f.pressure_alt;
  };
  for (int i = 1; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const double dt = fixes[u].time - fixes[u - 1].time;
    if (dt > 0) {
      h[u] = fcc_distance_km(fixes[u - 1].lat, fixes[u - 1].lon, fixes[u].lat, fixes[u].lon) * 1000.0 / dt;
      v[u] = (alt(i) - alt(i - 1)) / dt;
    } else {
      h[u] = h[u - 1];
      v[u] = v[u - 1];
    }
  }
  // Centred moving averages over fixes within +-5 s (window ends included as the reference does).
  std::vector<double> ph(static_cast<std::size_t>(n) + 1, 0.0), pv(static_cast<std::size_t>(n) + 1, 0.0);
  for (int i = 0; i < n; ++i) {
    ph[static_cast<std::size_t>(i) + 1] = ph[static_cast<std::size_t>(i)] + h[static_cast<std::size_t>(i)];
    pv[static_cast<std::size_t>(i) + 1] = pv[static_cast<std::size_t>(i)] + std::fabs(v[static_cast<std::size_t>(i)]);
  }
  for (int i = 0; i < n; ++i) {
    const double now = fixes[static_cast<std::size_t>(i)].time;
    int s = i;
    while (s > 0 && fixes[static_cast<std::size_t>(s)].time > now - kHalfWindow) --s;
    int e = i;
    while (e < n - 1 && fixes[static_cast<std::size_t>(e)].time < now + kHalfWindow) ++e;
    const double count = e - s + 1;
    out.ground_speed[static_cast<std::size_t>(i)] =
        (ph[static_cast<std::size_t>(e) + 1] - ph[static_cast<std::size_t>(s)]) / count;
    out.vertical_speed[static_cast<std::size_t>(i)] =
        (pv[static_cast<std::size_t>(e) + 1] - pv[static_cast<std::size_t>(s)]) / count;
  }
  return out;
}

std::vector<FlightWindow> find_flights(const std::vector<Fix>& fixes) {
  const int n = static_cast<int>(fixes.size());
  std::vector<FlightWindow> out;
  if (n < 2) return out;
  const MotionAverages ma = motion_averages(fixes);
  const std::vector<double>& hma = ma.ground_speed;
  const std::vector<double>& vma = ma.vertical_speed;
  std::vector<char> flying(static_cast<std::size_t>(n), 0), ground(static_cast<std::size_t>(n), 0);
  int fs = -1, gs = -1;
  for (int i = 0; i < n - 1; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (fs < 0 && hma[u] > kFlightStartH && vma[u] > kFlightStartV) fs = i;
    if (fs >= 0) {
      if (hma[u] > kFlightKeepH && vma[u] > kFlightKeepV) {
        if (fixes[u].time > fixes[static_cast<std::size_t>(fs)].time + kFlightTime) flying[u] = 1;
      } else {
        fs = -1;
      }
    }
    if (gs < 0 && hma[u] < kGroundH && vma[u] < kGroundV) gs = i;
    if (gs >= 0) {
      if (hma[u] < kGroundH && vma[u] < kGroundV) {
        if (fixes[u].time > fixes[static_cast<std::size_t>(gs)].time + kGroundTime) ground[u] = 1;
      } else {
        gs = -1;
      }
    }
  }
  for (int i = 0; i < n - 1; ++i) {
    if (!flying[static_cast<std::size_t>(i)]) continue;
    int j = i;
    while (j > 0 && !ground[static_cast<std::size_t>(j)]) --j;
    const int launch = j;
    j = i;
    while (j < n - 2 && !ground[static_cast<std::size_t>(j)]) ++j;
    out.push_back({launch, j});
    i = j;
  }
  return out;
}

std::vector<FlightWindow> detect_flights(const std::vector<Fix>& fixes) {
  std::vector<FlightWindow> out = find_flights(fixes);
  if (out.empty()) out.push_back({0, fixes.empty() ? 0 : static_cast<int>(fixes.size()) - 1});
  return out;
}

}  // namespace trailray::track::scoring
