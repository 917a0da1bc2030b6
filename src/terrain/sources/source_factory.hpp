#pragma once
// Turns a source as the user spells it (DESIGN.md "Terrain sources": --terrain / --imagery or
// the config file) into a HeightSource or an ImagerySource:
//   none                     -> no source (nullptr)
//   http://... / https://... -> HttpTileSource (URL template, disk cache) + decoder; a URL
//                               without placeholders is one remote raster (below)
//   /vsicurl/..., /vsis3/... -> a remote raster: one file (a Cloud-Optimized GeoTIFF at best)
//                               read through GDAL's range requests, only the blocks needed
//   *.mbtiles                -> MbtilesTileSource + decoder
//   a folder                 -> DirectoryTileSource ({z}/{x}/{y}.png|webp|jpg) + decoder
//   a folder with layer.json, or an http(s) URL of a layer.json
//                            -> QuantizedMeshSource (Cesium quantized-mesh terrain)
//   any other file           -> a GDAL raster (GeoTIFF, .hgt, VRT, .img, ...; any CRS)

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "terrain/sources/terrain_config.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

enum class SourceKind { none, http, mbtiles, directory, raster, remote_raster, quantized_mesh };

// What `spec` names, from its spelling and (for paths) what is on disk. Throws SourceError for
// an empty spec or a path that does not exist.
SourceKind classify_source(std::string_view spec);

// The path GDAL opens for a remote raster: "/vsicurl/" before an http(s) URL, a GDAL virtual
// path (/vsicurl/, /vsis3/, /vsigs/, /vsiaz/, ...) as it is.
std::string remote_raster_path(std::string_view spec);

struct SourceContext {
  NetworkSettings network;
  CacheSettings cache;
  std::function<void(std::string)> warn;  // one-off warnings (server unreachable, ...); may be empty
};

// Throws SourceError (naming the source) when it cannot be opened.
std::unique_ptr<HeightSource> open_height_source(const SourceSettings& settings, const SourceContext& context);
std::unique_ptr<ImagerySource> open_imagery_source(const SourceSettings& settings, const SourceContext& context);

// A raster of counts (count_geotiff.hpp's CountRaster: one band wider than a byte) opened for
// --overlay: its values warped with the largest under each pixel (GdalResampling::max), and what
// it holds. nullptr when `path` is a raster of another kind, or not a raster (a tile folder, an
// .mbtiles file, a URL): imagery then. Throws SourceError for a raster GDAL cannot open (and in
// the GPU bundle, which has no GDAL, for any raster).
struct CountSource {
  std::unique_ptr<HeightSource> values;
  double maximum = 0.0;
  std::string what;   // the band's description
  double cell_m = 0;  // its pixel width
};
CountSource open_count_source(const std::string& path);

// The encoding a tile source's name suggests ("terrarium", "terrain-rgb"/"mapbox", "alpinemaps"
// in a URL or path), when it suggests one.
std::optional<HeightEncoding> encoding_from_name(std::string_view spec);

}  // namespace trailray::terrain
