#include "track/clean.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "geo/geodesic.hpp"
#include "geo/local_frame.hpp"
#include "geo/wgs84.hpp"

namespace trailray::track {
namespace {

bool valid_coordinates(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0 && std::abs(p.lon) <= 180.0;
}

// A segment whose clock never advances: at least 3 timestamps spanning less than 1 ms per point
// (no GPS logs at 1 kHz; seen with placeholder times such as 1901-12-13T20:45:52Z). Fed the
// finite timestamps of the points with valid coordinates.
struct FrozenClockCheck {
  std::size_t timed = 0;
  double lo = 0.0, hi = 0.0;
  void add(double t) {
    lo = timed == 0 ? t : std::min(lo, t);
    hi = timed == 0 ? t : std::max(hi, t);
    ++timed;
  }
  bool frozen() const { return timed >= 3 && hi - lo < 1e-3 * static_cast<double>(timed - 1); }
};

bool same_fix(const TrackPoint& a, const TrackPoint& b) {
  const bool same_ele = a.ele == b.ele || (std::isnan(a.ele) && std::isnan(b.ele));
  return a.time == b.time && a.lat == b.lat && a.lon == b.lon && same_ele;
}

// Step 2b: runs of one timestamp at different places get evenly spread times over the
// interval to the next later timestamp (at most 1 s: loggers stamp whole seconds). Real runs
// are up to 10 long (10 Hz loggers); a longer run than kMaxFixesPerSecond is a stuck clock
// (seen: 51 fixes, 30 m apart, all stamped 10:24:03) and loses its times instead.
constexpr std::size_t kMaxFixesPerSecond = 20;

void spread_same_second_runs(std::vector<TrackPoint>& pts, CleanReport& report) {
  std::size_t i = 0;
  while (i < pts.size()) {
    if (!pts[i].has_time()) {
      ++i;
      continue;
    }
    const double t = pts[i].time;
    std::size_t end = i + 1;
    while (end < pts.size() && pts[end].time == t) ++end;
    const std::size_t run = end - i;
    if (run > kMaxFixesPerSecond) {
      // No logger writes that many fixes in one second: the clock stood still. Keep the
      // places, drop the made-up times.
      for (std::size_t k = 1; k < run; ++k) pts[i + k].time = kMissing;
      report.frozen_time += run - 1;
    } else if (run >= 2) {
      double next = kMissing;
      for (std::size_t k = end; k < pts.size(); ++k)
        if (pts[k].has_time()) {
          next = pts[k].time;
          break;
        }
      const double span = std::isnan(next) || next <= t ? 1.0 : std::min(next - t, 1.0);
      for (std::size_t k = 1; k < run; ++k)
        pts[i + k].time = t + span * static_cast<double>(k) / static_cast<double>(run);
      report.spread_time += run - 1;
    }
    i = end;
  }
}

// Steps 1 and 2: invalid coordinates, non-finite values, duplicates, same-second runs,
// non-increasing timestamps. Returns the kept points: one copy of the input, then compacted in
// place. The frozen-clock check needs every timestamp first: the copy assumes a running clock
// and is redone in the rare case that it was frozen.
std::vector<TrackPoint> drop_invalid_and_unordered(const std::vector<TrackPoint>& in, CleanReport& report) {
  std::vector<TrackPoint> pts;
  pts.reserve(in.size());
  CleanReport r;         // added to `report` once the pass is final
  bool repeats = false;  // two consecutive kept points with one timestamp: runs to spread
  bool ordered = true;   // every timestamp after the last earlier one: nothing to drop
  for (const bool frozen : {false, true}) {
    pts.clear();
    r = CleanReport{};
    repeats = false;
    ordered = true;
    FrozenClockCheck clock;
    double last_time = kMissing;
    for (const TrackPoint& in_point : in) {
      if (!valid_coordinates(in_point)) {
        ++r.invalid_coordinates;
        continue;
      }
      TrackPoint p = in_point;
      if (std::isinf(p.ele) || std::isinf(p.time)) {
        if (std::isinf(p.ele)) p.ele = kMissing;
        if (std::isinf(p.time)) p.time = kMissing;
        ++r.invalid_values;
      }
      if (p.has_time()) {
        clock.add(p.time);
        if (frozen) {
          p.time = kMissing;
          ++r.frozen_time;
        }
      }
      if (p.has_time()) {
        if (!pts.empty() && same_fix(pts.back(), p)) {
          ++r.duplicate_points;
          continue;
        }
        if (!pts.empty() && pts.back().time == p.time) repeats = true;
        if (!std::isnan(last_time) && !(p.time > last_time)) ordered = false;
        last_time = p.time;
      }
      pts.push_back(p);
    }
    if (frozen || !clock.frozen()) break;
  }
  report.invalid_coordinates += r.invalid_coordinates;
  report.invalid_values += r.invalid_values;
  report.frozen_time += r.frozen_time;
  report.duplicate_points += r.duplicate_points;

  if (repeats) spread_same_second_runs(pts, report);
  if (repeats || !ordered) {
    std::size_t kept = 0;
    double last_time = kMissing;  // the last kept timestamp of this segment
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const TrackPoint& p = pts[i];
      if (p.has_time()) {
        if (!std::isnan(last_time) && !(p.time > last_time)) {
          ++report.non_increasing_time;
          continue;
        }
        last_time = p.time;
      }
      if (kept != i) pts[kept] = p;
      ++kept;
    }
    pts.resize(kept);
  }
  return pts;
}

// Step 3: minimum distance between consecutive kept points; first and last points stay.
// In place: pts[0, kept) are the kept points, the last of them the one compared with. The
// distances between consecutive input points are computed a block ahead, in a loop of their
// own (no dependency between them, so the processor overlaps them); the comparison uses them
// whenever the previous point was kept, which is nearly always.
void enforce_min_distance(std::vector<TrackPoint>& pts, double min_distance_m, CleanReport& report) {
  if (!(min_distance_m > 0.0) || pts.size() < 2) return;
  const std::size_t n = pts.size();
  constexpr std::size_t kBlock = 1024;
  double step[kBlock];
  std::size_t kept = 1;
  bool prev_is_last_kept = true;  // the point before i is pts[kept - 1]
  for (std::size_t start = 1; start < n; start += kBlock) {
    const std::size_t end = std::min(n, start + kBlock);
    // pts[start - 1, end) are all originals here: compaction only wrote below kept <= start.
    for (std::size_t i = start; i < end; ++i)
      step[i - start] = geo::geodesic_distance_m(pts[i - 1].lat, pts[i - 1].lon, pts[i].lat, pts[i].lon);
    for (std::size_t i = start; i < end; ++i) {
      const TrackPoint& p = pts[i];
      const TrackPoint& prev = pts[kept - 1];
      double d = prev_is_last_kept ? step[i - start] : geo::geodesic_distance_m(prev.lat, prev.lon, p.lat, p.lon);
      if (prev.has_ele() && p.has_ele()) {
        const double dz = p.ele - prev.ele;
        const double d3 = std::sqrt(d * d + dz * dz);    // hypot is slow in glibc; it is only
        d = std::isfinite(d3) ? d3 : std::hypot(d, dz);  // needed where the squares overflow
      }
      prev_is_last_kept = true;
      if (d >= min_distance_m) {
        if (kept != i) pts[kept] = p;
        ++kept;
      } else if (i + 1 < n) {
        ++report.too_close;
        prev_is_last_kept = false;
      } else if (kept >= 2) {
        pts[kept - 1] = p;  // the last point replaces the previous kept one
        ++report.too_close;
      } else {
        if (kept != i) pts[kept] = p;  // only the first point before it: keep both
        ++kept;
      }
    }
  }
  pts.resize(kept);
}

// Step 4: Gaussian smoothing.
//
// A stretch is processed in blocks of kSmoothBlock points (or the half-width, if larger). A
// block's originals, with half a kernel on either side, are copied into small arrays: latitude
// and longitude offsets a, b from the first copied point, their products, the elevation and a
// has-elevation mask. For the points whose kernel is not truncated, every weighted sum over a
// window is then a convolution of one array with the kernel (loops the compiler vectorises),
// and the weighted moments of a and b give the 3D mean in closed form (geo::local_mean_offset).
// The few other points (truncated kernels at the stretch ends; windows reaching further than
// geo::kLocalMeanMaxOffsetDeg, or near a pole: the exact ECEF mean) are computed one by one.
// Smoothed values are written back once the next block has copied its originals, so every
// window sees original points. Elevations are summed in window order, as a plain loop would.
constexpr std::size_t kSmoothBlock = 1024;

struct SmoothScratch {
  std::vector<double> weight;          // w[j] = exp(-j^2 / (2 sigma^2)), j = 0..h
  std::vector<double> window_weight;   // the full kernel in window order: w[|t - h|], t = 0..2h
  std::vector<double> inv_weight_sum;  // for each k <= h: 1 / the sum of the 2k + 1 weights
  double window_weight_sum = 0.0;      // the sum of window_weight, added in window order
  // A block's originals, [g0, g1) of the stretch. a, b in degrees (b across the antimeridian);
  // e = elevation, 0 where missing, m = 1 where present, else 0; reach = prefix sums of
  // max(|da|, |db|) per step, bounding every offset within a window.
  std::vector<double> lat, lon, a, b, aa, bb, ab, e, m, reach;
  std::vector<double> fa, fb, faa, fbb, fab, fe, fm;  // convolutions, one per full-kernel point
  std::vector<geo::Ecef> ecef;                        // originals in ECEF, filled when needed
  std::vector<unsigned char> has_ecef;
  struct Results {
    std::size_t first = 0;
    std::vector<double> lat, lon, ele;
  };
  Results results[2];  // the current block's smoothed points and the previous block's
};

// y[c] = sum over t = 0..taps-1 of kernel[t] * x[c + t], c = 0..count-1, added in window order.
// With the number of taps known at compile time the inner loop unrolls and the compiler
// vectorises over c (several times faster than a pass over y per tap).
template <std::size_t Taps>
void convolve_fixed(const double* __restrict x, const double* __restrict kernel, std::size_t count,
                    double* __restrict y) {
  for (std::size_t c = 0; c < count; ++c) {
    double sum = 0.0;
    for (std::size_t t = 0; t < Taps; ++t) sum += kernel[t] * x[c + t];
    y[c] = sum;
  }
}

void convolve(const double* x, const std::vector<double>& kernel, std::size_t count, std::vector<double>& y) {
  y.resize(count);
  const double* k = kernel.data();
  switch (kernel.size()) {
    case 3:
      return convolve_fixed<3>(x, k, count, y.data());
    case 5:
      return convolve_fixed<5>(x, k, count, y.data());
    case 7:
      return convolve_fixed<7>(x, k, count, y.data());
    case 9:
      return convolve_fixed<9>(x, k, count, y.data());
    case 11:
      return convolve_fixed<11>(x, k, count, y.data());  // the default half-width, 5
    case 13:
      return convolve_fixed<13>(x, k, count, y.data());
    case 15:
      return convolve_fixed<15>(x, k, count, y.data());
    default:
      for (std::size_t c = 0; c < count; ++c) {
        double sum = 0.0;
        for (std::size_t t = 0; t < kernel.size(); ++t) sum += k[t] * x[c + t];
        y[c] = sum;
      }
  }
}

// For each full-kernel point c: the smoothed position from the convolutions (geo::local_mean_offset,
// longitude not yet wrapped into range) and elevation (NaN where no neighbour has one). iw: 1 /
// the kernel's sum. __restrict: no array overlaps another, so the compiler vectorises the loop.
void closed_form_means(std::size_t count, double iw, const double* __restrict lat, const double* __restrict lon,
                       const double* __restrict a, const double* __restrict b, const double* __restrict fa,
                       const double* __restrict fb, const double* __restrict faa, const double* __restrict fbb,
                       const double* __restrict fab, const double* __restrict fe, const double* __restrict fm,
                       double* __restrict out_lat, double* __restrict out_lon, double* __restrict out_ele) {
  for (std::size_t c = 0; c < count; ++c) {
    const double ma = fa[c] * iw, mb = fb[c] * iw;
    const geo::LatLonOffset d = geo::local_mean_offset(lat[c], ma - a[c], mb - b[c], faa[c] * iw - ma * ma,
                                                       fbb[c] * iw - mb * mb, fab[c] * iw - ma * mb);
    out_lat[c] = lat[c] + d.dlat;
    out_lon[c] = lon[c] + d.dlon;
    out_ele[c] = fe[c] / fm[c];
  }
}

class StretchSmoother {
 public:
  StretchSmoother(TrackPoint* s, std::size_t n, std::size_t half, SmoothScratch& scratch)
      : s_(s), n_(n), h_(half), block_(std::max(kSmoothBlock, half)), x_(scratch) {}

