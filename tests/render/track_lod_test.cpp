// The capsules' level-of-detail hierarchy (render/passes/track_lod.hpp), GL-free: every level
// keeps the chunks' ends and the changes of colour kind, its recorded errors bound every dropped
// point, levels shrink, and a view's plan draws each chunked segment once, joined end to end.
#include "render/passes/track_lod.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace trailray::render {
namespace {

// A walk in a plane at z = 0 (a few metres a step, turning smoothly), with a value per point that
// changes slowly with a little noise (an altitude), seeded.
struct Walk {
  std::vector<glm::dvec3> points;
  std::vector<float> values;
};
Walk walk(std::size_t count, std::uint64_t seed) {
  Walk w;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> turn(0.0, 0.3), drift(0.0, 1.0);
  double heading = 0.0, value = 500.0;
  glm::dvec3 p(0.0);
  for (std::size_t i = 0; i < count; ++i) {
    w.points.push_back(p);
    w.values.push_back(static_cast<float>(value));
    heading += turn(random);
    p += 4.0 * glm::dvec3(std::cos(heading), std::sin(heading), 0.0);
    value = 500.0 + 200.0 * std::sin(static_cast<double>(i) / 400.0) + 0.2 * drift(random);
  }
  return w;
}

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, double& s) {
  const glm::dvec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  s = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + ab * s));
}

// A level's kept points for one chunk, from the shared list.
std::vector<std::int32_t> kept_points(const TrackLod& lod, std::size_t level, std::size_t chunk) {
  const TrackLod::Level& l = lod.levels()[level];
  const TrackLod::ChunkLevel& cl = l.chunks[chunk];
  const auto begin = lod.indices().begin() + l.base + cl.list_first;
  return {begin, begin + cl.kept};
}

TEST(TrackLod, EveryLevelKeepsTheChunkEndsAndItsRecordedErrorsBoundEveryDroppedPoint) {
  const Walk w = walk(5000, 7);
  const TrackLod lod(w.points, w.values, {{0, 5000}});
  ASSERT_EQ(lod.chunks().size(), (5000u - 1 + TrackLod::kChunkPoints - 1) / TrackLod::kChunkPoints);
  ASSERT_GE(lod.levels().size(), 3u) << "a 5000-point walk has room for several coarser levels";
  for (std::size_t l = 0; l < lod.levels().size(); ++l)
    for (std::size_t c = 0; c < lod.chunks().size(); ++c) {
      const TrackLod::Chunk& chunk = lod.chunks()[c];
      const std::vector<std::int32_t> kept = kept_points(lod, l, c);
      ASSERT_GE(kept.size(), 2u);
      EXPECT_EQ(kept.front(), chunk.first) << "level " << l + 1 << " chunk " << c;
      EXPECT_EQ(kept.back(), chunk.last) << "level " << l + 1 << " chunk " << c;
      EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()) &&
                  std::adjacent_find(kept.begin(), kept.end()) == kept.end());
      double worst_m = 0.0, worst_value = 0.0;
      for (std::size_t k = 0; k + 1 < kept.size(); ++k)
        for (std::int32_t p = kept[k] + 1; p < kept[k + 1]; ++p) {
          double s = 0.0;
          const auto a = static_cast<std::size_t>(kept[k]), b = static_cast<std::size_t>(kept[k + 1]);
          worst_m = std::max(worst_m,
                             distance_to_segment(w.points[static_cast<std::size_t>(p)], w.points[a], w.points[b], s));
          const double expected = w.values[a] + (w.values[b] - w.values[a]) * s;
          worst_value = std::max(worst_value, std::abs(w.values[static_cast<std::size_t>(p)] - expected));
        }
      const TrackLod::ChunkLevel& cl = lod.levels()[l].chunks[c];
      EXPECT_NEAR(cl.position_error_m, worst_m, 1.0e-4 * (1.0 + worst_m)) << "level " << l + 1 << " chunk " << c;
      EXPECT_NEAR(cl.value_error, worst_value, 1.0e-3 * (1.0 + worst_value)) << "level " << l + 1 << " chunk " << c;
    }
}

TEST(TrackLod, EachLevelKeepsAtMostHalfOfTheOneBelowAndTheListsStayUnderFourBytesAPoint) {
  const Walk w = walk(20000, 11);
  const TrackLod lod(w.points, {}, {{0, 20000}});
  std::size_t below = 20000;
  for (const TrackLod::Level& level : lod.levels()) {
    const bool fewest = static_cast<std::size_t>(level.size) == lod.chunks().size() + 1;
    EXPECT_TRUE(2 * static_cast<std::size_t>(level.size) <= below + lod.chunks().size() || fewest)
        << level.size << " points at tolerance " << level.tolerance_m << " after " << below;
    below = static_cast<std::size_t>(level.size);
  }
  EXPECT_LE(lod.indices().size(), 20000u);
  EXPECT_LE(lod.levels().back().size, static_cast<std::int32_t>(2 * lod.chunks().size() + 1))
      << "the coarsest level keeps little more than the chunks' ends";
}

TEST(TrackLod, EveryLevelKeepsBothSidesOfEachChangeBetweenValuesNoValueAndACategory) {
  Walk w = walk(3000, 3);
  const float category = -1.0e30f;
  for (std::size_t i = 700; i < 1500; ++i) w.values[i] = category;
  for (std::size_t i = 2000; i < 2100; ++i) w.values[i] = std::numeric_limits<float>::quiet_NaN();
  const TrackLod lod(w.points, w.values, {{0, 3000}});
  ASSERT_FALSE(lod.levels().empty());
  const std::vector<std::int32_t> changes{699, 700, 1499, 1500, 1999, 2000, 2099, 2100};
  for (std::size_t l = 0; l < lod.levels().size(); ++l) {
    std::vector<std::int32_t> all;
    for (std::size_t c = 0; c < lod.chunks().size(); ++c) {
      const std::vector<std::int32_t> kept = kept_points(lod, l, c);
      all.insert(all.end(), kept.begin(), kept.end());
    }
    for (const std::int32_t point : changes)
      EXPECT_TRUE(std::find(all.begin(), all.end(), point) != all.end()) << "level " << l + 1 << " drops " << point;
  }
}

