#include "render/passes/track_lod.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace trailray::render {
namespace {

// A point's colour kind: on the scale, no value, a category (track_common.glsl's thresholds).
constexpr float kCategoryBelow = -1.0e29f;
std::uint8_t kind_of(float value) {
  if (std::isnan(value)) return 1;
  return value < kCategoryBelow ? 2 : 0;
}

struct Deviation {
  double position_m = 0.0, value = 0.0;
};

// How far point p lies from the capsule a-b: its distance from the axis, and its value's from the
// value interpolated at its place along the axis (as the shader colours the capsule).
struct Measure {
  const std::vector<glm::dvec3>& points;
  const std::vector<float>& values;
  const std::vector<std::uint8_t>& kinds;

  Deviation operator()(std::int32_t a, std::int32_t b, std::int32_t p) const {
    const glm::dvec3& pa = points[static_cast<std::size_t>(a)];
    const glm::dvec3 ab = points[static_cast<std::size_t>(b)] - pa;
    const glm::dvec3 ap = points[static_cast<std::size_t>(p)] - pa;
    const double length2 = glm::dot(ab, ab);
    const double s = length2 > 0.0 ? std::clamp(glm::dot(ap, ab) / length2, 0.0, 1.0) : 0.0;
    Deviation d;
    d.position_m = glm::length(ap - ab * s);
    if (!values.empty() && kinds[static_cast<std::size_t>(p)] == 0) {
      const double va = values[static_cast<std::size_t>(a)], vb = values[static_cast<std::size_t>(b)];
      d.value = std::abs(static_cast<double>(values[static_cast<std::size_t>(p)]) - (va + (vb - va) * s));
    }
    return d;
  }
};

// Douglas-Peucker over `in` (point indices, in order) between each pair of consecutive forced
// positions: a point is kept where the capsule between the kept points around it would be more
// than `tolerance_m` from it, or its value more than `value_tolerance` from the capsule's.
std::vector<std::int32_t> simplify(const std::vector<std::int32_t>& in, const std::vector<std::uint8_t>& forced,
                                   const Measure& measure, double tolerance_m, double value_tolerance) {
  std::vector<std::uint8_t> keep(in.size(), 0);
  keep.front() = keep.back() = 1;
  for (std::size_t k = 1; k + 1 < in.size(); ++k) keep[k] = forced[static_cast<std::size_t>(in[k])];
  std::vector<std::pair<std::size_t, std::size_t>> stack;
  std::size_t piece_start = 0;
  for (std::size_t k = 1; k < in.size(); ++k) {
    if (keep[k] == 0) continue;
    stack.emplace_back(piece_start, k);
    piece_start = k;
    while (!stack.empty()) {
      const auto [a, b] = stack.back();
      stack.pop_back();
      double worst = 1.0;
      std::size_t split = 0;
      for (std::size_t m = a + 1; m < b; ++m) {
        const Deviation d = measure(in[a], in[b], in[m]);
        const double score =
            std::max(d.position_m / tolerance_m, value_tolerance > 0.0 ? d.value / value_tolerance : 0.0);
        if (score > worst) worst = score, split = m;
      }
      if (split == 0) continue;
      keep[split] = 1;
      stack.emplace_back(a, split);
      stack.emplace_back(split, b);
    }
  }
  std::vector<std::int32_t> out;
  for (std::size_t k = 0; k < in.size(); ++k)
    if (keep[k] != 0) out.push_back(in[k]);
  return out;
}

// The largest deviation of any point between consecutive kept points from their capsule.
Deviation largest_deviation(const std::vector<std::int32_t>& kept, const Measure& measure) {
  Deviation worst;
  for (std::size_t k = 0; k + 1 < kept.size(); ++k)
    for (std::int32_t p = kept[k] + 1; p < kept[k + 1]; ++p) {
      const Deviation d = measure(kept[k], kept[k + 1], p);
      worst.position_m = std::max(worst.position_m, d.position_m);
      worst.value = std::max(worst.value, d.value);
    }
  return worst;
}

// A tolerance to start from: a quarter of the median distance between consecutive points (a
// level any coarser than the points themselves), never under a millimetre.
double start_tolerance(const std::vector<glm::dvec3>& points, const std::vector<TrackLod::Chunk>& chunks) {
  std::vector<double> steps;
  for (const TrackLod::Chunk& c : chunks)
    for (std::int32_t i = c.first; i < c.last && steps.size() < 100000; i += 1 + (c.last - c.first) / 64)
      steps.push_back(glm::length(points[static_cast<std::size_t>(i + 1)] - points[static_cast<std::size_t>(i)]));
  if (steps.empty()) return 1.0e-3;
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  return std::max(0.25 * steps[steps.size() / 2], 1.0e-3);
}

}  // namespace