  void run() {
    SmoothScratch::Results* pending = nullptr;
    int current = 0;
    for (std::size_t start = 0; start < n_; start += block_) {
      const std::size_t end = std::min(n_, start + block_);
      gather(start >= h_ ? start - h_ : 0, std::min(n_, end + h_));
      if (pending) write_back(*pending);  // its originals are copied: they are done with
      SmoothScratch::Results& r = x_.results[current];
      smooth_block(start, end, r);
      pending = &r;
      current = 1 - current;
    }
    if (pending) write_back(*pending);
  }

 private:
  void gather(std::size_t g0, std::size_t g1) {
    g0_ = g0;
    const std::size_t len = g1 - g0;
    for (auto* v : {&x_.lat, &x_.lon, &x_.a, &x_.b, &x_.aa, &x_.bb, &x_.ab, &x_.e, &x_.m, &x_.reach}) v->resize(len);
    const double lat_ref = s_[g0].lat, lon_ref = s_[g0].lon;
    all_ele_ = true;
    for (std::size_t j = 0; j < len; ++j) {
      const TrackPoint& p = s_[g0 + j];
      const double a = p.lat - lat_ref, b = geo::wgs84::wrap_dlon_deg(p.lon - lon_ref);
      x_.lat[j] = p.lat;
      x_.lon[j] = p.lon;
      x_.a[j] = a;
      x_.b[j] = b;
      x_.aa[j] = a * a;
      x_.bb[j] = b * b;
      x_.ab[j] = a * b;
      const bool has = p.has_ele();
      all_ele_ = all_ele_ && has;
      x_.e[j] = has ? p.ele : 0.0;
      x_.m[j] = has ? 1.0 : 0.0;
      x_.reach[j] = j == 0 ? 0.0 : x_.reach[j - 1] + std::max(std::abs(a - x_.a[j - 1]), std::abs(b - x_.b[j - 1]));
    }
    ecef_cleared_ = false;
  }

