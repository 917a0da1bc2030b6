#include "track/heatmap_exchange.hpp"

#include <zlib.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace trailray::track {
namespace {

constexpr std::size_t kTileCells = std::size_t{kHeatmapTileCells} * kHeatmapTileCells;

}  // namespace

std::string heatmap_description_json(const HeatmapDescription& d) {
  const nlohmann::json j = {{"format", "trailray-heatmap"},
                            {"version", 1},
                            {"cell_m", d.cell_m},
                            {"of", std::string(heatmap_measure_name(d.measure))},
                            {"tracks", d.tracks},
                            {"max", d.max_count},
                            {"colormap", d.colormap},
                            {"scale", d.scale}};
  return j.dump();
}

HeatmapDescription parse_heatmap_description(std::string_view text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw std::invalid_argument("its heatmap description is not a JSON object");
  const auto field = [&](const char* name) -> const nlohmann::json& {
    const auto it = j.find(name);
    if (it == j.end()) throw std::invalid_argument(std::string("its heatmap description has no \"") + name + "\"");
    return *it;
  };
  if (!field("format").is_string() || field("format").get<std::string>() != "trailray-heatmap")
    throw std::invalid_argument("not a trailray heatmap (\"format\" is not \"trailray-heatmap\")");
  HeatmapDescription d;
  const nlohmann::json &cell = field("cell_m"), &of = field("of"), &tracks = field("tracks"), &max = field("max"),
                       &colormap = field("colormap"), &scale = field("scale");
  if (!cell.is_number() || !(cell.get<double>() >= 1.0 && cell.get<double>() <= 100000.0))
    throw std::invalid_argument("its heatmap cell is not 1..100000 m");
  d.cell_m = cell.get<double>();
  const auto measure = of.is_string() ? parse_heatmap_measure(of.get<std::string>()) : std::nullopt;
  if (!measure) throw std::invalid_argument("its heatmap counts neither tracks, thermals nor time");
  d.measure = *measure;
  if (!tracks.is_number_unsigned()) throw std::invalid_argument("its heatmap's \"tracks\" is not a count");
  d.tracks = tracks.get<std::uint64_t>();
  if (!max.is_number_unsigned() || max.get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("its heatmap's \"max\" is not a count");
  d.max_count = max.get<std::uint32_t>();
  if (!colormap.is_string() || !scale.is_string())
    throw std::invalid_argument("its heatmap's \"colormap\" and \"scale\" are not names");
  d.colormap = colormap.get<std::string>();
  d.scale = scale.get<std::string>();
  return d;
}

std::vector<unsigned char> pack_heatmap_tile(const HeatmapCounts::Tile& tile) {
  std::vector<unsigned char> raw(kTileCells * 4);
  for (std::size_t i = 0; i < kTileCells; ++i)
    for (std::size_t b = 0; b < 4; ++b) raw[i * 4 + b] = static_cast<unsigned char>(tile[i] >> (8 * b));
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<unsigned char> packed(size);
  if (compress2(packed.data(), &size, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK)
    throw std::runtime_error("cannot compress a heatmap tile");
  packed.resize(size);
  return packed;
}

HeatmapCounts::Tile unpack_heatmap_tile(std::span<const unsigned char> packed) {
  // Exactly one tile's bytes: uncompress stops at the buffer's end, so a bomb cannot grow it.
  std::vector<unsigned char> raw(kTileCells * 4);
  uLongf size = static_cast<uLongf>(raw.size());
  if (packed.empty() || uncompress(raw.data(), &size, packed.data(), static_cast<uLong>(packed.size())) != Z_OK ||
      size != raw.size())
    throw std::invalid_argument("a damaged heatmap counts tile (not 65,536 zlib-compressed counts)");
  HeatmapCounts::Tile tile;
  for (std::size_t i = 0; i < kTileCells; ++i)
    tile[i] = static_cast<std::uint32_t>(raw[i * 4]) | static_cast<std::uint32_t>(raw[i * 4 + 1]) << 8 |
              static_cast<std::uint32_t>(raw[i * 4 + 2]) << 16 | static_cast<std::uint32_t>(raw[i * 4 + 3]) << 24;
  return tile;
}

std::pair<std::int64_t, std::int64_t> parse_heatmap_tile_key(std::string_view key, std::int64_t tiles_per_side) {
  const auto bad = [&] { return std::invalid_argument("a heatmap counts tile named '" + std::string(key) + "'"); };
  const std::size_t sep = key.find_first_of("/_");
  if (sep == std::string_view::npos) throw bad();
  std::int64_t col = -1, row = -1;
  const char* end = key.data() + key.size();
  const auto c = std::from_chars(key.data(), key.data() + sep, col);
  const auto r = std::from_chars(key.data() + sep + 1, end, row);
  if (c.ec != std::errc{} || c.ptr != key.data() + sep || r.ec != std::errc{} || r.ptr != end || col < 0 || row < 0)
    throw bad();
  if (col >= tiles_per_side || row >= tiles_per_side)
    throw std::invalid_argument("heatmap counts tile " + std::string(key) + " lies outside the grid");
  return {col, row};
}

std::int64_t heatmap_tiles_per_side(const HeatmapCounts& counts) {
  return (counts.cells_per_side() + kHeatmapTileCells - 1) / kHeatmapTileCells;
}

}  // namespace trailray::track
