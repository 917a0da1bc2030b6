#include "terrain/sources/source_factory.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace trailray::terrain {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

SourceKind classify_source(std::string_view spec) {
  if (spec.empty()) throw SourceError("empty terrain/imagery source (give a file, a folder, a URL or `none`)");
  if (spec == "none") return SourceKind::none;
  const std::string l = lower(spec);
  if (l.starts_with("http://") || l.starts_with("https://")) {
    if (l.substr(0, l.find('?')).ends_with("/layer.json")) return SourceKind::quantized_mesh;
    return spec.find('{') == std::string_view::npos ? SourceKind::remote_raster : SourceKind::http;
  }
  // GDAL's virtual file systems: on servers and object stores (even inside /vsizip/) a remote
  // raster; the others (/vsizip/, /vsigzip/, /vsitar/ of a local file) a raster GDAL opens.
  if (l.starts_with("/vsi")) {
    for (const char* network : {"/vsicurl", "/vsis3", "/vsigs", "/vsiaz", "/vsiadls", "/vsioss", "/vsiswift",
                                "/vsiwebhdfs", "/vsihdfs"})
      if (l.find(network) != std::string::npos) return SourceKind::remote_raster;
    return SourceKind::raster;
  }
  const std::filesystem::path path(spec);
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))
    throw SourceError(std::string(spec) + ": no such file or folder (a source is a raster file, a tile folder, an " +
                      ".mbtiles file, an http(s) URL template or `none`)");
  if (std::filesystem::is_directory(status))
    return std::filesystem::is_regular_file(path / "layer.json", ec) ? SourceKind::quantized_mesh : SourceKind::directory;
  if (l.ends_with(".mbtiles")) return SourceKind::mbtiles;
  return SourceKind::raster;
}

std::string remote_raster_path(std::string_view spec) {
  const std::string l = lower(spec);
  if (l.starts_with("http://") || l.starts_with("https://")) return "/vsicurl/" + std::string(spec);
  return std::string(spec);
}

std::optional<HeightEncoding> encoding_from_name(std::string_view spec) {
  const std::string l = lower(spec);
  if (l.find("terrarium") != std::string::npos) return HeightEncoding::terrarium;
  if (l.find("terrain-rgb") != std::string::npos || l.find("terrain_rgb") != std::string::npos ||
      l.find("mapbox") != std::string::npos)
    return HeightEncoding::mapbox;
  if (l.find("alpinemaps") != std::string::npos) return HeightEncoding::alpinemaps;
  return std::nullopt;
}

}  // namespace trailray::terrain
