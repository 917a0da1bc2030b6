// The bench's generated datasets: the many-track scenario's walks, each a segment, spread over
// their square and the same from run to run.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "app/pictures/bench_datasets.hpp"

namespace trailray::app {
namespace {

glm::dvec3 centroid(const scene::TrackPolyline& s) {
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& p : s.points_ecef) sum += p;
  return sum / static_cast<double>(s.points_ecef.size());
}

TEST(BenchDatasets, ManyWalksAreSegmentsSpreadOverTheirSquare) {
  const BenchDataset d = make_many_walks(12, 300);
  ASSERT_EQ(d.geometry.segments.size(), 12u);
  EXPECT_EQ(d.point_count(), 3600u);
  double farthest = 0.0, nearest = 1e12;
  for (std::size_t a = 0; a < 12; ++a) {
    EXPECT_EQ(d.geometry.segments[a].points_ecef.size(), 300u);
    for (std::size_t b = a + 1; b < 12; ++b) {
      const double apart = glm::length(centroid(d.geometry.segments[a]) - centroid(d.geometry.segments[b]));
      farthest = std::max(farthest, apart);
      nearest = std::min(nearest, apart);
    }
  }
  // Walks of 300 steps reach at most 1.8 km from their centre; the centres lie in 30 x 30 km.
  EXPECT_GT(farthest, 5000.0);
  EXPECT_LT(farthest, kManyWalksSpanM * 1.4143 + 4000.0);
  EXPECT_GT(nearest, 0.0);
  // The same sizes, the same walks.
  const BenchDataset again = make_many_walks(12, 300);
  EXPECT_EQ(again.geometry.segments[7].points_ecef[299], d.geometry.segments[7].points_ecef[299]);
  EXPECT_NE(make_many_walks(12, 301).geometry.segments[7].points_ecef[0], d.geometry.segments[7].points_ecef[0]);
}

}  // namespace
}  // namespace trailray::app
