// The browser's build of height_tiff.hpp: it has no GDAL to read TIFF with.
#include "terrain/height_decode.hpp"
#include "terrain/height_tiff.hpp"

namespace trailray::terrain::detail {
namespace {
[[noreturn]] void no_tiff() {
  throw TileDecodeError(
      "float (TIFF) height tiles are not readable in the browser; use a Terrarium, Terrain-RGB "
      "or AlpineMaps PNG source, or `trailray serve --terrain`, which serves them as Terrarium");
}
}  // namespace

HeightTile decode_float_tiff(std::span<const unsigned char>, const TileId&) { no_tiff(); }
std::vector<unsigned char> encode_float_tiff(const HeightTile&) { no_tiff(); }

}  // namespace trailray::terrain::detail
