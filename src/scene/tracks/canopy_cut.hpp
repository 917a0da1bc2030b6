#pragma once
// What is drawn with a surface model (`--surface`): the surface (canopy and buildings are seen),
// except along the parts of the tracks that run under cover, where the ground is drawn instead,
// in a corridor a few metres wide: the canopy made see-through around the track, so a hike in
// a forest is seen on its forest road, while a track behind a ridge stays hidden (ghosted) as
// before. The terrain model stays what the tracks stand on; this only decides what is drawn.
//
// A height source over two others: tiles of the surface with the samples within the corridor
// replaced by the ground's (bilinear in the ground's tile of the same id). The corridor is at
// least as wide as the tile's samples are apart, so coarse levels cut their nearest samples too.

#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "geo/web_mercator.hpp"
#include "scene/tracks/track_set.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::scene {

class CanopyCutHeights final : public terrain::HeightSource {
 public:
  // Neither source is owned; both outlive this. `radius_m`: half the corridor's width.
  CanopyCutHeights(terrain::HeightSource& surface, terrain::HeightSource& ground, double radius_m = 8.0);

  // The places to cut around (the covered points of the tracks, their segments filled in).
  // Call before the first load(): tiles already handed out keep their canopy.
  void set_cut_lines(const std::vector<std::vector<geo::LatLon>>& lines);
  std::size_t cut_points() const { return points_.size(); }

  const terrain::SourceInfo& info() const override { return info_; }
  terrain::TileResult<terrain::HeightTile> load(const terrain::TileId& tile, terrain::StopToken stop) override;
  std::optional<double> sample_native(double lat, double lon) override { return surface_.sample_native(lat, lon); }

 private:
  // The cut points within `reach` (Mercator metres) of a Mercator box, by grid cell.
  bool any_near(double min_x, double min_y, double max_x, double max_y, double reach) const;
  bool near(const geo::MercatorPoint& p, double reach) const;

  terrain::HeightSource& surface_;
  terrain::HeightSource& ground_;
  double radius_m_;
  terrain::SourceInfo info_;
  std::vector<geo::MercatorPoint> points_;
  std::vector<double> scale_;  // Mercator metres per ground metre at each point
  double cell_ = 1.0;          // Mercator metres a grid cell
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

// The runs of covered points (Track::cover) of the visible tracks, each a line of places.
std::vector<std::vector<geo::LatLon>> covered_lines(const TrackSet& tracks);

}  // namespace trailray::scene
