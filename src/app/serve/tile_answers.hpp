#pragma once
// The tiles of `trailray serve`: /tiles/terrain/{z}/{x}/{y}.png from the --terrain source through
// the terrain layer (any source: a GDAL raster warped to the tile, MBTiles, a folder, a server
// through the disk cache), always re-encoded as Terrarium PNG whatever the source's encoding, so
// the page reads one format; /tiles/imagery/{z}/{x}/{y} as stored (PNG, JPEG or WebP) where the
// source stores tiles, a PNG where it warps a raster.

#include <optional>
#include <string>
#include <vector>

#include "app/serve/http_server.hpp"
#include "terrain/loading/stop_token.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::app::serve {

// The tile of the path segments after "/tiles/<kind>/": "{z}", "{x}", "{y}<suffix>", decimal
// without signs or leading zeros beyond "0"; nullopt for anything else or an id outside the
// pyramid, or a zoom above `max_zoom`.
std::optional<terrain::TileId> parse_tile_segments(const std::vector<std::string>& segments, std::size_t first,
                                                   const std::string& suffix, int max_zoom);

// 200 with the tile, 404 where the source has no data there, 502 when the source failed, 503
// when cancelled (the server stopping). Thread-safe (the sources are).
HttpResponse terrain_tile_response(terrain::HeightSource& source, const terrain::TileId& tile, terrain::StopToken stop);
HttpResponse imagery_tile_response(terrain::ImagerySource& source, const terrain::TileId& tile,
                                   terrain::StopToken stop);

}  // namespace trailray::app::serve
