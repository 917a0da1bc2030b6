// The colour values of --color-by phase, on the points of a track other than the one analysed
// (the drawn track is cleaned: points dropped, times kept), and the category value's place in
// the colour range.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "synthetic_flight.hpp"
#include "track/color_values.hpp"
#include "track/flight/phase_values.hpp"

namespace fl = trailray::track::flight;
namespace tr = trailray::track;
using trailray::track::test::SyntheticFlight;

TEST(PhaseValues, PointsOfAThinnedTrackTakeThePhaseOfTheirTime) {
  SyntheticFlight sim;
  sim.ground(100);
  sim.glide(150, 0.0);
  const double thermal = sim.time();
  sim.circle(200, true, 1.5);
  sim.glide(150, 90.0);
  sim.ground(100);
  const tr::Track raw = sim.track();
  const fl::FlightAnalysis a = fl::analyse_flights(raw);
  ASSERT_EQ(a.flights.size(), 1u);
  // Every third point, plus one without a time: what the analysis never saw.
  tr::Track thinned;
  thinned.segments.emplace_back();
  for (std::size_t i = 0; i < raw.segments[0].points.size(); i += 3)
    thinned.segments[0].points.push_back(raw.segments[0].points[i]);
  tr::TrackPoint untimed = thinned.segments[0].points[100];
  untimed.time = tr::kMissing;
  thinned.segments[0].points.insert(thinned.segments[0].points.begin() + 100, untimed);
  const auto values = fl::phase_color_values(thinned, a);
  ASSERT_EQ(values.size(), 1u);
  ASSERT_EQ(values[0].size(), thinned.segments[0].points.size());
  EXPECT_TRUE(std::isnan(values[0][100]));
  int circling = 0;
  for (std::size_t i = 0; i < values[0].size(); ++i) {
    const double t = thinned.segments[0].points[i].time;
    if (std::isnan(t)) continue;
    EXPECT_EQ(fl::phase_at_time(a, t) == fl::Phase::Gliding, tr::is_category_value(values[0][i])) << i;
    if (t > thermal + 20 && t < thermal + 180) {
      EXPECT_TRUE(fl::is_circling(fl::phase_at_time(a, t)));
      EXPECT_NEAR(values[0][i], 1.5, 0.05) << i;
      ++circling;
    }
  }
  EXPECT_GT(circling, 50);
  EXPECT_EQ(fl::phase_at_time(a, sim.track().segments[0].points.front().time), fl::Phase::Ground);
  EXPECT_EQ(fl::phase_at_time(a, tr::kMissing), fl::Phase::Unknown);
}

TEST(PhaseValues, CategoryValuesStayOutOfTheRange) {
  const std::vector<std::vector<float>> values{{tr::kCategoryValue, 1.0f, 2.0f, tr::kCategoryValue, 3.0f}};
  const auto range = tr::robust_range(values, false, 0.0, 100.0);
  ASSERT_TRUE(range);
  EXPECT_EQ(range->min, 1.0);
  EXPECT_EQ(range->max, 3.0);
  EXPECT_FALSE(tr::robust_range(std::vector<std::vector<float>>{{tr::kCategoryValue}}, false));
  EXPECT_TRUE(tr::is_category_value(tr::kCategoryValue));
  EXPECT_FALSE(tr::is_category_value(-3.0e38f));  // the renderer's "no value"
  EXPECT_FALSE(tr::is_category_value(-1.0e6f));
  EXPECT_EQ(tr::parse_color_metric("phase"), tr::ColorMetric::phase);
  EXPECT_EQ(tr::format_color_value(tr::ColorMetric::phase, 2.35), "2.4");
}