TEST(TrackLod, ShortSegmentsAreNotChunkedAndSegmentsNeverShareAChunk) {
  const Walk w = walk(2600, 5);
  const TrackLod lod(w.points, {}, {{0, 2}, {2, 1500}, {1502, 1}, {1503, 1097}});
  EXPECT_FALSE(lod.chunked(0));
  EXPECT_TRUE(lod.chunked(1));
  EXPECT_FALSE(lod.chunked(2));
  EXPECT_TRUE(lod.chunked(3));
  for (const TrackLod::Chunk& c : lod.chunks()) {
    const std::int32_t first = c.segment == 1 ? 2 : 1503, last = c.segment == 1 ? 1501 : 2599;
    EXPECT_TRUE(c.segment == 1 || c.segment == 3);
    EXPECT_GE(c.first, first);
    EXPECT_LE(c.last, last);
  }
}

// The points a run draws, in order (list positions through the level's list).
std::vector<std::int32_t> run_points(const TrackLod& lod, const TrackLod::Run& run) {
  std::vector<std::int32_t> points;
  for (std::int32_t j = run.first; j <= run.last; ++j)
    points.push_back(run.list_base < 0 ? j : lod.indices()[static_cast<std::size_t>(run.list_base + j)]);
  return points;
}

TEST(TrackLod, APlanDrawsEachSegmentOnceEndToEndWithJointsSharedAcrossLevels) {
  const Walk w = walk(12000, 13);
  const TrackLod lod(w.points, w.values, {{0, 12000}});
  // Looking along +x from the walk's start: the near chunks at full detail, the far ones coarser.
  TrackLod::View view;
  view.eye = glm::dvec3(-50.0, 0.0, 30.0);
  view.forward = glm::dvec3(1.0, 0.0, 0.0);
  view.pixel_angle = 1.0e-2;
  view.corner_tangent = 0.8;
  const std::vector<TrackLod::Run> runs = lod.plan(view);
  ASSERT_FALSE(runs.empty());
  std::vector<int> levels;
  std::vector<std::int32_t> drawn;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const std::vector<std::int32_t> points = run_points(lod, runs[r]);
    ASSERT_GE(points.size(), 2u);
    levels.push_back(runs[r].level);
    if (r == 0) {
      EXPECT_EQ(points.front(), 0);
      EXPECT_EQ(runs[r].before, -1);
    } else {
      // Joined: the run starts where the last ended, and each side's joint is built with the
      // other's neighbouring point.
      EXPECT_EQ(points.front(), drawn.back());
      EXPECT_EQ(runs[r].before, drawn[drawn.size() - 2]);
      EXPECT_EQ(runs[r - 1].after, points[1]);
      drawn.pop_back();
    }
    drawn.insert(drawn.end(), points.begin(), points.end());
  }
  EXPECT_EQ(drawn.back(), 11999);
  EXPECT_EQ(runs.back().after, -1);
  EXPECT_TRUE(std::is_sorted(drawn.begin(), drawn.end()));
  EXPECT_LT(drawn.size(), 12000u / 2) << "far chunks merge";
  EXPECT_EQ(*std::min_element(levels.begin(), levels.end()), 0) << "the chunk at the camera is at full detail";
  EXPECT_GT(*std::max_element(levels.begin(), levels.end()), 1);

  // Every chunk's level holds the pixel bound at its nearest depth.
  for (std::size_t c = 0; c < lod.chunks().size(); ++c) {
    const int level = lod.level_for(c, view);
    if (level == 0) continue;
    const TrackLod::Chunk& chunk = lod.chunks()[c];
    const double nearest = glm::dot(chunk.centre - view.eye, view.forward) - chunk.radius;
    const double error_px =
        lod.levels()[static_cast<std::size_t>(level - 1)].chunks[c].position_error_m / (view.pixel_angle * nearest);
    EXPECT_LE(error_px, TrackLod::kMaxErrorPx) << "chunk " << c;
  }
}

TEST(TrackLod, ColouredByValueALevelIsTakenOnlyWhereItsValuesStayWithinTheColourScale) {
  const Walk w = walk(6000, 17);
  const TrackLod lod(w.points, w.values, {{0, 6000}});
  TrackLod::View view;
  view.eye = glm::dvec3(0.0, 0.0, 1.0e6);  // far above: every chunk could be coarsest by position
  view.forward = glm::dvec3(0.0, 0.0, -1.0);
  view.pixel_angle = 1.0e-3;
  view.corner_tangent = 0.8;
  view.by_value = true;
  for (const double range : {1.0e6, 50.0, 1.0e-6}) {
    view.value_range = range;
    for (std::size_t c = 0; c < lod.chunks().size(); ++c) {
      const int level = lod.level_for(c, view);
      const double error = level == 0 ? 0.0 : lod.levels()[static_cast<std::size_t>(level - 1)].chunks[c].value_error;
      EXPECT_LE(error, TrackLod::kMaxValueErrorFraction * range) << "range " << range << " chunk " << c;
      if (range == 1.0e6) {
        EXPECT_EQ(level, static_cast<int>(lod.levels().size()));
      }
    }
  }
}

}  // namespace
}  // namespace trailray::render
