#pragma once
// A height source for tests of the terrain view and the renderer: terrain whose height depends
// only on the distance east of a meridian (GL-free, so scene and render tests share it).

#include <cmath>
#include <cstdint>
#include <functional>
#include <stop_token>
#include <string>
#include <utility>

#include "geo/tile_id.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::test {

// Terrain whose height depends only on the distance east of a meridian: height_m(east_m), with
// east_m measured at the latitude `lat` (65 x 65 pixel-is-point tiles up to zoom 14, any tile).
class EastProfileSource : public terrain::HeightSource {
 public:
  EastProfileSource(std::string name, double lat, double lon, std::function<double(double east_m)> height_m)
      : lon_(lon), metres_per_degree_(111320.0 * std::cos(lat * M_PI / 180.0)), height_m_(std::move(height_m)) {
    info_.name = std::move(name);
    info_.max_zoom = 14;
  }
  const terrain::SourceInfo& info() const override { return info_; }
  terrain::TileResult<terrain::HeightTile> load(const terrain::TileId& id, std::stop_token) override {
    terrain::TileResult<terrain::HeightTile> r;
    r.status = terrain::TileStatus::ok;
    terrain::HeightTile& t = r.tile;
    t.id = id;
    t.width = t.height = 65;
    t.layout = terrain::SampleLayout::pixel_is_point;
    for (std::uint32_t row = 0; row < 65; ++row)
      for (std::uint32_t col = 0; col < 65; ++col) {
        const double east_m = (geo::latlon_from_tile_pixel(id, col, row, 64)->lon - lon_) * metres_per_degree_;
        t.heights.push_back(static_cast<float>(height_m_(east_m)));
      }
    terrain::update_height_range(t);
    return r;
  }

 private:
  terrain::SourceInfo info_;
  double lon_, metres_per_degree_;
  std::function<double(double)> height_m_;
};

}  // namespace trailray::test