  // Largest offset any point of the window [l - k, l + k] (copied indices) can have from l.
  double window_reach(std::size_t l, std::size_t k) const {
    return std::max(x_.reach[l + k] - x_.reach[l], x_.reach[l] - x_.reach[l - k]);
  }
  bool closed_form(std::size_t l, std::size_t k) const {
    return window_reach(l, k) <= geo::kLocalMeanMaxOffsetDeg && std::abs(x_.lat[l]) <= geo::kLocalMeanMaxLatDeg;
  }

  void smooth_block(std::size_t start, std::size_t end, SmoothScratch::Results& r) {
    r.first = start;
    const std::size_t len = end - start;
    r.lat.resize(len);
    r.lon.resize(len);
    r.ele.resize(len);
    // Points with the full kernel: [f0, f1).
    const std::size_t f0 = std::max(start, h_), f1 = std::min(end, n_ - h_);
    if (f0 < f1) {
      const std::size_t count = f1 - f0, x0 = f0 - h_ - g0_;
      const auto& kernel = x_.window_weight;
      convolve(&x_.a[x0], kernel, count, x_.fa);
      convolve(&x_.b[x0], kernel, count, x_.fb);
      convolve(&x_.aa[x0], kernel, count, x_.faa);
      convolve(&x_.bb[x0], kernel, count, x_.fbb);
      convolve(&x_.ab[x0], kernel, count, x_.fab);
      convolve(&x_.e[x0], kernel, count, x_.fe);
      if (all_ele_) {
        x_.fm.assign(count, x_.window_weight_sum);  // the same sum, in the same order
      } else {
        convolve(&x_.m[x0], kernel, count, x_.fm);
      }
      // Closed form for every full-kernel point: a loop without branches (vectorised).
      const std::size_t l0 = x0 + h_, o0 = f0 - start;
      closed_form_means(count, x_.inv_weight_sum[h_], &x_.lat[l0], &x_.lon[l0], &x_.a[l0], &x_.b[l0], x_.fa.data(),
                        x_.fb.data(), x_.faa.data(), x_.fbb.data(), x_.fab.data(), x_.fe.data(), x_.fm.data(),
                        &r.lat[o0], &r.lon[o0], &r.ele[o0]);
      double* out_lat = &r.lat[o0];
      double* out_lon = &r.lon[o0];
      double* out_ele = &r.ele[o0];
      // Then the longitude range, missing elevations, and the windows the closed form does not
      // cover.
      for (std::size_t c = 0; c < count; ++c) {
        const std::size_t l = x0 + h_ + c;
        out_lon[c] = geo::wgs84::wrap_dlon_deg(out_lon[c]);
        if (x_.m[l] == 0.0) out_ele[c] = s_[f0 + c].ele;
        if (!closed_form(l, h_)) exact_position(l, h_, out_lat[c], out_lon[c]);
      }
    }
    // The others: the stretch's end points stay, truncated kernels one by one.
    for (std::size_t i = start; i < end; ++i) {
      if (i >= f0 && i < f1) continue;
      const std::size_t o = i - start;
      if (i == 0 || i + 1 == n_) {
        r.lat[o] = s_[i].lat;
        r.lon[o] = s_[i].lon;
        r.ele[o] = s_[i].ele;
      } else {
        smooth_point(i - g0_, std::min({h_, i, n_ - 1 - i}), r.lat[o], r.lon[o], r.ele[o]);
        if (!s_[i].has_ele()) r.ele[o] = s_[i].ele;
      }
    }
  }

