#include "scene/pins/thermal_markers.hpp"

#include <fmt/format.h>

#include <cmath>

#include "scene/camera/camera.hpp"

namespace trailray::scene {
namespace {

// Whole metres, never "-0".
long whole(double metres) { return std::lround(metres) == 0 ? 0L : std::lround(metres); }

std::string signed_climb(double ms) {
  const double rounded = std::round(ms * 10.0) / 10.0;
  if (rounded == 0.0) return "0.0";
  return fmt::format("{}{:.1f}", rounded > 0.0 ? "+" : "\u2212", std::abs(rounded));
}

}  // namespace

std::string thermal_label(const track::flight::Thermal& thermal) {
  return fmt::format("{} m/s \u00b7 {}\u2192{} m", signed_climb(thermal.mean_climb_ms), whole(thermal.start.alt),
                     whole(thermal.end.alt));
}

std::vector<Waypoint> thermal_markers(const Track& track) {
  std::vector<Waypoint> out;
  if (!track.flights) return out;
  int flight_number = 0;
  for (const track::flight::Flight& flight : track.flights->flights) {
    ++flight_number;
    int number = 0;
    for (const track::flight::Thermal& th : flight.thermals) {
      ++number;
      if (!(th.gain_m > 0.0) || !std::isfinite(th.end.alt) || !std::isfinite(th.start.alt)) continue;
      Waypoint w;
      w.name = thermal_label(th);
      w.description = fmt::format("thermal {} of flight {}: {:.0f} s, {:.1f} turns, best {:.1f} m/s", number,
                                  flight_number, th.duration_s, th.turns, th.best_climb_ms);
      w.symbol = "thermal";
      w.source = track.source;
      w.kind = WaypointKind::Thermal;
      w.lat_deg = th.end.lat;
      w.lon_deg = th.end.lon;
      w.ele_m = th.end.alt;
      w.time_unix_s = th.end.time;
      w.marker_ecef = ecef_from({th.end.lat, th.end.lon, th.end.alt});
      w.ground_ecef = w.marker_ecef;
      w.priority = static_cast<int>(std::lround(th.gain_m));
      out.push_back(std::move(w));
    }
  }
  return out;
}

}  // namespace trailray::scene
