#include "app/pictures/heatmap_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "app/common/output_file.hpp"
#include "geo/web_mercator.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/sources/tile_source.hpp"
#include "terrain/writers/mbtiles_writer.hpp"
#include "track/heatmap_exchange.hpp"
#include "track/heatmap_pixels.hpp"

namespace trailray::app {
namespace fs = std::filesystem;
namespace {

constexpr const char* kMetadataKey = "trailray_heatmap";
constexpr const char* kCountsTable = "trailray_counts";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string without_trailing_slash(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  return path;
}

std::vector<unsigned char> read_file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_file_bytes(const fs::path& file, std::span<const unsigned char> bytes) {
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error(file.string() + ": cannot write");
}

std::vector<unsigned char> tile_png(const track::HeatmapPixels& pixels, const scene::HeatmapPalette& palette) {
  terrain::DecodedImage image;
  image.width = image.height = track::kHeatmapTilePixels;
  image.channels = 4;
  image.samples8.resize(pixels.size() * 4);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const glm::u8vec4 c = scene::heatmap_rgba(palette, pixels[i]);
    std::memcpy(&image.samples8[i * 4], &c, 4);
  }
  return terrain::encode_png(image);
}

// Every coloured tile of the zoom levels, handed to `put` (zoom, x, y, PNG), counted in `written`.
void for_each_coloured_tile(const track::HeatmapCounts& counts, HeatmapWritten& written,
                            const scene::HeatmapPalette& palette, const std::function<void(int)>& progress,
                            const std::function<void(int, std::int64_t, std::int64_t, const std::vector<unsigned char>&)>& put) {
  for (int z = written.min_zoom; z <= written.max_zoom; ++z) {
    if (progress) progress(z);
    for (const auto& [xy, pixels] : track::heatmap_tile_pixels(counts, z)) {
      put(z, xy.first, xy.second, tile_png(pixels, palette));
      ++written.tiles;
    }
  }
}

// The description a heatmap's tile output carries (metadata.json's or the MBTiles metadata's
// trailray_heatmap), as text; nullopt when `path` is not such an output or cannot be read.
std::optional<std::string> description_text(const std::string& path) {
  std::error_code ec;
  try {
    if (fs::is_directory(path, ec)) {
      if (!fs::exists(fs::path(path) / "metadata.json", ec)) return std::nullopt;
      const auto bytes = read_file_bytes(fs::path(path) / "metadata.json");
      const nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
      if (!j.is_object() || !j.contains(kMetadataKey)) return std::nullopt;
      const nlohmann::json& v = j.at(kMetadataKey);
      return v.is_string() ? v.get<std::string>() : v.dump();
    }
    if (!lower(path).ends_with(".mbtiles") || !fs::is_regular_file(path, ec)) return std::nullopt;
    const auto metadata = terrain::read_mbtiles_metadata(path);
    const auto it = metadata.find(kMetadataKey);
    if (it == metadata.end()) return std::nullopt;
    return it->second;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The lon/lat box of the counted cells, for the MBTiles "bounds".
std::string bounds_text(const track::HeatmapCounts& counts) {
  const track::HeatmapWindow w = counts.extent();
  const auto g = counts.geotransform(w);
  const geo::LatLon nw = geo::latlon_from_mercator(g[0], g[3]);
  const geo::LatLon se = geo::latlon_from_mercator(g[0] + g[1] * static_cast<double>(w.width()),
                                                   g[3] + g[5] * static_cast<double>(w.height()));
  return fmt::format("{:.6f},{:.6f},{:.6f},{:.6f}", nw.lon, se.lat, se.lon, nw.lat);
}

}  // namespace

HeatmapOutputKind heatmap_output_kind(const std::string& path) {
  const std::string l = lower(path);
  if (l.ends_with(".tif") || l.ends_with(".tiff")) return HeatmapOutputKind::geotiff;
  if (l.ends_with(".mbtiles")) return HeatmapOutputKind::mbtiles;
  std::error_code ec;
  if (path.ends_with('/') || fs::is_directory(path, ec)) return HeatmapOutputKind::folder;
  throw std::invalid_argument(fmt::format(
      "'{}': a heatmap is written as a GeoTIFF (.tif), an MBTiles file (.mbtiles) or a folder of tiles (a name "
      "ending in /)",
      path));
}

std::string heatmap_measure_title(track::HeatmapMeasure measure) {
  switch (measure) {
    case track::HeatmapMeasure::thermals: return "Flights climbing";
    case track::HeatmapMeasure::time: return "Seconds";
    case track::HeatmapMeasure::tracks: break;
  }
  return "Tracks";
}

HeatmapWritten write_heatmap_tiles(const track::HeatmapCounts& counts, const std::string& path_in,
                                   HeatmapOutputKind kind, HeatmapTileOptions options, bool force,
                                   const std::function<void(int)>& progress) {
  const std::string path = without_trailing_slash(path_in);
  HeatmapWritten written;
  written.min_zoom = options.min_zoom;
  written.max_zoom = options.max_zoom.value_or(track::heatmap_native_zoom(counts.cell_m()));
  if (written.min_zoom < 0 || written.max_zoom > 24 || written.min_zoom > written.max_zoom)
    throw std::invalid_argument(
        fmt::format("zoom levels {}..{}: they must lie in 0..24, the first not above the last", written.min_zoom,
                    written.max_zoom));
  written.max_count = track::heatmap_max(counts);
  options.palette.max_count = std::max<std::uint32_t>(written.max_count, 1);
  const std::string description = track::heatmap_description_json(
      {counts.cell_m(), counts.measure(), counts.tracks(), options.palette.max_count,
       std::string(scene::colormap_name(options.palette.colormap)),
       std::string(scene::heatmap_scale_name(options.palette.scale))});

  std::error_code ec;
  // An empty folder is filled; --force replaces a heatmap written before, never some other
  // folder (a typo must not delete one).
  const bool empty_folder = kind == HeatmapOutputKind::folder && fs::is_directory(path, ec) && fs::is_empty(path, ec);
  if (fs::exists(path, ec) && !empty_folder) {
    if (!force) throw std::runtime_error(path + ": exists (use --force to replace it)");
    if (kind == HeatmapOutputKind::folder && !is_heatmap_tiles(path))
      throw std::runtime_error(path + ": a folder that is not a heatmap's tiles: not replaced (give a new folder)");
  }

  if (kind == HeatmapOutputKind::mbtiles) {
    const std::string temporary = temporary_path_next_to(path);
    try {
      terrain::MbtilesWriter out(temporary);
      out.put_metadata("name", fs::path(path).stem().string());
      out.put_metadata("format", "png");
      out.put_metadata("type", "overlay");
      out.put_metadata("minzoom", std::to_string(written.min_zoom));
      out.put_metadata("maxzoom", std::to_string(written.max_zoom));
      out.put_metadata("bounds", bounds_text(counts));
      out.put_metadata("description", fmt::format("{} per {:g} m cell of {} tracks, by trailray",
                                                  heatmap_measure_title(counts.measure()), counts.cell_m(),
                                                  counts.tracks()));
      out.put_metadata(kMetadataKey, description);
      for_each_coloured_tile(counts, written, options.palette, progress,
                             [&](int z, std::int64_t x, std::int64_t y, const std::vector<unsigned char>& png) {
                               out.put_tile({z, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)}, png);
                             });
      for (const auto& [key, tile] : counts.tiles())
        out.put_extra(kCountsTable, fmt::format("{}/{}", key.first, key.second), track::pack_heatmap_tile(tile));
      out.finish();
      replace_with_temporary(temporary, path);
    } catch (const terrain::SourceError& e) {
      ::unlink(temporary.c_str());
      throw std::runtime_error(path + ": cannot write it: " + e.what());
    } catch (...) {
      ::unlink(temporary.c_str());
      throw;
    }
    return written;
  }

  // A folder: filled under a temporary name beside it, then renamed into place.
  const fs::path target = fs::absolute(path);
  std::string pattern = (target.parent_path() / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error(path + ": cannot make a temporary folder beside it: " + std::strerror(errno));
  const fs::path temporary = pattern;
  try {
    nlohmann::json metadata = {{"name", target.filename().string()},
                               {"format", "png"},
                               {"type", "overlay"},
                               {"scheme", "xyz"},
                               {"minzoom", written.min_zoom},
                               {"maxzoom", written.max_zoom},
                               {"bounds", bounds_text(counts)},
                               {kMetadataKey, description}};
    for_each_coloured_tile(counts, written, options.palette, progress,
                           [&](int z, std::int64_t x, std::int64_t y, const std::vector<unsigned char>& png) {
                             const fs::path file = temporary / std::to_string(z) / std::to_string(x) / (std::to_string(y) + ".png");
                             fs::create_directories(file.parent_path());
                             write_file_bytes(file, png);
                           });
    fs::create_directories(temporary / "counts");
    for (const auto& [key, tile] : counts.tiles())
      write_file_bytes(temporary / "counts" / fmt::format("{}_{}.u32.zlib", key.first, key.second),
                       track::pack_heatmap_tile(tile));
    const std::string text = metadata.dump(2) + "\n";
    write_file_bytes(temporary / "metadata.json", std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
    fs::permissions(temporary, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                   fs::perms::others_read | fs::perms::others_exec);
    if (fs::exists(target, ec)) {
      // The old one out of the way first (rename cannot replace a folder that has files).
      const fs::path old = target.parent_path() / ("." + target.filename().string() + ".old-" + std::to_string(::getpid()));
      fs::rename(target, old);
      fs::rename(temporary, target);
      fs::remove_all(old, ec);
    } else {
      fs::rename(temporary, target);
    }
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(temporary, ec);
    throw std::runtime_error(path + ": " + e.code().message());
  } catch (...) {
    fs::remove_all(temporary, ec);
    throw;
  }
  return written;
}

bool is_heatmap_tiles(const std::string& path) { return description_text(without_trailing_slash(path)).has_value(); }

std::optional<track::HeatmapDescription> describe_heatmap_tiles(const std::string& path) {
  const std::string p = without_trailing_slash(path);
  const std::optional<std::string> text = description_text(p);
  if (!text) return std::nullopt;
  try {
    return track::parse_heatmap_description(*text);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(p + ": " + e.what());
  }
}

track::HeatmapCounts read_heatmap_counts(const std::string& path) {
  const std::string p = without_trailing_slash(path);
  const std::optional<track::HeatmapDescription> d = describe_heatmap_tiles(p);
  if (!d) throw std::runtime_error(p + ": not a heatmap written by trailray (no " + kMetadataKey + " metadata)");
  track::HeatmapCounts counts(d->cell_m, d->measure);
  const std::int64_t tiles = track::heatmap_tiles_per_side(counts);
  std::error_code ec;
  std::string where = p;
  try {
    if (fs::is_directory(p, ec)) {
      for (const auto& entry : fs::directory_iterator(fs::path(p) / "counts")) {
        std::string name = entry.path().filename().string();
        if (!name.ends_with(".u32.zlib")) continue;
        name.resize(name.size() - std::strlen(".u32.zlib"));
        where = entry.path().string();
        const auto [col, row] = track::parse_heatmap_tile_key(name, tiles);
        counts.add_tile(col, row, track::unpack_heatmap_tile(read_file_bytes(entry.path())));
      }
    } else {
      for (const auto& [key, data] : terrain::read_mbtiles_extra(p, kCountsTable)) {
        const auto [col, row] = track::parse_heatmap_tile_key(key, tiles);
        counts.add_tile(col, row, track::unpack_heatmap_tile(data));
      }
    }
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(where + ": " + e.what());
  } catch (const fs::filesystem_error& e) {
    throw std::runtime_error(p + ": cannot read its counts: " + e.code().message());
  } catch (const terrain::SourceError& e) {
    throw std::runtime_error(e.what());
  }
  counts.set_tracks(d->tracks);
  return counts;
}

}  // namespace trailray::app