  // One point, copied index l, kernel half-width k, summing over the window.
  void smooth_point(std::size_t l, std::size_t k, double& lat, double& lon, double& ele) {
    if (closed_form(l, k)) {
      double sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;
      for (std::size_t j = l - k; j <= l + k; ++j) {
        const double wj = x_.weight[j > l ? j - l : l - j];
        const double a = x_.a[j] - x_.a[l], b = x_.b[j] - x_.b[l];
        sa += wj * a;
        sb += wj * b;
        saa += wj * a * a;
        sbb += wj * b * b;
        sab += wj * a * b;
      }
      const double iw = x_.inv_weight_sum[k];
      const double ma = sa * iw, mb = sb * iw;
      const geo::LatLonOffset d =
          geo::local_mean_offset(x_.lat[l], ma, mb, saa * iw - ma * ma, sbb * iw - mb * mb, sab * iw - ma * mb);
      lat = x_.lat[l] + d.dlat;
      lon = geo::wgs84::wrap_dlon_deg(x_.lon[l] + d.dlon);
    } else {
      exact_position(l, k, lat, lon);
    }
    double e = 0.0, we = 0.0;
    for (std::size_t j = l - k; j <= l + k; ++j) {
      const double wj = x_.weight[j > l ? j - l : l - j];
      e += wj * x_.e[j];
      we += wj * x_.m[j];
    }
    ele = e / we;
  }

