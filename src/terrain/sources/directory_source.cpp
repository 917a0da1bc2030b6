#include "terrain/sources/directory_source.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

#include "terrain/sources/encoded_sources.hpp"

namespace trailray::terrain {

namespace fs = std::filesystem;

namespace {

// Nothing stored as one tile is this big; a bigger file is a mistake, not something to load.
constexpr std::uintmax_t kMaxTileFileBytes = 64u << 20;
// Listing the coarsest level for bounds stops after this many files (a folder of millions of
// tiles at its coarsest level has no useful bounds to give anyway).
constexpr std::size_t kMaxFilesListedForBounds = 4096;

const std::vector<std::string> kExtensions = {"png", "webp", "jpg", "jpeg", "tif", "tiff"};

std::optional<std::uint32_t> numeric_name(std::string_view name) {
  if (name.empty() || name.size() > 10 ||
      !std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  std::uint32_t value = 0;
  const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), value);
  if (ec != std::errc{} || end != name.data() + name.size()) return std::nullopt;
  return value;
}

std::string read_text_file(const fs::path& path, const std::string& where) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw SourceError(where + ": cannot read " + path.string());
  return text;
}

// metadata.json values are text (tippecanoe writes "minzoom": "0") or numbers (mb-util copies
// whatever the MBTiles had); bounds may be an array. All become the MBTiles text form.
std::string metadata_text(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_array()) {
    std::string joined;
    for (const auto& item : value) joined += (joined.empty() ? "" : ",") + metadata_text(item);
    return joined;
  }
  return value.dump();
}

void read_metadata_json(const fs::path& file, TileMetadata& metadata) {
  const std::string where = file.string();
  const nlohmann::json json = nlohmann::json::parse(read_text_file(file, where), nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) throw SourceError(where + ": not valid JSON");
  if (!json.is_object()) throw SourceError(where + ": not a JSON object");
  for (const auto& [key, value] : json.items()) metadata.set(key, metadata_text(value), where);
  metadata.check(where);
}

std::vector<int> zoom_folders(const fs::path& root) {
  std::vector<int> zooms;
  std::error_code ec;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    const std::optional<std::uint32_t> z = numeric_name(it->path().filename().string());
    std::error_code type_ec;
    if (z && *z <= static_cast<std::uint32_t>(geo::kMaxTileZoom) && it->is_directory(type_ec))
      zooms.push_back(static_cast<int>(*z));
  }
  if (ec) throw SourceError(root.string() + ": cannot list the folder: " + ec.message());
  std::sort(zooms.begin(), zooms.end());
  return zooms;
}

// The union of the tiles present at `zoom`, and the extension of the first one; nothing when
// there are none or too many to list.
struct LevelListing {
  std::optional<geo::LatLonBounds> bounds;
  std::string first_extension;
};

LevelListing list_level(const fs::path& root, int zoom, TileScheme scheme) {
  LevelListing listing;
  geo::LatLonBounds bounds;
  std::size_t files = 0;
  std::error_code ec;
  const fs::path level = root / std::to_string(zoom);
  for (fs::directory_iterator xi(level, ec), end; !ec && xi != end; xi.increment(ec)) {
    const std::optional<std::uint32_t> x = numeric_name(xi->path().filename().string());
    if (!x) continue;
    std::error_code yec;
    for (fs::directory_iterator yi(xi->path(), yec); !yec && yi != end; yi.increment(yec)) {
      if (++files > kMaxFilesListedForBounds) return {};
      const fs::path name = yi->path().filename();
      const std::optional<std::uint32_t> y = numeric_name(name.stem().string());
      std::string extension = name.extension().string();
      if (!y || extension.size() < 2) continue;
      extension.erase(0, 1);
      if (std::find(kExtensions.begin(), kExtensions.end(), extension) == kExtensions.end()) continue;
      const std::optional<TileId> tile =
          scheme == TileScheme::tms ? geo::tile_from_tms(zoom, *x, *y) : geo::make_tile_id(zoom, *x, *y);
      const std::optional<geo::LatLonBounds> b = tile ? geo::tile_bounds_latlon(*tile) : std::nullopt;
      if (!b) continue;
      bounds.add(b->min_lat, b->min_lon);
      bounds.add(b->max_lat, b->max_lon);
      if (listing.first_extension.empty()) listing.first_extension = extension;
    }
  }
  if (!bounds.empty()) listing.bounds = bounds;
  return listing;
}

