#include "render/passes/track_pieces.hpp"

#include <algorithm>

namespace trailray::render {
namespace {

// The class of a piece of `capsules` (a power of two, 1 .. kPieceCapsules): log2.
int class_of(std::int32_t capsules) {
  int k = 0;
  while ((std::int32_t{1} << k) < capsules) ++k;
  return k;
}

// The pieces sorted into their classes.
CapsulePieces sorted(const std::vector<CapsulePiece>& unsorted) {
  CapsulePieces out;
  std::array<std::int32_t, CapsulePieces::kClasses> counts{};
  for (const CapsulePiece& p : unsorted) {
    ++counts[static_cast<std::size_t>(class_of(p.capsules))];
    out.capsule_count += static_cast<std::size_t>(p.capsules);
  }
  std::int32_t first = 0;
  for (int k = 0; k < CapsulePieces::kClasses; ++k) {
    CapsulePieces::Class& c = out.classes[static_cast<std::size_t>(k)];
    c.first = first;
    c.count = 0;
    c.capsules = std::int32_t{1} << k;
    first += counts[static_cast<std::size_t>(k)];
  }
  out.pieces.resize(unsorted.size());
  for (const CapsulePiece& p : unsorted) {
    CapsulePieces::Class& c = out.classes[static_cast<std::size_t>(class_of(p.capsules))];
    out.pieces[static_cast<std::size_t>(c.first + c.count++)] = p;
  }
  return out;
}

}  // namespace

std::vector<std::int32_t> CapsulePieces::texels() const {
  std::vector<std::int32_t> out;
  out.reserve(pieces.size() * 12);
  for (const CapsulePiece& p : pieces)
    out.insert(out.end(), {p.list_base, p.run_first, p.run_last, p.before, p.after, p.start, p.capsules, p.track,
                           p.segment_first, p.segment_last, p.first_block, p.block_shift});
  return out;
}

CapsulePieces plan_capsule_pieces(const TrackBuffer& buffer, CapsuleShape::Capsules mode,
                                  const std::optional<TrackLod::View>& lod,
                                  const std::function<bool(std::int32_t track)>& shown) {
  const TrackLod& hierarchy = buffer.lod();
  const bool through_lod = lod.has_value() && mode == CapsuleShape::Capsules::polyline;
  std::vector<TrackLod::Run> runs;
  if (through_lod) runs = hierarchy.plan(*lod);
  std::vector<CapsulePiece> unsorted;
  // `total` capsules from base.start: whole kPieceCapsules, then the rest by its binary digits.
  const auto add = [&](CapsulePiece base, std::int32_t total, std::int32_t points_per_capsule) {
    std::int32_t done = 0;
    for (std::int32_t size = CapsulePieces::kPieceCapsules; size >= 1; size /= 2)
      while (total - done >= size && (size == CapsulePieces::kPieceCapsules || ((total - done) & size) != 0)) {
        CapsulePiece piece = base;
        piece.start = base.start + done * points_per_capsule;
        piece.capsules = size;
        unsorted.push_back(piece);
        done += size;
      }
  };
  std::size_t next_run = 0;
  const auto& segments = buffer.segments();
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const TrackBuffer::Range& range = segments[s];
    const bool chunked = through_lod && hierarchy.chunked(s);
    // The runs are in segment order: skip this segment's (drawn or not) before the next one.
    const std::size_t runs_begin = next_run;
    if (chunked)
      while (next_run < runs.size() && runs[next_run].segment == static_cast<std::int32_t>(s)) ++next_run;
    if (range.count <= 0 || (shown && !shown(range.track))) continue;
    CapsulePiece base;
    base.track = range.track;
    base.segment_first = range.first;
    base.segment_last = range.first + range.count - 1;
    base.first_block = range.first_block;
    base.block_shift = range.block_shift;
    if (chunked) {
      for (std::size_t r = runs_begin; r < next_run; ++r) {
        const TrackLod::Run& run = runs[r];
        CapsulePiece piece = base;
        piece.list_base = run.list_base;
        piece.run_first = run.first;
        piece.run_last = run.last;
        piece.before = run.before;
        piece.after = run.after;
        piece.start = run.first;
        add(piece, run.last - run.first, 1);
      }
      continue;
    }
    CapsulePiece piece = base;
    piece.run_first = base.segment_first;
    piece.run_last = base.segment_last;
    piece.start = base.segment_first;
    const std::int32_t total = mode == CapsuleShape::Capsules::polyline ? std::max(range.count - 1, 1)
                               : mode == CapsuleShape::Capsules::pairs  ? range.count / 2
                                                                        : range.count;
    add(piece, total, mode == CapsuleShape::Capsules::pairs ? 2 : 1);
  }

  return sorted(unsorted);
}

CapsulePieces CapsulePieces::filtered(const std::function<bool(const CapsulePiece&)>& keep) const {
  std::vector<CapsulePiece> kept;
  for (const CapsulePiece& p : pieces)
    if (keep(p)) kept.push_back(p);
  return sorted(kept);
}

}  // namespace trailray::render
