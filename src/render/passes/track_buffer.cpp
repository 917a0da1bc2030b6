#include "render/passes/track_buffer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "render/gl/render_error.hpp"
#include "render/passes/texel_table.hpp"

namespace trailray::render {
namespace {

// Points without a value are stored as this (a NaN might not survive a shader compiler's fast
// math): the shader tests `value < kMissingValueBelow`.
constexpr float kMissingValue = -3.0e38f;

using texel_table::rows_for;
using texel_table::width_for;

Texture upload_rgba32f(std::vector<float>& texels, int width) {
  return texel_table::upload(texels, 4, width, GL_RGBA32F, GL_RGBA, GL_FLOAT);
}

// A sphere around the points: the box's centre and the farthest point from it.
TrackBuffer::Sphere bounding_sphere(std::vector<glm::dvec3>::const_iterator first,
                                    std::vector<glm::dvec3>::const_iterator last) {
  TrackBuffer::Sphere sphere;
  if (first == last) return sphere;
  glm::dvec3 lo = *first, hi = *first;
  for (auto p = first; p != last; ++p) {
    lo = glm::min(lo, *p);
    hi = glm::max(hi, *p);
  }
  sphere.centre = 0.5 * (lo + hi);
  for (auto p = first; p != last; ++p) sphere.radius = std::max(sphere.radius, glm::length(*p - sphere.centre));
  return sphere;
}

// Values and heights one per point (or none), every point finite.
void check_segment(const scene::TrackPolyline& line, std::size_t s) {
  const std::size_t n = line.points_ecef.size();
  if (!line.values.empty() && line.values.size() != n)
    throw std::invalid_argument("track segment " + std::to_string(s) + ": " + std::to_string(line.values.size()) +
                                " values for " + std::to_string(n) + " points");
  if (!line.heights_above_ground_m.empty() && line.heights_above_ground_m.size() != n)
    throw std::invalid_argument("track segment " + std::to_string(s) + ": " +
                                std::to_string(line.heights_above_ground_m.size()) + " heights above ground for " +
                                std::to_string(n) + " points");
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3& p = line.points_ecef[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::invalid_argument("track segment " + std::to_string(s) + " point " + std::to_string(i) +
                                  ": position is not a finite number");
  }
}

}  // namespace

TrackBuffer::TrackBuffer(const scene::TrackGeometry& geometry)
    : TrackBuffer(std::span<const scene::TrackGeometry* const>(std::array{&geometry})) {}

TrackBuffer::TrackBuffer(std::span<const scene::TrackGeometry* const> tracks) : track_count_(tracks.size()) {
  for (std::size_t t = 0; t < tracks.size(); ++t)
    for (std::size_t s = 0; s < tracks[t]->segments.size(); ++s) {
      const scene::TrackPolyline& line = tracks[t]->segments[s];
      check_segment(line, s);
      const std::size_t n = line.points_ecef.size();
      if (n == 0) continue;
      if (point_count_ + n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 8))
        throw RenderError("track: too many points for the GPU layout (" + std::to_string(point_count_ + n) + ")");
      Range range;
      range.first = static_cast<std::int32_t>(point_count_);
      range.count = static_cast<std::int32_t>(n);
      range.track = static_cast<std::int32_t>(t);
      segments_.push_back(range);
      point_count_ += n;
      has_values_ = has_values_ || !line.values.empty();
      has_drops_ = has_drops_ || !line.heights_above_ground_m.empty();
    }
  std::vector<glm::dvec3> all;
  all.reserve(point_count_);
  for (const scene::TrackGeometry* track : tracks)
    for (const scene::TrackPolyline& line : track->segments)
      all.insert(all.end(), line.points_ecef.begin(), line.points_ecef.end());
  make_blocks(all);
  const Sphere all_sphere = bounding_sphere(all.begin(), all.end());
  centre_ = all_sphere.centre;
  radius_ = all_sphere.radius;
  // Each track's: its segments are consecutive in `all`.
  track_spheres_.resize(track_count_);
  for (std::size_t s = 0; s < segments_.size();) {
    std::size_t end = s;
    while (end < segments_.size() && segments_[end].track == segments_[s].track) ++end;
    const auto first = all.begin() + segments_[s].first;
    const auto last = all.begin() + (segments_[end - 1].first + segments_[end - 1].count);
    track_spheres_[static_cast<std::size_t>(segments_[s].track)] = bounding_sphere(first, last);
    s = end;
  }
  std::vector<float> values;
  if (has_values_) {
    values.reserve(point_count_);
    for (const scene::TrackGeometry* track : tracks)
      for (const scene::TrackPolyline& line : track->segments) {
        if (line.values.empty())
          values.insert(values.end(), line.points_ecef.size(), std::numeric_limits<float>::quiet_NaN());
        else
          values.insert(values.end(), line.values.begin(), line.values.end());
      }
  }
  std::vector<TrackLod::Segment> lod_segments;
  for (const Range& range : segments_) lod_segments.push_back({range.first, range.count});
  lod_ = TrackLod(all, values, lod_segments);
  upload(tracks);
}

