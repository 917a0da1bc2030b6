#pragma once
// What density.cpp (the index) and density_cells.cpp (the questions) share: the cells' keys, and
// the arithmetic on whole-centimetre ECEF positions: any struct with int32 x, y, z (NeighbourIndex's own, private).
// Differences of int32 are exact in doubles, and so are their squares and sums below 2^53 (any two
// places on the Earth), so the only rounding is in the closest point on a segment.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#include "geo/wgs84.hpp"
#include "track/density.hpp"

namespace trailray::track::density_detail {

inline constexpr std::uint32_t kNoCell = std::numeric_limits<std::uint32_t>::max();

template <typename Job>
void run_all(std::size_t count, const ParallelFor& parallel, const Job& job) {
  if (parallel && count > 1) {
    parallel(count, job);
    return;
  }
  for (std::size_t i = 0; i < count; ++i) job(i);
}

// Cell coordinates are offset by 2^20 and packed in 21 bits each: with cells of at least 8 m,
// the Earth's +-6,378 km take +-797,000 cells, inside +-2^20.
inline constexpr std::int64_t kCellBias = std::int64_t{1} << 20;

inline std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  if (a % b != 0 && (a < 0) != (b < 0)) --q;
  return q;
}

inline std::uint64_t pack(std::int64_t cx, std::int64_t cy, std::int64_t cz) {
  return (static_cast<std::uint64_t>(cx + kCellBias) << 42) | (static_cast<std::uint64_t>(cy + kCellBias) << 21) |
         static_cast<std::uint64_t>(cz + kCellBias);
}

inline std::array<std::int64_t, 3> unpack(std::uint64_t key) {
  constexpr std::uint64_t mask = (std::uint64_t{1} << 21) - 1;
  return {static_cast<std::int64_t>((key >> 42) & mask) - kCellBias,
          static_cast<std::int64_t>((key >> 21) & mask) - kCellBias, static_cast<std::int64_t>(key & mask) - kCellBias};
}

// The place of a point on the ellipsoid (height 0) in whole centimetres; nullopt without a valid
// position.
template <typename Cm>
std::optional<Cm> surface_cm(double lat, double lon) {
  if (!std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > 90.0) return std::nullopt;
  const glm::dvec3 e = geo::ecef_from_geodetic(lat, lon, 0.0);
  return Cm{static_cast<std::int32_t>(std::llround(e.x * 100.0)), static_cast<std::int32_t>(std::llround(e.y * 100.0)),
            static_cast<std::int32_t>(std::llround(e.z * 100.0))};
}

template <typename Cm>
double distance_cm(const Cm& a, const Cm& b) {
  const double dx = static_cast<double>(b.x) - a.x, dy = static_cast<double>(b.y) - a.y,
               dz = static_cast<double>(b.z) - a.z;
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Squared distance from p to the segment a-b (a == b: the point): what decides a count.
template <typename Cm>
[[gnu::always_inline]] inline double segment_distance2(const Cm& p, const Cm& a, const Cm& b) {
  const double ax = static_cast<double>(a.x) - p.x, ay = static_cast<double>(a.y) - p.y,
               az = static_cast<double>(a.z) - p.z;
  const double dx = static_cast<double>(b.x) - a.x, dy = static_cast<double>(b.y) - a.y,
               dz = static_cast<double>(b.z) - a.z;
  const double length2 = dx * dx + dy * dy + dz * dz;
  double t = 0.0;
  if (length2 > 0.0) t = std::clamp(-(ax * dx + ay * dy + az * dz) / length2, 0.0, 1.0);
  const double cx = ax + t * dx, cy = ay + t * dy, cz = az + t * dz;
  return cx * cx + cy * cy + cz * cz;
}

// How far v is outside [lo, hi] (0 inside), without branches: these run for every run near a
// point, and which side a point lies on is a coin toss to a branch predictor.
inline double outside(std::int64_t v, std::int64_t lo, std::int64_t hi) {
  return static_cast<double>(std::max<std::int64_t>({lo - v, v - hi, 0}));
}

// Squared distance from p to a box (0 inside).
template <typename Cm>
[[gnu::always_inline]] inline double box_distance2(const Cm& p, const Cm& lo, const Cm& hi) {
  const double dx = outside(p.x, lo.x, hi.x), dy = outside(p.y, lo.y, hi.y), dz = outside(p.z, lo.z, hi.z);
  return dx * dx + dy * dy + dz * dz;
}

// Squared distance between two boxes (0 where they overlap).
template <typename Cm>
[[gnu::always_inline]] inline double box_box_distance2(const Cm& lo_a, const Cm& hi_a, const Cm& lo_b, const Cm& hi_b) {
  const double dx =
      static_cast<double>(std::max<std::int64_t>({std::int64_t{lo_b.x} - hi_a.x, std::int64_t{lo_a.x} - hi_b.x, 0}));
  const double dy =
      static_cast<double>(std::max<std::int64_t>({std::int64_t{lo_b.y} - hi_a.y, std::int64_t{lo_a.y} - hi_b.y, 0}));
  const double dz =
      static_cast<double>(std::max<std::int64_t>({std::int64_t{lo_b.z} - hi_a.z, std::int64_t{lo_a.z} - hi_b.z, 0}));
  return dx * dx + dy * dy + dz * dz;
}

template <typename Cm>
void grow(Cm& lo, Cm& hi, const Cm& p) {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

}  // namespace trailray::track::density_detail
