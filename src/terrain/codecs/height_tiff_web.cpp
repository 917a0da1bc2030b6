// height_tiff.hpp where there is no GDAL to read TIFF with: the browser's build, and the GPU
// bundle's program (trailray-gpu compiles this file into itself).
#include "terrain/codecs/height_decode.hpp"
#include "terrain/codecs/height_tiff.hpp"

namespace trailray::terrain::detail {
namespace {
[[noreturn]] void no_tiff() {
  throw TileDecodeError(
      "float (TIFF) height tiles need GDAL, which the browser and the GPU bundle do not have; use a "
      "Terrarium, Terrain-RGB or AlpineMaps PNG source, or `trailray serve --terrain`, which serves them "
      "as Terrarium");
}
}  // namespace

HeightTile decode_float_tiff(std::span<const unsigned char>, const TileId&) { no_tiff(); }
std::vector<unsigned char> encode_float_tiff(const HeightTile&) { no_tiff(); }

}  // namespace trailray::terrain::detail
