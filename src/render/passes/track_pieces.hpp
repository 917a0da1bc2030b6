#pragma once
// What the track pass draws of a buffer in a frame, as a table the vertex shader reads (built on
// the CPU once per frame, shared by the visible, overlay and shadow draws; no GL calls here).
//
// A piece is a power of two of consecutive capsules (1 .. kPieceCapsules) of one segment at one
// level of detail: a TrackLod::Run, or a whole segment at full detail, cut into pieces by the
// binary digits of its capsule count (200 capsules: 128 + 64 + 8). The pass draws every piece of
// a buffer as an instance of a quad list (gl_InstanceID picks its texels), so a buffer of 10,000
// tracks costs a few draw calls instead of one per segment and run: one instanced draw per size,
// whose pieces all have exactly that many capsules (no vertex runs for nothing).

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "render/passes/capsule_shape.hpp"
#include "render/passes/track_buffer.hpp"
#include "render/passes/track_lod.hpp"

namespace trailray::render {

struct CapsulePiece {
  std::int32_t list_base = -1;                       // the level's list in the LOD texture (-1: full detail)
  std::int32_t run_first = 0, run_last = 0;          // list positions of the run the piece belongs to
  std::int32_t before = -1, after = -1;              // the points joined across the run's ends (-1: none)
  std::int32_t start = 0;                            // list position of the piece's first capsule's first point
  std::int32_t capsules = 0;                         // 1 .. kPieceCapsules
  std::int32_t track = 0;                            // TrackBuffer::Range::track
  std::int32_t segment_first = 0, segment_last = 0;  // the segment's first and last point
  std::int32_t first_block = 0, block_shift = 8;     // its blocks (TrackBuffer::Range)
};

struct CapsulePieces {
  static constexpr std::int32_t kPieceCapsules = 256;
  static constexpr int kClasses = 9;  // pieces of 1, 2, 4, ... 256 capsules
  std::vector<CapsulePiece> pieces;   // class by class
  struct Class {
    std::int32_t first = 0, count = 0;  // its pieces
    std::int32_t capsules = 0;          // quads per instance: each of its pieces' capsules
  };
  std::array<Class, kClasses> classes{};
  std::size_t capsule_count = 0;  // capsules drawn (the pieces' sum)

  // The table as the shader reads it: three RGBA32I texels per piece (track.vert).
  std::vector<std::int32_t> texels() const;
  // The pieces `keep` accepts, classes kept.
  CapsulePieces filtered(const std::function<bool(const CapsulePiece&)>& keep) const;
};

// The pieces of every segment of `buffer` whose track `shown` accepts (empty function: all),
// through the level of detail's runs when `lod` is given (polylines only; other modes are drawn
// whole).
CapsulePieces plan_capsule_pieces(const TrackBuffer& buffer, CapsuleShape::Capsules mode,
                                  const std::optional<TrackLod::View>& lod,
                                  const std::function<bool(std::int32_t track)>& shown = {});

}  // namespace trailray::render
