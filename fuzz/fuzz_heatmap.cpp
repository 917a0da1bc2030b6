// libFuzzer target for the heatmap exchange format (track/heatmap_exchange.hpp): what `trailray
// heatmap` reads back from an .mbtiles file or a folder someone handed over to add to. The first
// byte picks the reader; each must answer or throw std::invalid_argument, never crash:
//   description  parse_heatmap_description -> a cell of 1..100000 m, a measure that names itself
//   tile         unpack_heatmap_tile -> 65,536 counts that pack and unpack to themselves
//   key          parse_heatmap_tile_key -> a tile inside the grid
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "track/heatmap_exchange.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace tr = trailray::track;
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    switch (data[0] % 3) {
      case 0: {
        const tr::HeatmapDescription d = tr::parse_heatmap_description(text);
        if (!(d.cell_m >= 1.0 && d.cell_m <= 100000.0)) std::abort();
        if (tr::parse_heatmap_measure(tr::heatmap_measure_name(d.measure)) != d.measure) std::abort();
        if (tr::parse_heatmap_description(tr::heatmap_description_json(d)).tracks != d.tracks) std::abort();
        break;
      }
      case 1: {
        const auto tile = tr::unpack_heatmap_tile({data + 1, size - 1});
        if (tr::unpack_heatmap_tile(tr::pack_heatmap_tile(tile)) != tile) std::abort();
        break;
      }
      default: {
        const auto [col, row] = tr::parse_heatmap_tile_key(text, 3131);
        if (col < 0 || row < 0 || col >= 3131 || row >= 3131) std::abort();
      }
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
