#pragma once
// The same heights four ways, for tests that check every kind of source agrees: a GeoTIFF from
// ../shared/data, the Terrarium tiles warped from it at one zoom level around an area, written
// as an XYZ folder, a TMS folder and an MBTiles file, and (started by the test) served over HTTP
// from the XYZ folder by LocalTileServer.

#include <cmath>
#include <filesystem>
#include <vector>

#include "terrain/gdal/gdal_raster.hpp"
#include "terrain/tile_fixtures.hpp"

namespace trailray::test {

struct DemPyramid {
  TempDir dir;
  std::filesystem::path xyz_folder, tms_folder, mbtiles;
  std::size_t tiles = 0;
};

// Every tile of `zoom` over the box, plus a ring of one tile around it (the sampler reads the
// neighbours of points within half a sample of a tile's edge).
inline std::vector<terrain::TileId> tiles_around(const geo::LatLonBounds& box, int zoom) {
  const auto nw = *geo::tile_containing(box.max_lat, box.min_lon, zoom);
  const auto se = *geo::tile_containing(box.min_lat, box.max_lon, zoom);
  std::vector<terrain::TileId> ids;
  for (std::uint32_t x = nw.x - 1; x <= se.x + 1; ++x)
    for (std::uint32_t y = nw.y - 1; y <= se.y + 1; ++y) ids.push_back({zoom, x, y});
  return ids;
}

inline void build_dem_pyramid(DemPyramid& p, const std::filesystem::path& dem, const geo::LatLonBounds& box, int zoom) {
  terrain::GdalHeightSource source(dem.string());
  const auto ids = tiles_around(box, zoom);
  p.xyz_folder = p.dir.path() / "xyz";
  p.tms_folder = p.dir.path() / "tms";
  p.mbtiles = p.dir.path() / "tiles.mbtiles";
  p.tiles = write_terrarium_folder(source, ids, p.xyz_folder, terrain::TileScheme::xyz);
  write_terrarium_folder(source, ids, p.tms_folder, terrain::TileScheme::tms);
  write_terrarium_mbtiles(source, ids, p.mbtiles);
}

}  // namespace trailray::test