TrackLod::TrackLod(const std::vector<glm::dvec3>& points, const std::vector<float>& values,
                   const std::vector<Segment>& segments) {
  std::vector<std::uint8_t> kinds(points.size(), 0);
  double value_lo = std::numeric_limits<double>::max(), value_hi = std::numeric_limits<double>::lowest();
  for (std::size_t i = 0; i < values.size(); ++i) {
    kinds[i] = kind_of(values[i]);
    if (kinds[i] == 0)
      value_lo = std::min<double>(value_lo, values[i]), value_hi = std::max<double>(value_hi, values[i]);
  }
  const double value_tolerance = value_hi > value_lo ? kBuildValueFraction * (value_hi - value_lo) : 0.0;

  // Chunks, and the points every level keeps: both sides of a change of colour kind.
  std::vector<std::uint8_t> forced(points.size(), 0);
  chunked_.assign(segments.size(), 0);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const Segment& segment = segments[s];
    if (segment.count < 3) continue;
    chunked_[s] = 1;
    const std::int32_t last = segment.first + segment.count - 1;
    for (std::int32_t i = segment.first + 1; i <= last; ++i)
      if (kinds[static_cast<std::size_t>(i)] != kinds[static_cast<std::size_t>(i - 1)])
        forced[static_cast<std::size_t>(i)] = forced[static_cast<std::size_t>(i - 1)] = 1;
    for (std::int32_t first = segment.first; first < last; first += kChunkPoints) {
      Chunk chunk;
      chunk.segment = static_cast<std::int32_t>(s);
      chunk.first = first;
      chunk.last = std::min(first + kChunkPoints, last);
      glm::dvec3 lo = points[static_cast<std::size_t>(first)], hi = lo;
      for (std::int32_t i = chunk.first; i <= chunk.last; ++i) {
        lo = glm::min(lo, points[static_cast<std::size_t>(i)]);
        hi = glm::max(hi, points[static_cast<std::size_t>(i)]);
      }
      chunk.centre = 0.5 * (lo + hi);
      for (std::int32_t i = chunk.first; i <= chunk.last; ++i)
        chunk.radius = std::max(chunk.radius, glm::length(points[static_cast<std::size_t>(i)] - chunk.centre));
      chunks_.push_back(chunk);
    }
  }
  if (chunks_.empty()) return;

  // The fewest points a level can keep: each chunk's ends and the forced points inside.
  std::size_t fewest = 0;
  double largest_radius = 0.0;
  for (const Chunk& c : chunks_) {
    fewest += 2;
    for (std::int32_t i = c.first + 1; i < c.last; ++i) fewest += forced[static_cast<std::size_t>(i)];
    largest_radius = std::max(largest_radius, c.radius);
  }

  const Measure measure{points, values, kinds};
  std::vector<std::vector<std::int32_t>> previous(chunks_.size());
  std::size_t previous_count = 0;
  for (std::size_t c = 0; c < chunks_.size(); ++c) {
    for (std::int32_t i = chunks_[c].first; i <= chunks_[c].last; ++i) previous[c].push_back(i);
    previous_count += previous[c].size();
  }
  // Tolerances grow by sqrt 2 until a level keeps at most half of the one below (a quarter, for a
  // random walk), up to the largest chunk's size, where only the fewest points are left.
  for (double tolerance = start_tolerance(points, chunks_);
       levels_.size() < static_cast<std::size_t>(kMaxLevels) && previous_count > fewest &&
       tolerance < 4.0 * largest_radius + 1.0;
       tolerance *= std::sqrt(2.0)) {
    std::vector<std::vector<std::int32_t>> lists(chunks_.size());
    std::size_t count = 0;
    for (std::size_t c = 0; c < chunks_.size(); ++c) {
      lists[c] = simplify(previous[c], forced, measure, tolerance, value_tolerance);
      count += lists[c].size();
    }
    if (2 * count > previous_count && count > fewest) continue;
    Level level;
    level.tolerance_m = tolerance;
    level.base = static_cast<std::int32_t>(indices_.size());
    for (std::size_t c = 0; c < chunks_.size(); ++c) {
      const Deviation worst = largest_deviation(lists[c], measure);
      ChunkLevel cl;
      cl.list_first = static_cast<std::int32_t>(indices_.size()) - level.base;
      cl.kept = static_cast<std::int32_t>(lists[c].size());
      cl.position_error_m = static_cast<float>(worst.position_m);
      cl.value_error = static_cast<float>(worst.value);
      level.chunks.push_back(cl);
      // A boundary point once: the next chunk of the same segment starts with it.
      const bool shared = c + 1 < chunks_.size() && chunks_[c + 1].segment == chunks_[c].segment;
      indices_.insert(indices_.end(), lists[c].begin(), lists[c].end() - (shared ? 1 : 0));
    }
    level.size = static_cast<std::int32_t>(indices_.size()) - level.base;
    levels_.push_back(std::move(level));
    previous = std::move(lists);
    previous_count = count;
  }
}

