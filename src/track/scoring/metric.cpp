#include "track/scoring/metric.hpp"

#include <algorithm>
#include <cmath>

#include "geo/geodesic.hpp"

namespace trailray::track::scoring {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr double kA = 6378.137;             // WGS84 semi-major axis, km
constexpr double kF = 1.0 / 298.257223563;  // WGS84 flattening
constexpr double kB = kA * (1.0 - kF);      // semi-minor axis, km
constexpr double kE2 = kF * (2.0 - kF);     // first eccentricity squared
// The largest normal curvature of the ellipsoid (meridian at the equator: radius b^2 / a).
constexpr double kMaxCurvature = kA / (kB * kB);
// Relative slack on every bound: covers floating-point rounding in the bound and the distance.
constexpr double kSlack = 1e-9;

// FCC coefficients (km per degree) from cos(mean latitude). k1 (along the meridian) grows with
// |latitude| and k2 (along the parallel) shrinks with it on [0, 90] degrees:
//   dk1/dphi = sin(2phi) (1.133210 - 0.0096 cos(2phi)) >= 0,
//   dk2/dphi = -111.41513 sin(phi) + 0.28365 sin(3phi) - 0.0006 sin(5phi) <= sin(phi) (-111.41513 + 0.851 + 0.003) <= 0
// (|sin(k phi)| <= k sin(phi) there). Both are even in phi. The bounds below rely on this.
inline void fcc_coefficients(double cosfm, double& k1, double& k2) {
  const double cos2 = 2 * cosfm * cosfm - 1;
  const double cos3 = cosfm * (2 * cos2 - 1);
  const double cos4 = 2 * cos2 * cos2 - 1;
  const double cos5 = 2 * cos2 * cos3 - cosfm;
  k1 = 111.13209 - 0.566605 * cos2 + 0.00120 * cos4;
  k2 = 111.41513 * cosfm - 0.09455 * cos3 + 0.00012 * cos5;
}

inline double fcc_from(double cosfm, double dlat, double dlon) {
  double k1 = 0, k2 = 0;
  fcc_coefficients(cosfm, k1, k2);
  return std::sqrt((k1 * dlat) * (k1 * dlat) + (k2 * dlon) * (k2 * dlon));
}

void ecef(double lat, double lon, double& x, double& y, double& z) {
  const double p = lat * kDegToRad, l = lon * kDegToRad;
  const double sp = std::sin(p), cp = std::cos(p);
  const double n = kA / std::sqrt(1 - kE2 * sp * sp);
  x = n * cp * std::cos(l);
  y = n * cp * std::sin(l);
  z = n * (1 - kE2) * sp;
}

// Upper bound on the geodesic length from the chord c (km). A geodesic of the ellipsoid, as a
// space curve, has curvature equal to the surface's normal curvature in its direction, at most
// kMaxCurvature. By Schur's comparison theorem a curve of length s <= pi/k with curvature <= k
// has a chord at least that of a circular arc of curvature k: c >= (2/k) sin(k s / 2), so
// s <= (2/k) asin(k c / 2). Scoring legs are far below pi/k (about 19,800 km).
double geodesic_upper_from_chord(double c) {
  const double x = std::min(1.0, kMaxCurvature * c * 0.5);
  return 2.0 / kMaxCurvature * std::asin(x);
}

}  // namespace

double fcc_distance_km(double lat1, double lon1, double lat2, double lon2) {
  return fcc_from(std::cos((lat1 + lat2) * 0.5 * kDegToRad), lat2 - lat1, lon2 - lon1);
}

Metric::Metric(const std::vector<Fix>& fixes, DistanceModel model) : fixes_(fixes), model_(model) {
  points_.resize(fixes.size());
  half_cos_.resize(fixes.size());
  half_sin_.resize(fixes.size());
  for (std::size_t i = 0; i < fixes.size(); ++i) {
    Box& b = points_[i];
    b.lat_min = b.lat_max = fixes[i].lat;
    b.lon_min = b.lon_max = fixes[i].lon;
    ecef(fixes[i].lat, fixes[i].lon, b.cx, b.cy, b.cz);
    set_coefficients(b);
    half_cos_[i] = std::cos(fixes[i].lat * 0.5 * kDegToRad);
    half_sin_[i] = std::sin(fixes[i].lat * 0.5 * kDegToRad);
  }
}

double Metric::distance(int i, int j) const {
  const Fix& a = fixes_[static_cast<std::size_t>(i)];
  const Fix& b = fixes_[static_cast<std::size_t>(j)];
  if (model_ == DistanceModel::Geodesic) return geo::geodesic_distance_m(a.lat, a.lon, b.lat, b.lon) / 1000.0;
  // cos((phi1 + phi2) / 2) from the half angles: no trigonometry per pair.
  const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
  const double cosfm = half_cos_[ui] * half_cos_[uj] - half_sin_[ui] * half_sin_[uj];
  return fcc_from(cosfm, b.lat - a.lat, b.lon - a.lon);
}

double Metric::distance(double lat1, double lon1, double lat2, double lon2) const {
  if (model_ == DistanceModel::Geodesic) return geo::geodesic_distance_m(lat1, lon1, lat2, lon2) / 1000.0;
  return fcc_distance_km(lat1, lon1, lat2, lon2);
}

