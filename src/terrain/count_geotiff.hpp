#pragma once
// A grid of counts (a heatmap) as a GeoTIFF that QGIS and GDAL open as they are: one band,
// UInt32, EPSG:3857 (Web Mercator), the geotransform given, DEFLATE-compressed. Encoded in memory:
// the caller writes the bytes where and how it writes files (atomically).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace trailray::terrain {

// `counts` row by row from the north-west corner (width * height of them). Throws
// std::runtime_error with GDAL's message when GDAL cannot make it.
std::vector<unsigned char> encode_count_geotiff(std::span<const std::uint32_t> counts, std::uint32_t width,
                                                std::uint32_t height, const std::array<double, 6>& geotransform);

}  // namespace trailray::terrain