// Reads a whole file with POSIX calls, for errno's precise reasons. nullopt when it does not
// exist; throws std::runtime_error (the reason) when it exists but cannot be read.
std::optional<std::vector<unsigned char>> read_tile_file(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT || errno == ENOTDIR) return std::nullopt;
    throw std::runtime_error(std::strerror(errno));
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw std::runtime_error(std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw std::runtime_error("it is a folder");
  if (st.st_size <= 0) throw std::runtime_error("the file is empty");
  if (static_cast<std::uintmax_t>(st.st_size) > kMaxTileFileBytes)
    throw std::runtime_error("the file has " + std::to_string(st.st_size) + " bytes, too many for a tile");
  std::vector<unsigned char> bytes(static_cast<std::size_t>(st.st_size));
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::strerror(errno));
    if (n == 0) break;  // shrank while we read: keep what is there, the decoder will judge it
    got += static_cast<std::size_t>(n);
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace

fs::path tile_relative_path(const TileId& tile, TileScheme scheme, std::string_view extension) {
  const std::uint32_t y = scheme == TileScheme::tms ? tms_y(tile).value_or(tile.y) : tile.y;
  return fs::path(std::to_string(tile.zoom)) / std::to_string(tile.x) /
         (std::to_string(y) + "." + std::string(extension));
}

DirectoryTileSource::DirectoryTileSource(fs::path root, DirectorySourceOptions options) : root_(std::move(root)) {
  info_.name = root_.string();
  std::error_code ec;
  if (!fs::is_directory(root_, ec))
    throw SourceError(info_.name + (fs::exists(root_, ec) ? ": not a folder" : ": no such folder"));

  TileMetadata metadata;
  if (fs::exists(root_ / "metadata.json", ec)) read_metadata_json(root_ / "metadata.json", metadata);
  const bool gdal2tiles = fs::exists(root_ / "tilemapresource.xml", ec);
  scheme_ = options.scheme.value_or(metadata.scheme.value_or(gdal2tiles ? TileScheme::tms : TileScheme::xyz));

  const std::vector<int> zooms = zoom_folders(root_);
  if (zooms.empty()) throw SourceError(info_.name + ": no zoom level folders (0/, 1/, ...) in it: not a tile folder");
  info_.min_zoom = zooms.front();
  info_.max_zoom = zooms.back();
  metadata.apply_to(info_);
  if (info_.min_zoom > info_.max_zoom)
    throw SourceError(info_.name + ": metadata zoom levels " + std::to_string(info_.min_zoom) + ".." +
                      std::to_string(info_.max_zoom) + " are inverted");

  if (!info_.bounds || info_.format.empty()) {
    const LevelListing listing = list_level(root_, info_.min_zoom, scheme_);
    if (!info_.bounds) info_.bounds = listing.bounds;
    if (info_.format.empty()) info_.format = listing.first_extension == "jpeg" ? "jpg" : listing.first_extension;
  }

  // The stated format first (both spellings of JPEG), then any other.
  if (info_.format == "jpg") extensions_ = {"jpg", "jpeg"};
  if (info_.format == "tif") extensions_ = {"tif", "tiff"};
  if (extensions_.empty() && !info_.format.empty()) extensions_ = {info_.format};
  for (const std::string& e : kExtensions)
    if (std::find(extensions_.begin(), extensions_.end(), e) == extensions_.end()) extensions_.push_back(e);
}

EncodedTile DirectoryTileSource::fetch(const TileId& tile, StopToken stop) {
  EncodedTile result;
  if (stop.stop_requested()) {
    result.status = TileStatus::cancelled;
    return result;
  }
  if (!geo::is_valid(tile)) {
    result.status = TileStatus::failed;
    result.error = info_.name + " " + geo::to_string(tile) + ": not a valid tile id";
    return result;
  }
  if (tile.zoom < info_.min_zoom || tile.zoom > info_.max_zoom) return result;  // no_data
  for (const std::string& extension : extensions_) {
    const fs::path path = root_ / tile_relative_path(tile, scheme_, extension);
    try {
      std::optional<std::vector<unsigned char>> bytes = read_tile_file(path);
      if (!bytes) continue;
      result.status = TileStatus::ok;
      result.bytes = std::move(*bytes);
    } catch (const std::exception& e) {
      result.status = TileStatus::failed;
      result.error = info_.name + " " + geo::to_string(tile) + ": cannot read " + path.string() + ": " + e.what();
    }
    return result;
  }
  return result;  // no_data
}

}  // namespace trailray::terrain