  // The exact 3D mean (ECEF) of the window's originals, projected back onto the ellipsoid.
  void exact_position(std::size_t l, std::size_t k, double& lat, double& lon) {
    if (!ecef_cleared_) {
      x_.ecef.resize(x_.lat.size());
      x_.has_ecef.assign(x_.lat.size(), 0);
      ecef_cleared_ = true;
    }
    geo::Ecef mean;
    const double iw = x_.inv_weight_sum[k];
    for (std::size_t j = l - k; j <= l + k; ++j) {
      if (!x_.has_ecef[j]) {
        x_.ecef[j] = geo::to_ecef(x_.lat[j], x_.lon[j]);
        x_.has_ecef[j] = 1;
      }
      const double wj = x_.weight[j > l ? j - l : l - j] * iw;
      mean.x += wj * x_.ecef[j].x;
      mean.y += wj * x_.ecef[j].y;
      mean.z += wj * x_.ecef[j].z;
    }
    geo::from_ecef(mean, lat, lon);
  }

  void write_back(const SmoothScratch::Results& r) {
    for (std::size_t o = 0; o < r.lat.size(); ++o) {
      TrackPoint& p = s_[r.first + o];
      p.lat = r.lat[o];
      p.lon = r.lon[o];
      p.ele = r.ele[o];
    }
  }