Box Metric::merge(const Box& a, const Box& b) {
  Box m;
  m.lat_min = std::min(a.lat_min, b.lat_min);
  m.lat_max = std::max(a.lat_max, b.lat_max);
  m.lon_min = std::min(a.lon_min, b.lon_min);
  m.lon_max = std::max(a.lon_max, b.lon_max);
  set_coefficients(m);
  // A sphere holding both spheres: centre on the line between them.
  const double dx = b.cx - a.cx, dy = b.cy - a.cy, dz = b.cz - a.cz;
  const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (d + b.radius <= a.radius) {
    m.cx = a.cx, m.cy = a.cy, m.cz = a.cz, m.radius = a.radius;
  } else if (d + a.radius <= b.radius) {
    m.cx = b.cx, m.cy = b.cy, m.cz = b.cz, m.radius = b.radius;
  } else {
    const double r = (d + a.radius + b.radius) * 0.5;
    const double t = (r - a.radius) / d;
    m.cx = a.cx + dx * t, m.cy = a.cy + dy * t, m.cz = a.cz + dz * t;
    m.radius = r * (1 + kSlack);
  }
  return m;
}

void Metric::set_coefficients(Box& b) {
  b.side = b.lat_min > 0 ? 1 : (b.lat_max < 0 ? -1 : 0);
  const double abs_max = std::max(std::fabs(b.lat_min), std::fabs(b.lat_max));
  const double abs_min = b.side == 0 ? 0.0 : std::min(std::fabs(b.lat_min), std::fabs(b.lat_max));
  fcc_coefficients(std::cos(abs_min * kDegToRad), b.k1_at_min, b.k2_at_min);
  fcc_coefficients(std::cos(abs_max * kDegToRad), b.k1_at_max, b.k2_at_max);
}

namespace {

// Bounds of k1 and k2 over every mean latitude of a fix of a and a fix of b. The mean latitude
// lies between the two latitudes, so |mean| <= max(|lat|) of both boxes; when both boxes lie in
// the same hemisphere also |mean| >= min(|lat|) of both; otherwise it may be 0. k1 grows and k2
// shrinks with |latitude| (fcc_coefficients), which gives the four extremes.
struct KRange {
  double k1_hi, k2_hi, k1_lo, k2_lo;
};

KRange k_range(const Box& a, const Box& b) {
  KRange r{};
  r.k1_hi = std::max(a.k1_at_max, b.k1_at_max);
  r.k2_lo = std::min(a.k2_at_max, b.k2_at_max);
  if (a.side != 0 && a.side == b.side) {
    r.k2_hi = std::max(a.k2_at_min, b.k2_at_min);
    r.k1_lo = std::min(a.k1_at_min, b.k1_at_min);
  } else {
    double k1 = 0, k2 = 0;
    fcc_coefficients(1.0, k1, k2);
    r.k2_hi = k2;
    r.k1_lo = k1;
  }
  return r;
}

}  // namespace

double Metric::upper(const Box& a, const Box& b) const {
  if (model_ == DistanceModel::Geodesic) {
    // Chord between any two fixes <= centre distance + both radii (triangle inequality in 3D).
    const double dx = b.cx - a.cx, dy = b.cy - a.cy, dz = b.cz - a.cz;
    const double c = std::sqrt(dx * dx + dy * dy + dz * dz) + a.radius + b.radius;
    return geodesic_upper_from_chord(c) * (1 + kSlack) + 1e-9;
  }
  // FCC: d = sqrt((k1 dlat)^2 + (k2 dlon)^2) grows with |dlat|, |dlon|, k1 and k2: take the
  // largest of each.
  const KRange k = k_range(a, b);
  const double dlat = std::max(a.lat_max - b.lat_min, b.lat_max - a.lat_min);
  const double dlon = std::max(a.lon_max - b.lon_min, b.lon_max - a.lon_min);
  return std::sqrt((k.k1_hi * dlat) * (k.k1_hi * dlat) + (k.k2_hi * dlon) * (k.k2_hi * dlon)) * (1 + kSlack) + 1e-9;
}

double Metric::lower(const Box& a, const Box& b) const {
  if (model_ == DistanceModel::Geodesic) {
    // The geodesic is never shorter than the chord; the chord is at least centre distance - radii.
    const double dx = b.cx - a.cx, dy = b.cy - a.cy, dz = b.cz - a.cz;
    const double c = std::sqrt(dx * dx + dy * dy + dz * dz) - a.radius - b.radius;
    return std::max(0.0, c * (1 - kSlack) - 1e-9);
  }
  // FCC: the smallest |dlat|, |dlon| (gaps between the intervals) and the smallest k1, k2.
  const KRange k = k_range(a, b);
  const double dlat = std::max({0.0, a.lat_min - b.lat_max, b.lat_min - a.lat_max});
  const double dlon = std::max({0.0, a.lon_min - b.lon_max, b.lon_min - a.lon_max});
  return std::max(
      0.0, std::sqrt((k.k1_lo * dlat) * (k.k1_lo * dlat) + (k.k2_lo * dlon) * (k.k2_lo * dlon)) * (1 - kSlack) - 1e-9);
}

}  // namespace trailray::track::scoring
