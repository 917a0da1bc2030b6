// The drawn surface with the canopy cut along the tracks under cover: samples within the corridor
// take the ground's height, the others keep the surface's; tiles far from every cut are the
// surface's as they are (the ground not even loaded); a coarse level still cuts its nearest
// samples; and the covered runs of tracks become the lines cut along.
#include "scene/tracks/canopy_cut.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geo/tile_id.hpp"
#include "track/cover.hpp"

namespace trailray::scene {
namespace {

// A flat source: every sample at `height_m`; counts its loads.
class FlatSource final : public terrain::HeightSource {
 public:
  explicit FlatSource(float height_m) : height_(height_m) { info_.max_zoom = 18; }
  const terrain::SourceInfo& info() const override { return info_; }
  terrain::TileResult<terrain::HeightTile> load(const terrain::TileId& id, terrain::StopToken) override {
    ++loads;
    terrain::HeightTile t;
    t.id = id;
    t.width = t.height = 256;
    t.heights.assign(256 * 256, height_);
    terrain::update_height_range(t);
    return {terrain::TileStatus::ok, std::move(t), {}};
  }
  int loads = 0;

 private:
  float height_;
  terrain::SourceInfo info_;
};

// The Mercator y of a tile's sample row (pixel_is_area), and the row nearest a latitude.
std::uint32_t row_of(const geo::TileId& id, double lat) {
  const auto p = geo::tile_pixel(lat, geo::tile_bounds_latlon(id)->min_lon + 1e-9, id.zoom, 256);
  return static_cast<std::uint32_t>(std::floor(p->py));
}

TEST(CanopyCut, SamplesAlongTheCoveredLineShowTheGroundTheRestTheCanopy) {
  FlatSource surface(520.0f), ground(500.0f);
  CanopyCutHeights cut(surface, ground, 8.0);
  const geo::TileId id = *geo::tile_containing(46.70, 7.85, 17);  // about 200 m a side, 0.8 m a sample
  const geo::LatLonBounds box = *geo::tile_bounds_latlon(id);
  const double lat = 0.5 * (box.min_lat + box.max_lat);
  cut.set_cut_lines({{{lat, box.min_lon - 0.001}, {lat, box.max_lon + 0.001}}});  // west to east across it
  ASSERT_GT(cut.cut_points(), 2u);
  const auto r = cut.load(id, {});
  ASSERT_EQ(r.status, terrain::TileStatus::ok);
  const std::uint32_t on = row_of(id, lat);
  const double metres_per_row = (box.max_lat - box.min_lat) * 111320.0 / 256.0;
  const auto rows_away = [&](double m) { return static_cast<std::uint32_t>(std::lround(m / metres_per_row)); };
  for (const std::uint32_t col : {0u, 100u, 255u}) {
    EXPECT_EQ(r.tile.at(col, on), 500.0f) << col;                     // on the line: the ground
    EXPECT_EQ(r.tile.at(col, on + rows_away(5.0)), 500.0f) << col;    // 5 m off: within the corridor
    EXPECT_EQ(r.tile.at(col, on + rows_away(12.0)), 520.0f) << col;   // 12 m off: the canopy
    EXPECT_EQ(r.tile.at(col, 0), 520.0f) << col;
  }
  EXPECT_EQ(r.tile.min_m, 500.0f);
  EXPECT_EQ(r.tile.max_m, 520.0f);

  // Far away: the surface's tile as it is, the ground never asked.
  const int ground_loads = ground.loads;
  const auto far = cut.load(*geo::tile_containing(46.75, 7.95, 17), {});
  EXPECT_EQ(far.tile.min_m, 520.0f);
  EXPECT_EQ(ground.loads, ground_loads);

  // A coarse level (samples about 100 m apart): the samples nearest the line are cut all the same.
  const geo::TileId coarse = *geo::tile_containing(lat, 7.85, 10);
  const auto c = cut.load(coarse, {});
  EXPECT_EQ(c.tile.min_m, 500.0f);
  EXPECT_EQ(c.tile.max_m, 520.0f);
}

TEST(CanopyCut, NoCutLinesIsTheSurface) {
  FlatSource surface(520.0f), ground(500.0f);
  CanopyCutHeights cut(surface, ground);
  const auto r = cut.load(*geo::tile_containing(46.70, 7.85, 15), {});
  EXPECT_EQ(r.tile.min_m, 520.0f);
  EXPECT_EQ(ground.loads, 0);
  EXPECT_NE(cut.info().name.find("canopy cut"), std::string::npos);
}

TEST(CanopyCut, CoveredRunsOfVisibleTracksAreTheLines) {
  Track t;
  t.cleaned.segments.resize(2);
  for (int i = 0; i < 5; ++i) t.cleaned.segments[0].points.push_back({46.7, 7.85 + 0.001 * i});
  for (int i = 0; i < 2; ++i) t.cleaned.segments[1].points.push_back({46.8, 7.85 + 0.001 * i});
  const auto c = static_cast<std::uint8_t>(track::Cover::covered), o = static_cast<std::uint8_t>(track::Cover::open);
  t.cover = {o, c, c, o, c, c, c};  // a segment boundary between the last two runs
  TrackSet set;
  set.add(t);
  const auto lines = covered_lines(set);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].size(), 2u);
  EXPECT_EQ(lines[1].size(), 1u);
  EXPECT_EQ(lines[2].size(), 2u);
  EXPECT_DOUBLE_EQ(lines[2][0].lat, 46.8);
  set[0].visible = false;
  EXPECT_TRUE(covered_lines(set).empty());
}

}  // namespace
}  // namespace trailray::scene
