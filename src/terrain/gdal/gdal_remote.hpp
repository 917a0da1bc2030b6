#pragma once
// Remote rasters read through GDAL (an http(s) URL of one file, or a /vsicurl/, /vsis3/, ...
// path): GDAL fetches only the header and the blocks a read needs with HTTP range requests, so a
// Cloud-Optimized GeoTIFF of a whole country serves a view from its overviews and a track from a
// few blocks. The network settings of the tile servers apply (timeouts, retries, headers with
// ${VAR}, --offline); GDAL 3.6 keeps what it read in memory for the run and has no disk cache,
// so nothing is written to the tile cache.

#include <memory>
#include <string>

#include "terrain/gdal/gdal_raster.hpp"
#include "terrain/sources/terrain_config.hpp"

namespace trailray::terrain {

// Throws SourceError naming the URL: offline, the server unreachable or without range requests
// (HTTP Range, which reading part of a file needs), or not a raster.
std::unique_ptr<GdalHeightSource> open_remote_height_source(const SourceSettings& settings,
                                                            const NetworkSettings& network);
std::unique_ptr<GdalImagerySource> open_remote_imagery_source(const SourceSettings& settings,
                                                              const NetworkSettings& network);

}  // namespace trailray::terrain
