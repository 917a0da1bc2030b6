// The track pass's per-frame piece table (render/passes/track_pieces.hpp): every capsule of every
// shown track's segments is in exactly one piece, pieces are powers of two sorted into their size
// classes, hidden tracks have none, pins' pairs keep their stride, and through the level of detail
// the pieces are exactly the plan's runs. Also the many-track buffer's layout (track_buffer.hpp).
#include "render/passes/track_pieces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "gl_test_support.hpp"

namespace trailray::render {
namespace {

using test::GlTest;

// A straight line of `count` points, 3 m apart, starting at `origin` (ECEF offsets near Earth's surface).
scene::TrackPolyline line(std::size_t count, const glm::dvec3& origin) {
  scene::TrackPolyline l;
  for (std::size_t i = 0; i < count; ++i)
    l.points_ecef.push_back(origin + glm::dvec3(3.0 * static_cast<double>(i), 0.5 * static_cast<double>(i % 7), 0.0));
  return l;
}

// Per (track, segment first point): the capsule positions the pieces cover, each counted.
std::map<std::pair<std::int32_t, std::int32_t>, std::map<std::int32_t, int>> covered(const CapsulePieces& pieces,
                                                                                     std::int32_t stride) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::map<std::int32_t, int>> out;
  for (const CapsulePiece& p : pieces.pieces)
    for (std::int32_t k = 0; k < p.capsules; ++k) ++out[{p.track, p.segment_first}][p.start + k * stride];
  return out;
}

void expect_sorted_powers_of_two(const CapsulePieces& pieces) {
  std::size_t capsules = 0;
  std::int32_t next = 0;
  for (int k = 0; k < CapsulePieces::kClasses; ++k) {
    const CapsulePieces::Class& c = pieces.classes[static_cast<std::size_t>(k)];
    EXPECT_EQ(c.first, next) << "class " << k;
    EXPECT_EQ(c.capsules, 1 << k);
    for (std::int32_t i = c.first; i < c.first + c.count; ++i)
      EXPECT_EQ(pieces.pieces[static_cast<std::size_t>(i)].capsules, c.capsules) << "piece " << i;
    capsules += static_cast<std::size_t>(c.count) * static_cast<std::size_t>(c.capsules);
    next = c.first + c.count;
  }
  EXPECT_EQ(static_cast<std::size_t>(next), pieces.pieces.size());
  EXPECT_EQ(capsules, pieces.capsule_count);
}

class TrackPiecesTest : public GlTest {
 protected:
  const glm::dvec3 here_{4.3e6, 0.8e6, 4.6e6};
  // Track 0: one segment of 600 points; track 1: two segments (1 point, 2 points); track 2: 257
  // points; track 3: empty.
  std::vector<scene::TrackGeometry> geometries() const {
    std::vector<scene::TrackGeometry> g(4);
    g[0].segments = {line(600, here_)};
    g[1].segments = {line(1, here_ + glm::dvec3(0, 50, 0)), line(2, here_ + glm::dvec3(0, 80, 0))};
    g[2].segments = {line(257, here_ + glm::dvec3(0, 120, 0))};
    return g;
  }
  static std::vector<const scene::TrackGeometry*> pointers(const std::vector<scene::TrackGeometry>& g) {
    std::vector<const scene::TrackGeometry*> out;
    for (const scene::TrackGeometry& t : g) out.push_back(&t);
    return out;
  }
};

TEST_F(TrackPiecesTest, ManyTracksShareOneBufferWhoseSegmentsNameTheirTrack) {
  const std::vector<scene::TrackGeometry> g = geometries();
  const std::vector<const scene::TrackGeometry*> p = pointers(g);
  const TrackBuffer buffer{std::span<const scene::TrackGeometry* const>(p)};
  EXPECT_EQ(buffer.point_count(), 600u + 1u + 2u + 257u);
  EXPECT_EQ(buffer.track_count(), 4u);
  ASSERT_EQ(buffer.segments().size(), 4u);
  const std::vector<std::int32_t> tracks{0, 1, 1, 2};
  std::int32_t first = 0;
  for (std::size_t s = 0; s < 4; ++s) {
    EXPECT_EQ(buffer.segments()[s].track, tracks[s]);
    EXPECT_EQ(buffer.segments()[s].first, first);
    first += buffer.segments()[s].count;
  }
  // Each track's sphere holds its points and not much more (track 0 is 1.8 km long).
  ASSERT_EQ(buffer.track_spheres().size(), 4u);
  EXPECT_NEAR(buffer.track_spheres()[0].radius, 0.5 * 3.0 * 599, 5.0);
  EXPECT_LT(buffer.track_spheres()[1].radius, 20.0);
  EXPECT_EQ(buffer.track_spheres()[3].radius, 0.0);  // no points
}

TEST_F(TrackPiecesTest, EveryCapsuleOfTheShownTracksIsInExactlyOnePiece) {
  const std::vector<scene::TrackGeometry> g = geometries();
  const std::vector<const scene::TrackGeometry*> p = pointers(g);
  const TrackBuffer buffer{std::span<const scene::TrackGeometry* const>(p)};
  const CapsulePieces all = plan_capsule_pieces(buffer, CapsuleShape::Capsules::polyline, std::nullopt);
  expect_sorted_powers_of_two(all);
  // 599 capsules, a sphere, 1 capsule, 256 capsules.
  EXPECT_EQ(all.capsule_count, 599u + 1u + 1u + 256u);
  const auto cover = covered(all, 1);
  ASSERT_EQ(cover.size(), 4u);
  for (const TrackBuffer::Range& range : buffer.segments()) {
    const auto& positions = cover.at({range.track, range.first});
    const std::int32_t capsules = std::max(range.count - 1, 1);
    ASSERT_EQ(static_cast<std::int32_t>(positions.size()), capsules) << "segment at " << range.first;
    EXPECT_EQ(positions.begin()->first, range.first);
    EXPECT_EQ(positions.rbegin()->first, range.first + capsules - 1);
    for (const auto& [position, times] : positions) EXPECT_EQ(times, 1) << "position " << position;
  }
  for (const CapsulePiece& piece : all.pieces) {
    const TrackBuffer::Range& range = *std::find_if(buffer.segments().begin(), buffer.segments().end(),
                                                    [&](const auto& r) { return r.first == piece.segment_first; });
    EXPECT_EQ(piece.segment_last, range.first + range.count - 1);
    EXPECT_EQ(piece.first_block, range.first_block);
    EXPECT_EQ(piece.list_base, -1);
  }

  // Hidden: track 0's pieces go, the others' stay as they were.
  const CapsulePieces shown = plan_capsule_pieces(buffer, CapsuleShape::Capsules::polyline, std::nullopt,
                                                  [](std::int32_t track) { return track != 0; });
  expect_sorted_powers_of_two(shown);
  EXPECT_EQ(shown.capsule_count, 1u + 1u + 256u);
  auto without = cover;
  without.erase({0, 0});
  EXPECT_EQ(covered(shown, 1), without);
  // Filtering the table the same way gives the same pieces.
  EXPECT_EQ(covered(all.filtered([](const CapsulePiece& piece) { return piece.track != 0; }), 1), without);
}

TEST_F(TrackPiecesTest, PairsKeepTheirStrideAndSinglesTakeEveryPoint) {
  scene::TrackGeometry stems;
  stems.segments = {line(2 * 300, here_)};
  const TrackBuffer buffer(stems);
  const CapsulePieces pairs = plan_capsule_pieces(buffer, CapsuleShape::Capsules::pairs, std::nullopt);
  EXPECT_EQ(pairs.capsule_count, 300u);
  const auto pair_cover = covered(pairs, 2);
  const auto& positions = pair_cover.at({0, 0});
  ASSERT_EQ(positions.size(), 300u);
  for (const auto& [position, times] : positions) {
    EXPECT_EQ(position % 2, 0);
    EXPECT_EQ(times, 1);
  }
  const CapsulePieces singles = plan_capsule_pieces(buffer, CapsuleShape::Capsules::singles, std::nullopt);
  EXPECT_EQ(singles.capsule_count, 600u);
  EXPECT_EQ(covered(singles, 1).at({0, 0}).size(), 600u);
}

TEST_F(TrackPiecesTest, ThroughTheLevelOfDetailThePiecesAreThePlansRuns) {
  scene::TrackGeometry walk;
  walk.segments = {line(3000, here_)};
  const TrackBuffer buffer(walk);
  TrackLod::View far;
  far.eye = here_ + glm::dvec3(4500.0, 0.0, 200000.0);
  far.forward = glm::normalize(here_ + glm::dvec3(4500.0, 0.0, 0.0) - far.eye);
  far.pixel_angle = 1.0e-3;
  far.corner_tangent = 0.7;
  const std::vector<TrackLod::Run> runs = buffer.lod().plan(far);
  ASSERT_FALSE(runs.empty());
  std::size_t capsules = 0;
  for (const TrackLod::Run& run : runs) capsules += static_cast<std::size_t>(run.last - run.first);
  ASSERT_LT(capsules, 2999u) << "a far view merges capsules";
  const CapsulePieces pieces = plan_capsule_pieces(buffer, CapsuleShape::Capsules::polyline, far);
  expect_sorted_powers_of_two(pieces);
  EXPECT_EQ(pieces.capsule_count, capsules);
  for (const CapsulePiece& piece : pieces.pieces) {
    const auto run = std::find_if(runs.begin(), runs.end(), [&](const TrackLod::Run& r) {
      return r.list_base == piece.list_base && r.first == piece.run_first && r.last == piece.run_last;
    });
    ASSERT_NE(run, runs.end());
    EXPECT_EQ(piece.before, run->before);
    EXPECT_EQ(piece.after, run->after);
    EXPECT_GE(piece.start, run->first);
    EXPECT_LE(piece.start + piece.capsules, run->last);
  }
}

}  // namespace
}  // namespace trailray::render
