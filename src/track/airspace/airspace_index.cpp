#include "track/airspace/airspace_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geo/geodesic.hpp"
#include "geo/longitude.hpp"
#include "geo/wgs84.hpp"

namespace trailray::track::airspace {
namespace {

// Boxes spanning more cells than this go to the list tested everywhere.
constexpr std::int64_t kMaxCellsPerAirspace = 4096;

std::int64_t cell_of(double deg) { return static_cast<std::int64_t>(std::floor(deg / AirspaceIndex::kCellDeg)); }

}  // namespace

AirspaceIndex::AirspaceIndex(const AirspaceFile& file) : file_(file) {
  boxes_.reserve(file.airspaces.size());
  for (std::uint32_t i = 0; i < file.airspaces.size(); ++i) {
    BoundingBox b{90, -90, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const auto& p : file.airspaces[i].boundary) {
      b.lat_min = std::min(b.lat_min, p.lat);
      b.lat_max = std::max(b.lat_max, p.lat);
      b.lon_min = std::min(b.lon_min, p.lon);
      b.lon_max = std::max(b.lon_max, p.lon);
    }
    boxes_.push_back(b);
    const std::int64_t x0 = cell_of(b.lon_min), x1 = cell_of(b.lon_max);
    const std::int64_t y0 = cell_of(b.lat_min), y1 = cell_of(b.lat_max);
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCellsPerAirspace) {
      wide_.push_back(i);
      continue;
    }
    for (std::int64_t x = x0; x <= x1; ++x)
      for (std::int64_t y = y0; y <= y1; ++y) cells_[cell_key(x, y)].push_back(i);
  }
}

const std::vector<std::uint32_t>& AirspaceIndex::candidates(double lat, double lon) const {
  scratch_.clear();
  if (!(std::abs(lat) <= 90.0) || !(std::abs(lon) <= 180.0)) return scratch_;
  // A box across the antimeridian lies past +-180: the point a turn away may fall in it.
  for (const double x : {lon, lon - 360.0, lon + 360.0}) {
    const auto it = cells_.find(cell_key(cell_of(x), cell_of(lat)));
    if (it != cells_.end())
      for (std::uint32_t i : it->second)
        if (boxes_[i].contains(lat, x)) scratch_.push_back(i);
  }
  for (std::uint32_t i : wide_)
    for (const double x : {lon, lon - 360.0, lon + 360.0})
      if (boxes_[i].contains(lat, x)) {
        scratch_.push_back(i);
        break;
      }
  return scratch_;
}

bool AirspaceIndex::contains(std::size_t airspace, double lat, double lon) const {
  const auto& ring = file_.airspaces[airspace].boundary;
  if (ring.size() < 3) return false;  // a line (a cable) has no inside
  lon = geo::longitude_near(lon, boxes_[airspace].lon_min, boxes_[airspace].lon_max);
  if (!boxes_[airspace].contains(lat, lon)) return false;
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const geo::LatLon& a = ring[i];
    const geo::LatLon& b = ring[j];
    if ((a.lat > lat) != (b.lat > lat)) {
      const double lon_at = a.lon + (lat - a.lat) / (b.lat - a.lat) * (b.lon - a.lon);
      if (lon < lon_at) inside = !inside;
    }
  }
  return inside;
}

double AirspaceIndex::distance_to_boundary_m(std::size_t airspace, double lat, double lon) const {
  // Nearest edge in a local plane centred on the point (metres east and north through the
  // radii of curvature there); then the geodesic distance to that edge's nearest point, so the
  // plane's scale error (growing with distance) does not enter the result.
  const auto& ring = file_.airspaces[airspace].boundary;
  if (ring.empty()) return std::numeric_limits<double>::infinity();
  lon = geo::longitude_near(lon, boxes_[airspace].lon_min, boxes_[airspace].lon_max);
  const double phi = lat * geo::wgs84::kRadPerDeg;
  const double c = std::cos(phi);
  const geo::wgs84::RadiiSquared r = geo::wgs84::radii_squared_from_sin2(1.0 - c * c);
  const double m_per_deg_lat = std::sqrt(r.meridional_m2) * geo::wgs84::kRadPerDeg;
  const double m_per_deg_lon = std::sqrt(r.prime_vertical_m2) * c * geo::wgs84::kRadPerDeg;
  double best = std::numeric_limits<double>::infinity();
  geo::LatLon foot{lat, lon};
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const double ax = (ring[j].lon - lon) * m_per_deg_lon, ay = (ring[j].lat - lat) * m_per_deg_lat;
    const double bx = (ring[i].lon - lon) * m_per_deg_lon, by = (ring[i].lat - lat) * m_per_deg_lat;
    const double dx = bx - ax, dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? -(ax * dx + ay * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double px = ax + t * dx, py = ay + t * dy;
    const double d2 = px * px + py * py;
    if (d2 < best) {
      best = d2;
      foot = {ring[j].lat + t * (ring[i].lat - ring[j].lat), ring[j].lon + t * (ring[i].lon - ring[j].lon)};
    }
  }
  if (!std::isfinite(best)) return best;
  return geo::geodesic_distance_m(lat, lon, foot.lat, foot.lon);
}

}  // namespace trailray::track::airspace
