#include "scene/tracks/track_set.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace trailray::scene {

const glm::dvec3& Track::ecef(std::size_t point) const {
  const std::size_t line = segment_of(point);
  if (line >= geometry.segments.size() || point < segment_first.at(line))
    throw std::out_of_range("Track::ecef: no point " + std::to_string(point) + " in '" + name + "'");
  return geometry.segments[line].points_ecef.at(point - segment_first[line]);
}

std::size_t Track::segment_of(std::size_t point) const {
  const auto it = std::upper_bound(segment_first.begin(), segment_first.end(), point);
  return it == segment_first.begin() ? 0 : static_cast<std::size_t>(it - segment_first.begin()) - 1;
}

std::optional<double> Track::start_time() const {
  for (double t : time_unix_s)
    if (!std::isnan(t)) return t;
  return std::nullopt;
}

std::optional<double> Track::end_time() const {
  for (auto it = time_unix_s.rbegin(); it != time_unix_s.rend(); ++it)
    if (!std::isnan(*it)) return *it;
  return std::nullopt;
}

double Track::lowest_altitude() const {
  double lowest = std::numeric_limits<double>::quiet_NaN();
  for (double h : altitude_m)
    if (std::isfinite(h) && !(h >= lowest)) lowest = h;
  return lowest;
}

namespace {

bool any_value(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double h) { return !std::isnan(h); });
}

}  // namespace

bool Track::has_pressure_altitude() const { return any_value(pressure_altitude_m); }
bool Track::has_gnss_altitude() const { return any_value(gnss_altitude_m); }

// The float the IGC altitudes are kept in differs from the drawn double by well under 1 cm; the
// GNSS and pressure altitudes of a fix differ by metres almost everywhere.
Track::AltitudeSource Track::altitude_source() const {
  constexpr double kSame = 0.01;  // metres
  std::size_t gnss = 0, pressure = 0;
  for (std::size_t i = 0; i < altitude_m.size(); ++i) {
    const double a = altitude_m[i];
    if (std::isnan(a)) continue;
    if (std::fabs(a - gnss_altitude(i)) <= kSame) ++gnss;
    if (std::fabs(a - pressure_altitude(i)) <= kSame) ++pressure;
  }
  if (gnss == 0 && pressure == 0) return AltitudeSource::none;
  return gnss >= pressure ? AltitudeSource::gnss : AltitudeSource::pressure;
}

std::size_t Track::points_with_value() const {
  std::size_t n = 0;
  for (const TrackPolyline& line : geometry.segments)
    n += static_cast<std::size_t>(
        std::count_if(line.values.begin(), line.values.end(), [](float v) { return !std::isnan(v); }));
  return n;
}

TrackId TrackSet::add(Track track) {
  static std::atomic<TrackId> next_id{1};
  track.id = next_id.fetch_add(1, std::memory_order_relaxed);
  tracks_.push_back(std::move(track));
  return tracks_.back().id;
}

const Track* TrackSet::find(TrackId id) const {
  for (const Track& t : tracks_)
    if (t.id == id) return &t;
  return nullptr;
}

Track* TrackSet::find(TrackId id) { return const_cast<Track*>(static_cast<const TrackSet&>(*this).find(id)); }

}  // namespace trailray::scene
