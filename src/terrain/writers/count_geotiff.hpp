#pragma once
// A grid of counts (a heatmap) as a GeoTIFF that QGIS and GDAL open as they are: one band,
// UInt32, EPSG:3857 (Web Mercator), the geotransform given, DEFLATE-compressed. Encoded in memory:
// the caller writes the bytes where and how it writes files (atomically).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace trailray::terrain {

// `counts` row by row from the north-west corner (width * height of them); `what` names the band
// (the heatmap's measure: "tracks", "thermals", "time"). Throws std::runtime_error with GDAL's
// message when GDAL cannot make it.
std::vector<unsigned char> encode_count_geotiff(std::span<const std::uint32_t> counts, std::uint32_t width,
                                                std::uint32_t height, const std::array<double, 6>& geotransform,
                                                std::string_view what = "tracks");

// A raster of counts as --overlay sees one: a single band of integers wider than a byte or of
// floats (a single 8-bit band is a gray image, not counts).
struct CountRaster {
  double maximum = 0.0;  // the band's largest value (read exactly, the whole band)
  std::string what;      // the band's description ("tracks" in ours), empty when none
  double cell_m = 0.0;   // the pixel width in the raster's own units (metres in EPSG:3857)
};
// nullopt for any other raster. Throws SourceError naming `path` when GDAL cannot open it.
std::optional<CountRaster> describe_count_raster(const std::string& path);

}  // namespace trailray::terrain
