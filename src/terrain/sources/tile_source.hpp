#pragma once
// The one interface behind every terrain and imagery source (DESIGN.md "Terrain sources"):
//   EncodedTileSource  - compressed image bytes per tile: a folder of tiles, an MBTiles file,
//                        an http(s) URL template (with its disk cache);
//   HeightSource       - decoded height grids per tile (an EncodedTileSource + a HeightEncoding,
//                        or a GDAL raster warped to Web Mercator);
//   ImagerySource      - decoded RGBA tiles (albedo for the renderer).
// Every fetch/load is thread-safe and may block (disk, network): the async loader calls them
// from its workers; a stop_token lets it give up on tiles that left the view.

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geo/bounds.hpp"
#include "terrain/codecs/height_encoding.hpp"
#include "terrain/loading/stop_token.hpp"
#include "terrain/tile.hpp"

namespace trailray::terrain {

// A source that cannot be opened at all (a missing file, an unreadable MBTiles, a bad URL
// template). The message names the source.
class SourceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Row numbering of a tile pyramid on disk or on a server.
enum class TileScheme { xyz, tms };

// "xyz" or "tms" exactly (callers that accept other spellings normalise first); nullopt else.
std::optional<TileScheme> parse_tile_scheme(std::string_view name);

struct SourceInfo {
  std::string name;  // the path or URL template, for messages
  int min_zoom = 0;
  int max_zoom = 15;                        // the finest level the source has
  std::optional<geo::LatLonBounds> bounds;  // where it has data, when known
  std::optional<HeightEncoding> encoding;   // from the source's metadata, when it says
  std::string format;                       // "png", "jpg", "webp", "tif", ... when known
  std::string attribution;                  // to show with the picture, when known
};

struct EncodedTile {
  TileStatus status = TileStatus::no_data;
  std::vector<unsigned char> bytes;  // when ok: the file as stored (PNG, JPEG, WebP, ...)
  std::string error;                 // when failed
};

class EncodedTileSource {
 public:
  virtual ~EncodedTileSource() = default;
  virtual const SourceInfo& info() const = 0;
  virtual EncodedTile fetch(const TileId& tile, StopToken stop) = 0;
};

class HeightSource {
 public:
  virtual ~HeightSource() = default;
  virtual const SourceInfo& info() const = 0;
  virtual TileResult<HeightTile> load(const TileId& tile, StopToken stop) = 0;

  // Height at a point read from the source's own grid (no Mercator resampling), when the source
  // has one (a GDAL raster); NaN where it has no data; nullopt when the source is tiles only.
  virtual std::optional<double> sample_native(double /*lat*/, double /*lon*/) { return std::nullopt; }
};

class ImagerySource {
 public:
  virtual ~ImagerySource() = default;
  virtual const SourceInfo& info() const = 0;
  virtual TileResult<ImageTile> load(const TileId& tile, StopToken stop) = 0;
};

}  // namespace trailray::terrain