// Block origins, kept in double: each segment's points in blocks from its own first point (a gap
// between segments, however wide, costs no precision), blocks as large as the points' spread
// within them allows (see the header), segment by segment.
void TrackBuffer::make_blocks(const std::vector<glm::dvec3>& all) {
  const auto blocks_reach = [&](const Range& range, std::int32_t size) {
    for (std::int32_t first = range.first; first < range.first + range.count; first += size)
      for (std::int32_t i = first + 1; i < std::min(range.first + range.count, first + size); ++i)
        if (glm::length(all[static_cast<std::size_t>(i)] - all[static_cast<std::size_t>(first)]) > kMaxBlockReachM)
          return false;
    return true;
  };
  for (Range& range : segments_) {
    range.block_shift = 8;
    while (range.block_shift > 0 && !blocks_reach(range, std::int32_t{1} << range.block_shift)) --range.block_shift;
    const std::int32_t block_size = std::int32_t{1} << range.block_shift;
    range.first_block = static_cast<std::int32_t>(block_origins_.size());
    for (std::int32_t i = range.first; i < range.first + range.count; i += block_size)
      block_origins_.push_back(all[static_cast<std::size_t>(i)]);
  }
}

// The points (offsets from their blocks' origins, with values), the drops and the blocks texture.
void TrackBuffer::upload(std::span<const scene::TrackGeometry* const> tracks) {
  texture_width_ = width_for(point_count_);
  std::vector<float> texels;
  texels.reserve(point_count_ * 4);
  std::vector<float> drops;
  if (has_drops_) drops.reserve(point_count_);
  std::size_t segment = 0;
  for (const scene::TrackGeometry* track : tracks)
    for (const scene::TrackPolyline& line : track->segments) {
      if (line.points_ecef.empty()) continue;
      const Range& range = segments_[segment++];
      const auto first_block = static_cast<std::size_t>(range.first_block);
      for (std::size_t i = 0; i < line.points_ecef.size(); ++i) {
        const glm::dvec3 offset = line.points_ecef[i] - block_origins_[first_block + (i >> range.block_shift)];
        const float value = line.values.empty() || std::isnan(line.values[i]) ? kMissingValue : line.values[i];
        texels.insert(texels.end(), {static_cast<float>(offset.x), static_cast<float>(offset.y),
                                     static_cast<float>(offset.z), value});
        if (has_drops_) {
          const float drop = line.heights_above_ground_m.empty() ? 0.0f : line.heights_above_ground_m[i];
          drops.push_back(std::isfinite(drop) ? std::max(drop, 0.0f) : 0.0f);
        }
      }
    }
  points_ = upload_rgba32f(texels, texture_width_);
  if (has_drops_) drops_ = texel_table::upload(drops, 1, texture_width_, GL_R32F, GL_RED, GL_FLOAT);
  // The hierarchy's lists (at least one texel: the programs' integer sampler always has a texture).
  std::vector<std::int32_t> lists = lod_.indices();
  if (lists.empty()) lists.push_back(0);
  lod_texture_width_ = width_for(lists.size());
  lod_indices_ = texel_table::upload(lists, 1, lod_texture_width_, GL_R32I, GL_RED_INTEGER, GL_INT);
  block_texture_width_ = width_for(block_origins_.size());
  std::vector<float> zeros(std::max<std::size_t>(block_origins_.size(), 1) * 4, 0.0f);
  blocks_ = upload_rgba32f(zeros, block_texture_width_);
}

std::size_t TrackBuffer::gpu_bytes() const {
  const auto rows = [](std::size_t texels, int width) {
    return static_cast<std::size_t>(std::max(1, rows_for(texels, width)));
  };
  std::size_t bytes = rows(point_count_, texture_width_) * texture_width_ * 16;
  bytes += rows(block_origins_.size(), block_texture_width_) * block_texture_width_ * 16;
  if (has_drops_) bytes += rows(point_count_, texture_width_) * texture_width_ * 4;
  bytes += rows(std::max<std::size_t>(lod_.indices().size(), 1), lod_texture_width_) * lod_texture_width_ * 4;
  return bytes;
}

void TrackBuffer::set_eye(const glm::dvec3& eye_ecef) {
  if (eye_set_ && eye_ == eye_ecef) return;
  if (block_origins_.empty()) return;
  eye_ = eye_ecef;
  eye_set_ = true;
  std::vector<float> texels;
  texels.reserve(block_origins_.size() * 4);
  for (const glm::dvec3& origin : block_origins_) {
    const glm::dvec3 offset = origin - eye_ecef;  // in double, rounded once
    texels.insert(texels.end(),
                  {static_cast<float>(offset.x), static_cast<float>(offset.y), static_cast<float>(offset.z), 0.0f});
  }
  const int rows = std::max(1, rows_for(block_origins_.size(), block_texture_width_));
  texels.resize(static_cast<std::size_t>(block_texture_width_) * rows * 4, 0.0f);
  glBindTexture(GL_TEXTURE_2D, blocks_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, block_texture_width_, rows, GL_RGBA, GL_FLOAT, texels.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace trailray::render
