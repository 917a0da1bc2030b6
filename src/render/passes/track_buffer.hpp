#pragma once
// A track on the GPU (DESIGN.md "The frame", step 4): its points live only in textures, no
// vertex buffer. The track pass builds each segment's quad from gl_VertexID and fetches the
// points it needs.
//
// Layout, 16 bytes per point plus 1/16 byte per point of block origins (for recorded tracks):
//   points    RGBA32F, 2D (at most 2048 wide (texel_table.hpp), as narrow as keeps the row count): texel i is
//             point i of the track (segments one after the other): xyz = float offset from the
//             point's block origin (ECEF metres), w = the colour attribute (NaN: no value).
//   blocks    RGBA32F, one texel per block (up to 256 points of a segment): "block origin minus eye", rewritten
//             each frame by set_eye() from the origins kept in double on the CPU. A point's
//             camera-relative position is its offset plus its block's texel: no large number
//             ever reaches the GPU, so a track 300 km from anything stays exact to the
//             millimetre next to the camera (DESIGN.md precision rule).
//   drops     R32F, optional (curtains): metres from the point down to the ground.
//   lod       R32I: the level-of-detail hierarchy's index lists (track_lod.hpp), about 2 bytes
//             per point (at most 4); one texel when the track has nothing to merge.
// A texture wider than 2048 is not guaranteed by WebGL2; the 2D layout holds a million points
// in 489 rows.
//
// Blocks: each segment's points are cut into blocks from the segment's own first point, so a
// jump between segments (tracks of one file far apart) costs nothing. Block size, per segment:
// kMaxBlockPoints (256), halved until every point of the segment lies within kMaxBlockReachM of
// its block's origin (its first point), so that a float offset never loses more than about a
// millimetre. A track recorded every second keeps 256; only a segment with sparse points (a
// straight 300 km segment, a GPS jump) gets small blocks, down to a block per point, and the
// other segments of the buffer keep theirs.
//
// Many tracks, one buffer: a season of 10,000 tracks is one buffer whose segments name the track
// they belong to (Range::track), so the track pass draws all of them in a few draws and takes
// each track's colour and visibility from a small table (TrackDraw::track_styles).
//
// Segments are never bridged: the shader clamps the neighbour lookups (x0, x3) to the segment, so
// nothing is read past a segment's points.

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "render/gl/gl_objects.hpp"
#include "render/passes/track_lod.hpp"
#include "scene/tracks/track_geometry.hpp"

namespace trailray::render {

class TrackBuffer {
 public:
  static constexpr int kMaxBlockPoints = 256;
  static constexpr double kMaxBlockReachM = 16000.0;  // float spacing there: 1 mm

  struct Range {
    std::int32_t first = 0;        // index of the segment's first point in the points texture
    std::int32_t count = 0;        // its points (a segment of one point is a sphere)
    std::int32_t first_block = 0;  // its first block in the blocks texture: point first + k is
                                   // relative to block first_block + (k >> block_shift)
    std::int32_t block_shift = 8;  // log2 of the segment's points per block
    std::int32_t track = 0;        // the track it belongs to (index into the geometries given)
  };

  // Uploads (the GL context must be current). Throws std::invalid_argument when a segment's
  // values or heights are neither empty nor one per point, or a point is not finite; RenderError
  // when GL refuses the textures (more points than the largest texture holds).
  explicit TrackBuffer(const scene::TrackGeometry& geometry);
  // Many tracks in one buffer: track k's segments get Range::track k (empty segments, and so
  // tracks without points, take no range).
  explicit TrackBuffer(std::span<const scene::TrackGeometry* const> tracks);

  std::size_t point_count() const { return point_count_; }
  const std::vector<Range>& segments() const { return segments_; }
  bool has_values() const { return has_values_; }
  bool has_drops() const { return has_drops_; }
  std::size_t track_count() const { return track_count_; }  // the geometries given
  int texture_width() const { return texture_width_; }
  const Texture& points() const { return points_; }
  const Texture& blocks() const { return blocks_; }
  const Texture& drops() const { return drops_; }  // 0 without curtain heights
  // The level-of-detail hierarchy (its chunks index segments()) and its lists on the GPU.
  const TrackLod& lod() const { return lod_; }
  const Texture& lod_indices() const { return lod_indices_; }

  // The bytes of GPU memory the textures take (the figure the issue asks about).
  std::size_t gpu_bytes() const;

  // A sphere around every point (ECEF), for culling and the shadow cascades' may_hold.
  glm::dvec3 bounding_centre_ecef() const { return centre_; }
  double bounding_radius_m() const { return radius_; }
  // The same per track (index: Range::track; radius 0 around the origin for a track without points).
  struct Sphere {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
  };
  const std::vector<Sphere>& track_spheres() const { return track_spheres_; }

  // Rewrites the block texture for an eye (the camera's position: the passes work in
  // camera-relative ECEF). Cheap (a texel per block); a no-op when the eye is unchanged.
  void set_eye(const glm::dvec3& eye_ecef);

 private:
  void make_blocks(const std::vector<glm::dvec3>& all);
  void upload(std::span<const scene::TrackGeometry* const> tracks);

  std::size_t point_count_ = 0;
  std::size_t track_count_ = 0;
  std::vector<Range> segments_;
  bool has_values_ = false, has_drops_ = false;
  int texture_width_ = 1;
  std::vector<glm::dvec3> block_origins_;
  glm::dvec3 eye_{0.0};
  bool eye_set_ = false;
  glm::dvec3 centre_{0.0};
  double radius_ = 0.0;
  std::vector<Sphere> track_spheres_;
  TrackLod lod_;
  Texture points_, blocks_, drops_, lod_indices_;
  int block_texture_width_ = 1;
  int lod_texture_width_ = 1;
};

}  // namespace trailray::render
