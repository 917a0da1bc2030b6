#include "track/clean.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geo/geodesic.hpp"
#include "geo/local_frame.hpp"

namespace trailray::track {
namespace {

bool valid_coordinates(const TrackPoint& p) {
  return std::isfinite(p.lat) && std::isfinite(p.lon) && std::abs(p.lat) <= 90.0 &&
         std::abs(p.lon) <= 180.0;
}

// Steps 1 and 2: invalid coordinates, non-finite values, non-increasing timestamps.
std::vector<TrackPoint> drop_invalid_and_unordered(const std::vector<TrackPoint>& in, CleanReport& report) {
  std::vector<TrackPoint> out;
  out.reserve(in.size());
  double last_time = kMissing;  // the last kept timestamp of this segment
  for (TrackPoint p : in) {
    if (!valid_coordinates(p)) {
      ++report.invalid_coordinates;
      continue;
    }
    const bool repaired = std::isinf(p.ele) || std::isinf(p.time);
    if (std::isinf(p.ele)) p.ele = kMissing;
    if (std::isinf(p.time)) p.time = kMissing;
    if (p.has_time()) {
      if (!std::isnan(last_time) && !(p.time > last_time)) {
        ++report.non_increasing_time;
        continue;
      }
      last_time = p.time;
    }
    if (repaired) ++report.invalid_values;
    out.push_back(p);
  }
  return out;
}

// Step 3: minimum distance between consecutive kept points; first and last points stay.
std::vector<TrackPoint> enforce_min_distance(const std::vector<TrackPoint>& in, double min_distance_m,
                                             CleanReport& report) {
  if (!(min_distance_m > 0.0) || in.size() < 2) return in;
  std::vector<TrackPoint> out;
  out.reserve(in.size());
  out.push_back(in.front());
  for (std::size_t i = 1; i < in.size(); ++i) {
    const TrackPoint& p = in[i];
    const TrackPoint& prev = out.back();
    if (geo::geodesic_distance_m(prev.lat, prev.lon, p.lat, p.lon) >= min_distance_m) {
      out.push_back(p);
    } else if (i + 1 < in.size()) {
      ++report.too_close;
    } else if (out.size() >= 2) {
      out.back() = p;  // the last point replaces the previous kept one
      ++report.too_close;
    } else {
      out.push_back(p);  // only the first point before it: keep both
    }
  }
  return out;
}

// Step 4: Gaussian smoothing with a symmetric, renormalised kernel.
void smooth_gaussian(std::vector<TrackPoint>& pts, int half_width, double sigma) {
  const std::size_t n = pts.size();
  if (n < 3 || half_width <= 0 || !(sigma > 0.0) || !std::isfinite(sigma)) return;
  const std::size_t half = static_cast<std::size_t>(half_width);

  std::vector<double> weight(half + 1);
  for (std::size_t j = 0; j <= half; ++j) {
    const double x = static_cast<double>(j);
    weight[j] = std::exp(-x * x / (2.0 * sigma * sigma));
  }

  const TrackPoint& first = pts.front();
  const double h0 = first.has_ele() ? first.ele : 0.0;
  const geo::LocalFrame frame(first.lat, first.lon, h0);
  std::vector<geo::Enu> enu(n);
  for (std::size_t i = 0; i < n; ++i) enu[i] = frame.to_local(pts[i].lat, pts[i].lon, h0);
  std::vector<double> ele(n);
  for (std::size_t i = 0; i < n; ++i) ele[i] = pts[i].ele;

  for (std::size_t i = 1; i + 1 < n; ++i) {
    const std::size_t k = std::min({half, i, n - 1 - i});
    geo::Enu sum;
    double wsum = 0.0, ele_sum = 0.0, ele_wsum = 0.0;
    for (std::size_t j = i - k; j <= i + k; ++j) {
      const double w = weight[j > i ? j - i : i - j];
      sum.east += w * enu[j].east;
      sum.north += w * enu[j].north;
      sum.up += w * enu[j].up;
      wsum += w;
      if (!std::isnan(ele[j])) {
        ele_sum += w * ele[j];
        ele_wsum += w;
      }
    }
    const geo::Enu mean{sum.east / wsum, sum.north / wsum, sum.up / wsum};
    double h = 0.0;
    frame.to_geodetic(mean, pts[i].lat, pts[i].lon, h);
    if (pts[i].has_ele()) pts[i].ele = ele_sum / ele_wsum;  // ele_wsum includes the point itself
  }
}

}  // namespace

Segment clean_segment(const Segment& segment, const CleanOptions& options, CleanReport& report) {
  Segment out;
  out.points = drop_invalid_and_unordered(segment.points, report);
  out.points = enforce_min_distance(out.points, options.min_distance_m, report);
  if (options.smooth) smooth_gaussian(out.points, options.smooth_half_width, options.smooth_sigma);
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
