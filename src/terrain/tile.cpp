#include "terrain/tile.hpp"

#include <algorithm>

#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

void update_height_range(HeightTile& tile) {
  float lo = std::numeric_limits<float>::infinity(), hi = -std::numeric_limits<float>::infinity();
  for (float h : tile.heights) {
    if (std::isnan(h)) continue;
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  tile.min_m = lo <= hi ? lo : kNoHeight;
  tile.max_m = lo <= hi ? hi : kNoHeight;
}

std::optional<TileScheme> parse_tile_scheme(std::string_view name) {
  if (name == "xyz") return TileScheme::xyz;
  if (name == "tms") return TileScheme::tms;
  return std::nullopt;
}

std::string_view to_string(TileStatus status) {
  switch (status) {
    case TileStatus::ok:
      return "ok";
    case TileStatus::no_data:
      return "no data";
    case TileStatus::failed:
      return "failed";
    case TileStatus::cancelled:
      return "cancelled";
  }
  return "?";
}

}  // namespace trailray::terrain
