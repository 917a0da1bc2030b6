// open_height_source and open_imagery_source of the GPU bundle's program (trailray-gpu,
// scripts/gpu-bundle.sh): tile folders and MBTiles only. A GDAL raster or a tile server would
// bring GDAL's or libcurl's trees of libraries into a bundle that must stay small and run where
// only glibc and a GPU driver are installed. Not part of trailray_terrain: trailray-gpu compiles
// it into itself, so the library's own openers (source_openers.cpp, every kind of source) are
// never linked into it.
#include "terrain/sources/directory_source.hpp"
#include "terrain/sources/encoded_sources.hpp"
#include "terrain/sources/mbtiles_source.hpp"
#include "terrain/sources/source_factory.hpp"

namespace trailray::terrain {
namespace {

std::shared_ptr<EncodedTileSource> tiles_of(const SourceSettings& s) {
  switch (classify_source(s.source)) {
    case SourceKind::directory: {
      DirectorySourceOptions o;
      o.scheme = s.scheme;
      return std::make_shared<DirectoryTileSource>(s.source, o);
    }
    case SourceKind::mbtiles:
      return std::make_shared<MbtilesTileSource>(s.source);
    default:
      throw SourceError(s.source +
                        ": the GPU bundle reads tile folders and .mbtiles files (GDAL rasters and tile servers "
                        "are the full program's: `trailray render` on a machine with trailray installed)");
  }
}

}  // namespace

std::unique_ptr<HeightSource> open_height_source(const SourceSettings& s, const SourceContext&) {
  if (classify_source(s.source) == SourceKind::none) return nullptr;
  auto tiles = tiles_of(s);
  std::optional<HeightEncoding> encoding = s.encoding;
  if (!encoding && !tiles->info().encoding) encoding = encoding_from_name(s.source).value_or(HeightEncoding::terrarium);
  return std::make_unique<EncodedHeightSource>(std::move(tiles), encoding);
}

std::unique_ptr<ImagerySource> open_imagery_source(const SourceSettings& s, const SourceContext&) {
  if (classify_source(s.source) == SourceKind::none) return nullptr;
  return std::make_unique<EncodedImagerySource>(tiles_of(s));
}

CountSource open_count_source(const std::string& path) {
  if (classify_source(path) == SourceKind::raster)
    throw SourceError(path + ": the GPU bundle draws overlays from tile folders and .mbtiles files, not rasters");
  return {};
}

}  // namespace trailray::terrain
