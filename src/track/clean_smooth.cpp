// Cleaning step 4 (clean.hpp): Gaussian smoothing of positions and elevations (the elevation and
// the IGC pressure and GNSS altitudes, each over the neighbours that have one), stretch by stretch
// between pauses.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

#include "geo/local_frame.hpp"
#include "geo/wgs84.hpp"
#include "track/clean_steps.hpp"

namespace trailray::track::detail {
namespace {

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

// The IGC altitudes kept beside `ele` (TrackPoint::pressure_altitude, gnss_altitude), each smoothed
// on its own like `ele`, over the neighbours that have one.
constexpr float TrackPoint::*kAltitudeChannels[] = {&TrackPoint::pressure_altitude, &TrackPoint::gnss_altitude};
constexpr std::size_t kChannels = std::size(kAltitudeChannels);

// One such channel's copied values and mask (like e, m below) and their convolutions.
struct ChannelScratch {
  std::vector<double> e, m, fe, fm;
};

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
  ChannelScratch channel[kChannels];                  // filled only when a copied point has one
  std::vector<glm::dvec3> ecef;                       // originals in ECEF, filled when needed
  std::vector<unsigned char> has_ecef;
  struct Results {
    std::size_t first = 0;
    std::vector<double> lat, lon, ele;
    std::vector<double> channel[kChannels];
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
    for (std::size_t c = 0; c < kChannels; ++c) gather_channel(c, g0, len);
  }

  // Only IGC files have these altitudes: other tracks skip their arrays and convolutions.
  void gather_channel(std::size_t c, std::size_t g0, std::size_t len) {
    const auto field = kAltitudeChannels[c];
    bool any = false, all = true;
    for (std::size_t j = 0; j < len; ++j) {
      const bool has = !std::isnan(s_[g0 + j].*field);
      any = any || has;
      all = all && has;
    }
    any_[c] = any;
    all_[c] = all;
    if (!any) return;
    ChannelScratch& x = x_.channel[c];
    x.e.resize(len);
    x.m.resize(len);
    for (std::size_t j = 0; j < len; ++j) {
      const float v = s_[g0 + j].*field;
      const bool has = !std::isnan(v);
      x.e[j] = has ? static_cast<double>(v) : 0.0;
      x.m[j] = has ? 1.0 : 0.0;
    }
  }

  // Channel c of the full-kernel points [f0, f0 + count), x0 their window's first copied index,
  // into out (NaN where the point has none).
  void smooth_channel_full(std::size_t c, std::size_t f0, std::size_t count, std::size_t x0, double* out) {
    const auto field = kAltitudeChannels[c];
    if (!any_[c]) {
      for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<double>(s_[f0 + i].*field);
      return;
    }
    ChannelScratch& x = x_.channel[c];
    convolve(&x.e[x0], x_.window_weight, count, x.fe);
    if (all_[c]) {
      x.fm.assign(count, x_.window_weight_sum);
    } else {
      convolve(&x.m[x0], x_.window_weight, count, x.fm);
    }
    for (std::size_t i = 0; i < count; ++i)
      out[i] = x.m[x0 + h_ + i] == 0.0 ? static_cast<double>(s_[f0 + i].*field) : x.fe[i] / x.fm[i];
  }

  // One point's channel c (copied index l, kernel half-width k).
  double smooth_channel_point(std::size_t c, std::size_t l, std::size_t k) const {
    const ChannelScratch& x = x_.channel[c];
    if (!any_[c] || x.m[l] == 0.0) return static_cast<double>(s_[g0_ + l].*kAltitudeChannels[c]);
    double e = 0.0, we = 0.0;
    for (std::size_t j = l - k; j <= l + k; ++j) {
      const double wj = x_.weight[j > l ? j - l : l - j];
      e += wj * x.e[j];
      we += wj * x.m[j];
    }
    return e / we;
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
    for (auto& v : r.channel) v.resize(len);
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
      for (std::size_t c = 0; c < kChannels; ++c) smooth_channel_full(c, f0, count, x0, &r.channel[c][o0]);
    }
    // The others: the stretch's end points stay, truncated kernels one by one.
    for (std::size_t i = start; i < end; ++i) {
      if (i >= f0 && i < f1) continue;
      const std::size_t o = i - start;
      if (i == 0 || i + 1 == n_) {
        r.lat[o] = s_[i].lat;
        r.lon[o] = s_[i].lon;
        r.ele[o] = s_[i].ele;
        for (std::size_t c = 0; c < kChannels; ++c) r.channel[c][o] = static_cast<double>(s_[i].*kAltitudeChannels[c]);
      } else {
        const std::size_t k = std::min({h_, i, n_ - 1 - i});
        smooth_point(i - g0_, k, r.lat[o], r.lon[o], r.ele[o]);
        if (!s_[i].has_ele()) r.ele[o] = s_[i].ele;
        for (std::size_t c = 0; c < kChannels; ++c) r.channel[c][o] = smooth_channel_point(c, i - g0_, k);
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
    glm::dvec3 mean{};
    const double iw = x_.inv_weight_sum[k];
    for (std::size_t j = l - k; j <= l + k; ++j) {
      if (!x_.has_ecef[j]) {
        x_.ecef[j] = geo::ecef_from_geodetic(x_.lat[j], x_.lon[j], 0.0);
        x_.has_ecef[j] = 1;
      }
      const double wj = x_.weight[j > l ? j - l : l - j] * iw;
      mean.x += wj * x_.ecef[j].x;
      mean.y += wj * x_.ecef[j].y;
      mean.z += wj * x_.ecef[j].z;
    }
    const geo::Geodetic g = geo::geodetic_from_ecef(mean);
    lat = g.lat_deg;
    lon = g.lon_deg;
  }

  void write_back(const SmoothScratch::Results& r) {
    for (std::size_t o = 0; o < r.lat.size(); ++o) {
      TrackPoint& p = s_[r.first + o];
      p.lat = r.lat[o];
      p.lon = r.lon[o];
      p.ele = r.ele[o];
      for (std::size_t c = 0; c < kChannels; ++c) p.*kAltitudeChannels[c] = static_cast<float>(r.channel[c][o]);
    }
  }

  TrackPoint* s_;
  std::size_t n_, h_;
  std::size_t block_;  // at least h_: a block's window never reaches back beyond the previous block
  SmoothScratch& x_;
  std::size_t g0_ = 0;                              // stretch index of the first copied point
  bool all_ele_ = true;                             // every copied point has an elevation
  bool any_[kChannels] = {}, all_[kChannels] = {};  // some, every copied point has channel c
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

}  // namespace

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

}  // namespace trailray::track::detail
