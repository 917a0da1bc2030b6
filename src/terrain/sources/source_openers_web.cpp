// open_height_source and open_imagery_source in the browser's build: GDAL rasters, MBTiles and
// tile servers are the native program's (libcurl, SQLite and GDAL have no WebAssembly build
// here); the page reaches them through `trailray serve`, which serves any of them as tiles.
// Tile folders in the page's own (in-memory) file system still open.
#include "terrain/sources/directory_source.hpp"
#include "terrain/sources/encoded_sources.hpp"
#include "terrain/sources/source_factory.hpp"

namespace trailray::terrain {
namespace {

[[noreturn]] void not_in_the_browser(const SourceSettings& s) {
  throw SourceError(s.source +
                    ": rasters, MBTiles and tile servers are opened by the native program; run `trailray "
                    "serve --terrain " +
                    s.source + "` and open its page");
}

std::shared_ptr<EncodedTileSource> directory_tiles(const SourceSettings& s) {
  DirectorySourceOptions o;
  o.scheme = s.scheme;
  return std::make_shared<DirectoryTileSource>(s.source, o);
}

}  // namespace

std::unique_ptr<HeightSource> open_height_source(const SourceSettings& s, const SourceContext&) {
  const SourceKind kind = classify_source(s.source);
  if (kind == SourceKind::none) return nullptr;
  if (kind != SourceKind::directory) not_in_the_browser(s);
  auto tiles = directory_tiles(s);
  std::optional<HeightEncoding> encoding = s.encoding;
  if (!encoding && !tiles->info().encoding) encoding = encoding_from_name(s.source).value_or(HeightEncoding::terrarium);
  return std::make_unique<EncodedHeightSource>(std::move(tiles), encoding);
}

std::unique_ptr<ImagerySource> open_imagery_source(const SourceSettings& s, const SourceContext&) {
  const SourceKind kind = classify_source(s.source);
  if (kind == SourceKind::none) return nullptr;
  if (kind != SourceKind::directory) not_in_the_browser(s);
  return std::make_unique<EncodedImagerySource>(directory_tiles(s));
}

}  // namespace trailray::terrain
