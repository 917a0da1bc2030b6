#include "track/flight/flight_samples.hpp"

#include <algorithm>
#include <cmath>

namespace trailray::track::flight::detail {

Samples collect_samples(const Track& track, double max_gap_s) {
  Samples out;
  out.list.reserve(track.point_count());
  std::size_t index = 0;
  double last_alt = kMissing;
  std::size_t first_without_alt = 0;  // samples before the first elevation take it afterwards
  for (const Segment& seg : track.segments) {
    bool new_segment = true;
    for (const TrackPoint& p : seg.points) {
      const std::size_t point = index++;
      if (!p.has_time() || !std::isfinite(p.time) || !std::isfinite(p.lat) || !std::isfinite(p.lon) ||
          std::fabs(p.lat) > 90.0 || std::fabs(p.lon) > 180.0)
        continue;
      if (!out.list.empty() && !(p.time > out.list.back().time)) continue;  // repeated or backwards time
      Sample s;
      s.time = p.time;
      s.lat = p.lat;
      s.lon = p.lon;
      s.point = point;
      s.gap_before = !out.list.empty() && new_segment;
      new_segment = false;
      if (p.has_ele() && std::isfinite(p.ele)) {
        if (!out.has_altitude)
          for (std::size_t k = first_without_alt; k < out.list.size(); ++k) out.list[k].alt = p.ele;
        out.has_altitude = true;
        last_alt = p.ele;
      }
      s.alt = last_alt;
      out.list.push_back(s);
    }
  }
  // A logger that records every 20 s is slow, not gappy: a gap is a step over max_gap_s and
  // over three times the median step.
  std::vector<double> steps;
  steps.reserve(out.list.size());
  for (std::size_t k = 1; k < out.list.size(); ++k) steps.push_back(out.list[k].time - out.list[k - 1].time);
  double gap = max_gap_s;
  if (!steps.empty()) {
    auto mid = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), mid, steps.end());
    gap = std::max(gap, 3.0 * *mid);
  }
  for (std::size_t k = 1; k < out.list.size(); ++k)
    if (out.list[k].time - out.list[k - 1].time > gap) out.list[k].gap_before = true;
  return out;
}

Place place_of(const Sample& s) {
  Place p;
  p.time = s.time;
  p.lat = s.lat;
  p.lon = s.lon;
  p.alt = s.alt;
  p.point = s.point;
  return p;
}

}  // namespace trailray::track::flight::detail
