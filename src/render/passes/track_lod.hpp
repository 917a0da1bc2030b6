#pragma once
// Level of detail for the track pass's capsules (track_pass.hpp), GL-free: built once per
// TrackBuffer upload, chosen per frame.
//
// Far away, hundreds of a track's points fall in one pixel and their capsules cost a CPU
// rasterizer (and any GPU) for nothing. A hierarchy of coarser polylines replaces them: each
// level keeps a subset of the points (Douglas-Peucker on the previous level's points, at a
// tolerance doubled until it keeps at most half of them), so its capsules join kept points and
// every dropped point lies within the level's recorded error of the capsule that replaces it.
//
// Chunks: each segment's points are cut into chunks of kChunkPoints capsules, whose first and
// last points every level keeps (so chunks at different levels still meet at a shared point),
// with a bounding sphere each. Per frame each chunk takes the coarsest level whose position error
// projects to at most kMaxErrorPx pixels at the chunk's nearest depth (and, coloured by value,
// whose value error stays under kMaxValueErrorFraction of the colour scale), so the capsules
// drawn follow the pixels the track covers, not the points in the file; a chunk near the
// camera is drawn at full detail, point for point.
//
// Values: a capsule's colour is interpolated between its two points (track_trace.glsl), so a
// dropped point's value error is its distance from that line at its place along the capsule.
// Where a point has no value or a category (gliding) instead, the colour is not on the scale:
// every level keeps the points on both sides of each change between those kinds.
//
// Memory: the levels' index lists, 4 bytes per kept point; each level keeps at most half the
// points of the one below, so all of them take at most 4 bytes per point (about 2 on a 1M walk).

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace trailray::render {

class TrackLod {
 public:
  // Capsules per chunk (a chunk has one point more): small enough that a chunk's bounding
  // sphere is close to its points (an oblique view picks coarser levels for its far chunks; 256
  // drew 2.4 times fewer capsules than 1024 on a real flight), large enough that a million
  // points plan in 4000 steps.
  static constexpr std::int32_t kChunkPoints = 256;
  static constexpr double kMaxErrorPx = 0.5;                    // a dropped point's distance from its capsule
  static constexpr double kMaxValueErrorFraction = 1.0 / 32.0;  // of the colour scale's range
  // Values are simplified to this fraction of their span over the whole track: finer than the
  // draw's bound, so a colour scale a little narrower than the values still finds coarse levels.
  static constexpr double kBuildValueFraction = 1.0 / 64.0;
  static constexpr int kMaxLevels = 24;

  struct Segment {
    std::int32_t first = 0, count = 0;  // points [first, first + count) of `points`
  };
  struct Chunk {
    std::int32_t segment = 0;          // index into the segments given
    std::int32_t first = 0, last = 0;  // its first and last point (inclusive; shared with neighbours)
    glm::dvec3 centre{0.0};            // bounding sphere of its points (ECEF)
    double radius = 0.0;
  };
  struct ChunkLevel {
    std::int32_t list_first = 0;    // position of the chunk's first point in the level's list
    std::int32_t kept = 0;          // points kept (the last one is the next chunk's first)
    float position_error_m = 0.0f;  // the largest distance of a dropped point from its capsule's axis
    float value_error = 0.0f;       // the largest deviation of a dropped point's value from the capsule's
  };
  struct Level {
    double tolerance_m = 0.0;        // the tolerance it was simplified at
    std::int32_t base = 0;           // where its list starts in indices()
    std::int32_t size = 0;           // its list's length
    std::vector<ChunkLevel> chunks;  // one per chunk (chunks())
  };

  TrackLod() = default;
  // `values`: one per point or empty; NaN no value, below -1e29 a category (track::kCategoryValue).
  // Segments of fewer than 3 points get no chunks (nothing to merge): they are always drawn whole.
  TrackLod(const std::vector<glm::dvec3>& points, const std::vector<float>& values,
           const std::vector<Segment>& segments);

  const std::vector<Chunk>& chunks() const { return chunks_; }
  // Coarser levels only: level 0, full detail, is every point and has no list.
  const std::vector<Level>& levels() const { return levels_; }
  // Every level's list of kept point indices (into `points`), one level after the other; within
  // a level, each segment's chunks one after the other, a boundary point once.
  const std::vector<std::int32_t>& indices() const { return indices_; }

  // What a frame needs to choose levels.
  struct View {
    glm::dvec3 eye{0.0}, forward{0.0, 0.0, -1.0};  // ECEF; forward unit
    double pixel_angle = 0.0;                      // a pixel's size per metre of depth on the view axis
    double corner_tangent = 0.0;                   // tangent of the angle between the view axis and a corner
    bool by_value = false;
    double value_range = 0.0;  // the colour scale's max - min
  };
  // A stretch of consecutive chunks of one segment drawn at one level: the points at list
  // positions first..last of that level (level 0: point indices), and the points just before and
  // after the stretch (-1: none) that its end joints are built with.
  struct Run {
    std::int32_t segment = 0;
    int level = 0;                // 0: full detail
    std::int32_t list_base = -1;  // the level's base in indices() (-1: level 0)
    std::int32_t first = 0, last = 0;
    std::int32_t before = -1, after = -1;
  };
  // The level of each chunk for a view (0 full detail .. levels().size()).
  int level_for(std::size_t chunk, const View& view) const;
  // The runs of every chunked segment, in segment order.
  std::vector<Run> plan(const View& view) const;
  // The point before the chunk's last one and after its first one at a level.
  std::int32_t second_point(std::size_t chunk, int level) const;
  std::int32_t second_last_point(std::size_t chunk, int level) const;
  // Whether a segment (index into the segments given) is drawn through the chunks.
  bool chunked(std::size_t segment) const { return segment < chunked_.size() && chunked_[segment] != 0; }

 private:
  std::vector<Chunk> chunks_;
  std::vector<Level> levels_;
  std::vector<std::int32_t> indices_;
  std::vector<std::uint8_t> chunked_;
};

}  // namespace trailray::render
