// Tile decoding speed: height tiles per second for each encoding (items_per_second), imagery
// tiles per second, on synthetic but realistic tiles -- a smooth mountain field with ridges and
// fine detail, so that the PNG filters and zlib work as hard as on real terrain (the low bytes
// of Terrarium and Mapbox pixels are noise-like) -- and on the real AlpineMaps tiles when
// ../shared/data is present.
//
//   build/bench/terrain_decode_bench --benchmark_repetitions=9 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gdal/cpl_vsi.h>
#include <gdal/gdal.h>

#include "terrain/codecs/height_decode.hpp"
#include "terrain/codecs/image_codec.hpp"

namespace {

using trailray::terrain::DecodedImage;
using trailray::terrain::HeightEncoding;
using trailray::terrain::HeightTile;
using trailray::terrain::TileId;
using Bytes = std::vector<unsigned char>;

constexpr TileId kTile{12, 2138, 1443};

// Heights in metres at (u, v) in [0, 1]^2 of the tile: a massif from ~700 m to ~3300 m, ridges,
// and a few metres of high-frequency roughness.
double mountain(double u, double v) {
  const double dx = u - 0.55, dy = v - 0.45;
  double h = 700.0 + 2600.0 * std::exp(-(dx * dx + dy * dy) * 6.0);
  h += 180.0 * std::abs(std::sin(9.0 * u + 3.0 * v)) - 90.0;  // ridges
  h += 60.0 * std::sin(23.0 * u) * std::cos(19.0 * v);
  h += 3.0 * std::sin(210.0 * u + 0.7) * std::sin(170.0 * v + 0.3);  // rock and forest texture
  return h;
}

HeightTile mountain_tile(std::uint32_t size) {
  HeightTile tile;
  tile.id = kTile;
  tile.width = tile.height = size;
  tile.layout = trailray::terrain::layout_for_size(size);
  const double step = tile.layout == trailray::terrain::SampleLayout::pixel_is_point ? size - 1.0 : size;
  const double offset = tile.layout == trailray::terrain::SampleLayout::pixel_is_point ? 0.0 : 0.5;
  for (std::uint32_t r = 0; r < size; ++r)
    for (std::uint32_t c = 0; c < size; ++c)
      tile.heights.push_back(static_cast<float>(mountain((c + offset) / step, (r + offset) / step)));
  trailray::terrain::update_height_range(tile);
  return tile;
}

// A hillshaded, green-to-grey picture of the mountain with some pixel noise: close to what an
// orthophoto costs a JPEG decoder.
Bytes mountain_jpeg(std::uint32_t size) {
  DecodedImage image;
  image.width = image.height = size;
  image.channels = 3;
  std::uint32_t noise = 12345;
  for (std::uint32_t r = 0; r < size; ++r)
    for (std::uint32_t c = 0; c < size; ++c) {
      const double u = (c + 0.5) / size, v = (r + 0.5) / size, e = 1.0 / size;
      const double slope_x = mountain(u + e, v) - mountain(u - e, v), slope_y = mountain(u, v + e) - mountain(u, v - e);
      const double shade = std::clamp(0.6 - 0.004 * (slope_x - slope_y), 0.1, 1.0);
      const double rock = std::clamp((mountain(u, v) - 1500.0) / 1500.0, 0.0, 1.0);
      noise = noise * 1664525u + 1013904223u;
      const double grain = static_cast<double>(noise >> 24) / 255.0 * 30.0 - 15.0;
      const double rgb[3] = {60 + 120 * rock, 110 + 60 * rock, 50 + 120 * rock};
      for (double channel : rgb)
        image.samples8.push_back(static_cast<std::uint8_t>(std::clamp(channel * shade * 1.6 + grain, 0.0, 255.0)));
    }
  return trailray::terrain::encode_jpeg(image, 85);
}

Bytes read_shared(const std::string& relative) {
  std::ifstream in(std::string(TRAILRAY_SHARED_DATA) + "/" + relative, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void run_height_decode(benchmark::State& state, const Bytes& bytes, HeightEncoding encoding) {
  for (auto _ : state) {
    HeightTile tile = trailray::terrain::decode_height_tile(bytes, encoding, kTile);
    benchmark::DoNotOptimize(tile.heights.data());
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes.size()));
  state.counters["tile_bytes"] = static_cast<double>(bytes.size());
}

void BM_DecodeHeight(benchmark::State& state, HeightEncoding encoding, std::uint32_t size) {
  const Bytes bytes = trailray::terrain::encode_height_tile(mountain_tile(size), encoding);
  run_height_decode(state, bytes, encoding);
}
BENCHMARK_CAPTURE(BM_DecodeHeight, terrarium_256, HeightEncoding::terrarium, 256);
BENCHMARK_CAPTURE(BM_DecodeHeight, mapbox_256, HeightEncoding::mapbox, 256);
BENCHMARK_CAPTURE(BM_DecodeHeight, terrarium_512, HeightEncoding::terrarium, 512);
BENCHMARK_CAPTURE(BM_DecodeHeight, alpinemaps_65, HeightEncoding::alpinemaps, 65);
BENCHMARK_CAPTURE(BM_DecodeHeight, float_tiff_256, HeightEncoding::float32, 256);

void BM_DecodeHeightRealAlpineMaps(benchmark::State& state) {
  const Bytes bytes = read_shared("tiles/alpinemaps/test-tile.png");
  if (bytes.empty()) {
    state.SkipWithError("shared data absent: tiles/alpinemaps/test-tile.png");
    return;
  }
  run_height_decode(state, bytes, HeightEncoding::alpinemaps);
}
BENCHMARK(BM_DecodeHeightRealAlpineMaps);

// The peer: GDAL's PNG driver (libpng underneath, like ours) decoding the same Terrarium bytes
// from memory into three byte planes, plus the same formula: what a GDAL-based tool pays.
void BM_DecodeTerrariumWithGdal(benchmark::State& state) {
  const Bytes bytes = trailray::terrain::encode_height_tile(mountain_tile(256), HeightEncoding::terrarium);
  GDALAllRegister();
  const char* name = "/vsimem/trailray-bench-terrarium.png";
  VSILFILE* f = VSIFileFromMemBuffer(name, const_cast<GByte*>(bytes.data()), bytes.size(), FALSE);
  VSIFCloseL(f);
  std::vector<unsigned char> rgb(256 * 256 * 3);
  std::vector<float> heights(256 * 256);
  int bands[3] = {1, 2, 3};
  for (auto _ : state) {
    GDALDatasetH ds = GDALOpen(name, GA_ReadOnly);
    if (!ds || GDALDatasetRasterIO(ds, GF_Read, 0, 0, 256, 256, rgb.data(), 256, 256, GDT_Byte, 3, bands, 3,
                                   256 * 3, 1) != CE_None) {
      state.SkipWithError("GDAL could not read the tile");
      break;
    }
    GDALClose(ds);
    for (std::size_t i = 0; i < heights.size(); ++i)
      heights[i] = static_cast<float>(rgb[3 * i] * 256.0 + rgb[3 * i + 1] + rgb[3 * i + 2] / 256.0 - 32768.0);
    benchmark::DoNotOptimize(heights.data());
  }
  VSIUnlink(name);
  state.SetItemsProcessed(state.iterations());
  state.counters["tile_bytes"] = static_cast<double>(bytes.size());
}
BENCHMARK(BM_DecodeTerrariumWithGdal);

void run_image_decode(benchmark::State& state, const Bytes& bytes) {
  for (auto _ : state) {
    trailray::terrain::ImageTile tile = trailray::terrain::decode_image_tile(bytes, kTile);
    benchmark::DoNotOptimize(tile.rgba.data());
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes.size()));
  state.counters["tile_bytes"] = static_cast<double>(bytes.size());
}

void BM_DecodeImageryJpeg256(benchmark::State& state) { run_image_decode(state, mountain_jpeg(256)); }
BENCHMARK(BM_DecodeImageryJpeg256);

void BM_DecodeImageryRealOrtho(benchmark::State& state) {
  const Bytes bytes = read_shared("tiles/alpinemaps_ortho/7/69/83.jpg");
  if (bytes.empty()) {
    state.SkipWithError("shared data absent: tiles/alpinemaps_ortho/7/69/83.jpg");
    return;
  }
  run_image_decode(state, bytes);
}
BENCHMARK(BM_DecodeImageryRealOrtho);

}  // namespace
