#pragma once
// Internal to flight analysis: the track as one time-ordered list of samples, and small local
// geometry helpers. Not part of the API (flight_analysis.hpp is).

#include <cmath>
#include <cstddef>
#include <vector>

#include "geo/wgs84.hpp"
#include "track/flight/flight_analysis.hpp"

namespace trailray::track::flight::detail {

struct Sample {
  double time = 0.0;
  double lat = 0.0, lon = 0.0;
  double alt = kMissing;    // NaN only when the whole track has no elevation
  std::size_t point = 0;    // Place::point
  bool gap_before = false;  // a segment boundary or a gap (see collect_samples) before this sample
};

struct Samples {
  std::vector<Sample> list;
  bool has_altitude = false;
};

// Points with a time, a finite position and a time after the previous sample's, in track order.
// Missing elevations take the nearest earlier one (the first known before any). A step longer
// than max_gap_s and than 3 times the median step is a gap.
Samples collect_samples(const Track& track, double max_gap_s);

Place place_of(const Sample& s);

// East/north metres of (lat, lon) from (lat0, lon0) on the tangent plane (equirectangular with
// the ellipsoid's radii at lat0): exact enough over a thermal or one step.
struct EastNorth {
  double e = 0.0, n = 0.0;
};
inline EastNorth east_north(double lat0, double lon0, double lat, double lon) {
  using namespace geo::wgs84;
  const double s = sin_lat(lat0 * kRadPerDeg);
  const RadiiSquared r = radii_squared_from_sin2(s * s);
  return {std::sqrt(r.prime_vertical_m2) * cos_lat(lat0 * kRadPerDeg) * wrap_dlon_deg(lon - lon0) * kRadPerDeg,
          std::sqrt(r.meridional_m2) * (lat - lat0) * kRadPerDeg};
}

// Compass bearing (degrees from north, [0, 360)) of an east/north vector.
inline double bearing_deg(double e, double n) {
  double b = std::atan2(e, n) / geo::wgs84::kRadPerDeg;
  if (b < 0) b += 360.0;
  return b >= 360.0 ? 0.0 : b;
}

// A run of one phase over samples [first, last] (last is the next run's first).
struct Run {
  Phase phase = Phase::Unknown;
  std::size_t first = 0, last = 0;
};

// The phases of the flight over samples [first, last], and the cumulative signed heading change
// (degrees, clockwise positive) at every sample of it (index 0 = `first`).
struct TurnPhases {
  std::vector<Run> runs;
  std::vector<double> heading_sum;
};
TurnPhases turn_phases(const std::vector<Sample>& s, std::size_t first, std::size_t last, const FlightOptions& o);

// Take-off and landing sample indexes of every flight, in order.
struct FlightRange {
  std::size_t takeoff = 0, landing = 0;
};
std::vector<FlightRange> find_flight_ranges(const std::vector<Sample>& s);

Thermal thermal_figures(const std::vector<Sample>& s, const Run& run, const std::vector<double>& heading_sum,
                        std::size_t flight_first, const FlightOptions& o);
Glide glide_figures(const std::vector<Sample>& s, const Run& run);

}  // namespace trailray::track::flight::detail
