// The heatmap exchange format (track/heatmap_exchange.hpp): what is written reads back the same,
// and damaged input is refused with what is wrong.
#include "track/heatmap_exchange.hpp"

#include <gtest/gtest.h>

#include <zlib.h>

using namespace trailray::track;

TEST(HeatmapExchange, DescriptionsAndTilesReadBackAsWritten) {
  const HeatmapDescription d{80.0, HeatmapMeasure::thermals, 12345678901ull, 4000000000u, "magma", "linear"};
  const HeatmapDescription back = parse_heatmap_description(heatmap_description_json(d));
  EXPECT_EQ(back.cell_m, 80.0);
  EXPECT_EQ(back.measure, HeatmapMeasure::thermals);
  EXPECT_EQ(back.tracks, 12345678901ull);
  EXPECT_EQ(back.max_count, 4000000000u);
  EXPECT_EQ(back.colormap, "magma");
  EXPECT_EQ(back.scale, "linear");
  HeatmapCounts::Tile tile{};
  for (std::size_t i = 0; i < tile.size(); i += 97) tile[i] = static_cast<std::uint32_t>(i * 40503u);
  EXPECT_EQ(unpack_heatmap_tile(pack_heatmap_tile(tile)), tile);
  HeatmapCounts counts(50.0);
  const std::int64_t n = heatmap_tiles_per_side(counts);
  EXPECT_EQ(n, (counts.cells_per_side() + 255) / 256);
  EXPECT_EQ(parse_heatmap_tile_key("1070/725", n), (std::pair<std::int64_t, std::int64_t>{1070, 725}));
  EXPECT_EQ(parse_heatmap_tile_key("3_4", n), (std::pair<std::int64_t, std::int64_t>{3, 4}));
}

TEST(HeatmapExchange, DamagedInputIsRefusedSayingWhat) {
  const auto refused = [](auto&& f, const std::string& what) {
    try {
      f();
      ADD_FAILURE() << "accepted; expected: " << what;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused([] { parse_heatmap_description("not json"); }, "not a JSON object");
  refused([] { parse_heatmap_description(R"({"format": "other"})"); }, "not a trailray heatmap");
  refused([] { parse_heatmap_description(R"({"format": "trailray-heatmap", "cell_m": 50})"); }, "has no \"of\"");
  refused([] {
    parse_heatmap_description(
        R"({"format":"trailray-heatmap","cell_m":0.5,"of":"tracks","tracks":1,"max":1,"colormap":"warm","scale":"log"})");
  }, "1..100000");
  refused([] {
    parse_heatmap_description(
        R"({"format":"trailray-heatmap","cell_m":50,"of":"speed","tracks":1,"max":1,"colormap":"warm","scale":"log"})");
  }, "neither tracks");
  refused([] {
    parse_heatmap_description(
        R"({"format":"trailray-heatmap","cell_m":50,"of":"time","tracks":-3,"max":1,"colormap":"warm","scale":"log"})");
  }, "\"tracks\"");
  // A tile one count short, bytes that are not zlib, and a "bomb" that would inflate to 64 MiB.
  std::vector<unsigned char> raw(65535 * 4, 0), packed(compressBound(static_cast<uLong>(raw.size())));
  uLongf size = static_cast<uLongf>(packed.size());
  ASSERT_EQ(compress(packed.data(), &size, raw.data(), static_cast<uLong>(raw.size())), Z_OK);
  packed.resize(size);
  refused([&] { unpack_heatmap_tile(packed); }, "damaged");
  refused([] { unpack_heatmap_tile(std::vector<unsigned char>{1, 2, 3}); }, "damaged");
  std::vector<unsigned char> big(64u << 20, 0), bomb(compressBound(static_cast<uLong>(big.size())));
  size = static_cast<uLongf>(bomb.size());
  ASSERT_EQ(compress(bomb.data(), &size, big.data(), static_cast<uLong>(big.size())), Z_OK);
  bomb.resize(size);
  refused([&] { unpack_heatmap_tile(bomb); }, "damaged");
  refused([] { parse_heatmap_tile_key("12", 100); }, "named '12'");
  refused([] { parse_heatmap_tile_key("-1/3", 100); }, "named");
  refused([] { parse_heatmap_tile_key("1/2x", 100); }, "named");
  refused([] { parse_heatmap_tile_key("100/3", 100); }, "outside the grid");
}