int TrackLod::level_for(std::size_t chunk, const View& view) const {
  const Chunk& c = chunks_[chunk];
  const glm::dvec3 to_centre = c.centre - view.eye;
  const double centre_depth = glm::dot(to_centre, view.forward);
  const double nearest_depth = centre_depth - c.radius;
  if (nearest_depth <= 0.0 || view.pixel_angle <= 0.0) return 0;
  // An error of e metres at depth z spans e / (z * pixel angle) pixels across the view axis; off
  // it, its component along the axis moves the image too, by up to sqrt(1 + t^2) times, t the
  // tangent of the angle from the axis (at most the picture's corner's, for what shows).
  const double off_axis = glm::length(to_centre - view.forward * centre_depth) + c.radius;
  const double tangent = std::min(off_axis / nearest_depth, view.corner_tangent);
  const double allowed_m = kMaxErrorPx * view.pixel_angle * nearest_depth / std::sqrt(1.0 + tangent * tangent);
  const double allowed_value = kMaxValueErrorFraction * view.value_range;
  for (int l = static_cast<int>(levels_.size()); l >= 1; --l) {
    const ChunkLevel& cl = levels_[static_cast<std::size_t>(l - 1)].chunks[chunk];
    if (cl.position_error_m <= allowed_m && (!view.by_value || cl.value_error <= allowed_value)) return l;
  }
  return 0;
}

std::int32_t TrackLod::second_point(std::size_t chunk, int level) const {
  if (level == 0) return chunks_[chunk].first + 1;
  const Level& l = levels_[static_cast<std::size_t>(level - 1)];
  return indices_[static_cast<std::size_t>(l.base + l.chunks[chunk].list_first + 1)];
}

std::int32_t TrackLod::second_last_point(std::size_t chunk, int level) const {
  if (level == 0) return chunks_[chunk].last - 1;
  const Level& l = levels_[static_cast<std::size_t>(level - 1)];
  const ChunkLevel& cl = l.chunks[chunk];
  return indices_[static_cast<std::size_t>(l.base + cl.list_first + cl.kept - 2)];
}

std::vector<TrackLod::Run> TrackLod::plan(const View& view) const {
  std::vector<int> level(chunks_.size());
  for (std::size_t c = 0; c < chunks_.size(); ++c) level[c] = level_for(c, view);
  const auto same_segment = [&](std::size_t a, std::size_t b) { return chunks_[a].segment == chunks_[b].segment; };
  std::vector<Run> runs;
  for (std::size_t a = 0; a < chunks_.size();) {
    std::size_t b = a;
    while (b + 1 < chunks_.size() && same_segment(b + 1, a) && level[b + 1] == level[a]) ++b;
    Run run;
    run.segment = chunks_[a].segment;
    run.level = level[a];
    if (run.level == 0) {
      run.first = chunks_[a].first;
      run.last = chunks_[b].last;
    } else {
      const Level& l = levels_[static_cast<std::size_t>(run.level - 1)];
      run.list_base = l.base;
      run.first = l.chunks[a].list_first;
      run.last = l.chunks[b].list_first + l.chunks[b].kept - 1;
    }
    if (a > 0 && same_segment(a - 1, a)) run.before = second_last_point(a - 1, level[a - 1]);
    if (b + 1 < chunks_.size() && same_segment(b + 1, a)) run.after = second_point(b + 1, level[b + 1]);
    runs.push_back(run);
    a = b + 1;
  }
  return runs;
}

}  // namespace trailray::render