  TrackPoint* s_;
  std::size_t n_, h_;
  std::size_t block_;  // at least h_: a block's window never reaches back beyond the previous block
  SmoothScratch& x_;
  std::size_t g0_ = 0;   // stretch index of the first copied point
  bool all_ele_ = true;  // every copied point has an elevation
  bool ecef_cleared_ = false;
};

// Gaussian smoothing with a symmetric, renormalised kernel over pts[first, last), in place.
void smooth_gaussian(std::vector<TrackPoint>& pts, std::size_t first, std::size_t last, int half_width, double sigma,
                     SmoothScratch& scratch) {
  const std::size_t n = last - first;
  if (n < 3 || half_width <= 0 || !(sigma > 0.0) || !std::isfinite(sigma)) return;
  const std::size_t half = std::min(static_cast<std::size_t>(half_width), (n - 1) / 2);

  auto& w = scratch.weight;
  w.resize(half + 1);
  for (std::size_t j = 0; j <= half; ++j) {
    const double x = static_cast<double>(j);
    w[j] = std::exp(-x * x / (2.0 * sigma * sigma));
  }
  scratch.window_weight.resize(2 * half + 1);
  scratch.window_weight_sum = 0.0;
  for (std::size_t t = 0; t <= 2 * half; ++t) {
    scratch.window_weight[t] = w[t > half ? t - half : half - t];
    scratch.window_weight_sum += scratch.window_weight[t];
  }
  scratch.inv_weight_sum.resize(half + 1);
  for (std::size_t k = 0; k <= half; ++k) {
    double sum = 0.0;
    for (std::size_t j = 0; j <= 2 * k; ++j) sum += w[j > k ? j - k : k - j];
    scratch.inv_weight_sum[k] = 1.0 / sum;
  }
  StretchSmoother(pts.data() + first, n, half, scratch).run();
}

// Smooths each stretch between pauses (timed points more than max_gap_s apart) on its own.
void smooth_pieces(std::vector<TrackPoint>& pts, const CleanOptions& o) {
  const bool pauses = std::isfinite(o.max_gap_s) && o.max_gap_s > 0.0;
  SmoothScratch scratch;
  std::size_t start = 0;
  double last_time = kMissing;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!pts[i].has_time()) continue;
    if (pauses && !std::isnan(last_time) && pts[i].time - last_time > o.max_gap_s) {
      smooth_gaussian(pts, start, i, o.smooth_half_width, o.smooth_sigma, scratch);
      start = i;
    }
    last_time = pts[i].time;
  }
  smooth_gaussian(pts, start, pts.size(), o.smooth_half_width, o.smooth_sigma, scratch);
}

}  // namespace

Segment clean_segment(const Segment& segment, const CleanOptions& options, CleanReport& report) {
  Segment out;
  out.points = drop_invalid_and_unordered(segment.points, report);
  enforce_min_distance(out.points, options.min_distance_m, report);
  if (options.smooth) smooth_pieces(out.points, options);
  return out;
}

Track clean_track(const Track& track, const CleanOptions& options, CleanReport& report) {
  Track out;
  out.name = track.name;
  out.description = track.description;
  out.type = track.type;
  out.segments.reserve(track.segments.size());
  for (const Segment& s : track.segments) out.segments.push_back(clean_segment(s, options, report));
  return out;
}

}  // namespace trailray::track
