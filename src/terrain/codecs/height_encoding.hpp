#pragma once
// How heights are packed into the pixels of image tiles, and decoding them.

#include <optional>
#include <string>
#include <string_view>

namespace trailray::terrain {

enum class HeightEncoding {
  terrarium,   // h = R*256 + G + B/256 - 32768 (Mapzen / AWS terrain tiles)
  mapbox,      // h = -10000 + (R*65536 + G*256 + B) * 0.1 (Mapbox terrain-RGB, MapTiler)
  alpinemaps,  // h = (R*256 + G) / 8 (AlpineMaps, 65 x 65 samples, pixel-is-point)
  float32,     // a single-band float raster (GDAL, float TIFF tiles): the value is the height
};

// "terrarium", "mapbox" (also "terrain-rgb", "mapbox-terrain-rgb"), "alpinemaps", "float".
std::optional<HeightEncoding> parse_height_encoding(std::string_view name);
std::string_view to_string(HeightEncoding encoding);

// Heights outside this range cannot be real (the Dead Sea shore is at -430 m, Everest 8849 m,
// the deepest ocean -10994 m): a tile full of them was probably decoded with the wrong encoding.
inline constexpr float kPlausibleMinHeightM = -11000.0f;
inline constexpr float kPlausibleMaxHeightM = 9000.0f;

}  // namespace trailray::terrain
