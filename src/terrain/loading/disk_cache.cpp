#include "terrain/loading/disk_cache.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {
namespace {

namespace fs = std::filesystem;

constexpr unsigned char kMagic[4] = {'T', 'R', 'T', 'C'};
constexpr std::uint16_t kFormatVersion = 1;
constexpr std::uint16_t kFlagNoData = 1;
constexpr const char* kEntryExtension = ".tile";
constexpr const char* kTemporaryMarker = ".tile.tmp-";
// A temporary file this old was left by a writer that crashed (a write takes milliseconds).
constexpr auto kStaleTemporaryAge = std::chrono::hours(1);

void put_u16(std::vector<unsigned char>& out, std::uint16_t v) {
  out.push_back(static_cast<unsigned char>(v & 0xff));
  out.push_back(static_cast<unsigned char>(v >> 8));
}
void put_u32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>((v >> (8 * i)) & 0xff));
}
void put_i64(std::vector<unsigned char>& out, std::int64_t value) {
  const auto v = static_cast<std::uint64_t>(value);
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<unsigned char>((v >> (8 * i)) & 0xff));
}
std::uint16_t get_u16(const unsigned char* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
std::uint32_t get_u32(const unsigned char* p) {
  return std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) | (std::uint32_t{p[3]} << 24);
}
std::int64_t get_i64(const unsigned char* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return static_cast<std::int64_t>(v);
}

std::uint32_t crc32_of(std::span<const unsigned char> bytes, std::uint32_t crc = 0) {
  return static_cast<std::uint32_t>(crc32_z(crc, bytes.data(), bytes.size()));
}

// A string that fits the header, or "" (a dropped ETag only costs a full download later).
std::string_view storable(const std::string& text) {
  return text.size() <= DiskCache::kMaxStringBytes ? std::string_view(text) : std::string_view();
}

std::vector<unsigned char> encode_header(const CacheEntryInfo& info, std::span<const unsigned char> payload) {
  const std::string_view etag = storable(info.etag), modified = storable(info.last_modified),
                         type = storable(info.content_type);
  std::vector<unsigned char> out;
  out.reserve(DiskCache::kFixedHeaderBytes + etag.size() + modified.size() + type.size());
  out.insert(out.end(), std::begin(kMagic), std::end(kMagic));
  put_u16(out, kFormatVersion);
  put_u16(out, info.no_data ? kFlagNoData : 0);
  put_u32(out, static_cast<std::uint32_t>(payload.size()));
  put_u32(out, crc32_of(payload));
  put_i64(out, info.fetched_at);
  put_i64(out, info.expires_at);
  put_u16(out, static_cast<std::uint16_t>(etag.size()));
  put_u16(out, static_cast<std::uint16_t>(modified.size()));
  put_u16(out, static_cast<std::uint16_t>(type.size()));
  put_u16(out, 0);
  std::uint32_t header_crc = crc32_of(out);
  for (std::string_view s : {etag, modified, type}) {
    header_crc = crc32_of({reinterpret_cast<const unsigned char*>(s.data()), s.size()}, header_crc);
  }
  put_u32(out, header_crc);
  for (std::string_view s : {etag, modified, type}) out.insert(out.end(), s.begin(), s.end());
  return out;
}

// The entry in `file`, or nullopt when any check fails.
std::optional<CacheEntry> decode_entry(std::span<const unsigned char> file) {
  constexpr std::size_t fixed = DiskCache::kFixedHeaderBytes;
  if (file.size() < fixed || !std::equal(std::begin(kMagic), std::end(kMagic), file.begin())) return std::nullopt;
  const unsigned char* p = file.data();
  if (get_u16(p + 4) != kFormatVersion) return std::nullopt;
  const std::uint16_t flags = get_u16(p + 6);
  const std::uint32_t payload_length = get_u32(p + 8), payload_crc = get_u32(p + 12);
  const std::size_t lengths[3] = {get_u16(p + 32), get_u16(p + 34), get_u16(p + 36)};
  const std::size_t strings = lengths[0] + lengths[1] + lengths[2];
  if (file.size() != fixed + strings + payload_length) return std::nullopt;
  if (crc32_of(file.subspan(fixed, strings), crc32_of(file.first(40))) != get_u32(p + 40)) return std::nullopt;
  const std::span<const unsigned char> payload = file.subspan(fixed + strings);
  if (crc32_of(payload) != payload_crc) return std::nullopt;

  CacheEntry entry;
  entry.info.no_data = (flags & kFlagNoData) != 0;
  entry.info.fetched_at = get_i64(p + 16);
  entry.info.expires_at = get_i64(p + 24);
  const char* text = reinterpret_cast<const char*>(p + fixed);
  entry.info.etag.assign(text, lengths[0]);
  entry.info.last_modified.assign(text + lengths[0], lengths[1]);
  entry.info.content_type.assign(text + lengths[0] + lengths[1], lengths[2]);
  entry.payload.assign(payload.begin(), payload.end());
  return entry;
}

bool write_all(int fd, std::span<const unsigned char> bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes = bytes.subspan(static_cast<std::size_t>(n));
  }
  return true;
}

bool read_all(int fd, std::span<unsigned char> bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::read(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;  // an error, or the file shrank under us
    bytes = bytes.subspan(static_cast<std::size_t>(n));
  }
  return true;
}

std::string temporary_name(const fs::path& entry) {
  // Unique per process (pid) and per write in it (counter): two writers never share a file.
  static std::atomic<std::uint64_t> counter{0};
  return entry.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

std::uint64_t fnv1a64(std::string_view text) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

}  // namespace

fs::path DiskCache::default_folder() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  // The XDG spec: a relative path in XDG_CACHE_HOME is invalid and is ignored.
  if (xdg != nullptr && xdg[0] == '/') return fs::path(xdg) / "trailray" / "tiles";
  const char* home = std::getenv("HOME");
  if (home == nullptr || home[0] == '\0') {
    const passwd* user = ::getpwuid(::getuid());
    home = user != nullptr ? user->pw_dir : nullptr;
  }
  if (home == nullptr || home[0] == '\0') {
    throw SourceError("tile cache: no folder for it (neither XDG_CACHE_HOME nor a home folder is set)");
  }
  return fs::path(home) / ".cache" / "trailray" / "tiles";
}

std::string DiskCache::namespace_for(std::string_view url_template) {
  std::string_view rest = url_template;
  if (const std::size_t scheme = rest.find("://"); scheme != std::string_view::npos) rest.remove_prefix(scheme + 3);
  rest = rest.substr(0, rest.find('?'));
  std::string slug;
  bool in_placeholder = false;
  for (char c : rest) {
    if (c == '{') in_placeholder = true;
    if (in_placeholder) {
      in_placeholder = c != '}';
      continue;
    }
    if (c == '$') continue;
    const bool keep = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z');
    if (keep) {
      slug.push_back(c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c);
    } else if (!slug.empty() && slug.back() != '-') {
      slug.push_back('-');
    }
    if (slug.size() >= 48) break;
  }
  while (!slug.empty() && slug.back() == '-') slug.pop_back();
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a64(url_template)));
  return (slug.empty() ? std::string() : slug + "-") + std::string(hash, 12);
}

std::size_t DiskCache::overhead_bytes(const CacheEntryInfo& info) {
  return kFixedHeaderBytes + storable(info.etag).size() + storable(info.last_modified).size() +
         storable(info.content_type).size();
}

DiskCache::DiskCache(std::string_view source_key, DiskCacheOptions options)
    : folder_(options.folder.empty() ? default_folder() : options.folder), max_bytes_(options.max_bytes) {
  namespace_folder_ = folder_ / namespace_for(source_key);
  std::error_code ec;
  fs::create_directories(namespace_folder_, ec);
  if (ec) throw SourceError("tile cache " + namespace_folder_.string() + ": cannot create the folder: " + ec.message());
  std::uint64_t total = 0;
  for (const ScannedEntry& entry : scan_folder(true)) total += entry.size;
  total_bytes_ = total;
  evict_if_over_limit();
}

fs::path DiskCache::entry_path(const TileId& tile) const {
  return namespace_folder_ / std::to_string(tile.zoom) / std::to_string(tile.x) /
         (std::to_string(tile.y) + kEntryExtension);
}

std::uint64_t DiskCache::total_bytes() const {
  std::lock_guard lock(total_mutex_);
  return total_bytes_;
}

std::uint64_t DiskCache::damaged_entries_removed() const {
  std::lock_guard lock(total_mutex_);
  return damaged_removed_;
}

void DiskCache::add_to_total(std::int64_t delta) {
  std::lock_guard lock(total_mutex_);
  if (delta < 0 && static_cast<std::uint64_t>(-delta) > total_bytes_) {
    total_bytes_ = 0;
  } else {
    total_bytes_ = static_cast<std::uint64_t>(static_cast<std::int64_t>(total_bytes_) + delta);
  }
}

std::optional<CacheEntry> DiskCache::read(const TileId& tile) {
  if (!is_valid(tile)) return std::nullopt;
  const fs::path path = entry_path(tile);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return std::nullopt;
  }
  const auto size = static_cast<std::uint64_t>(st.st_size);
  std::optional<CacheEntry> entry;
  if (size >= kFixedHeaderBytes && size <= kFixedHeaderBytes + 3 * kMaxStringBytes + kMaxPayloadBytes) {
    std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
    if (read_all(fd, bytes)) entry = decode_entry(bytes);
  }
  if (entry) {
    ::futimens(fd, nullptr);  // used now: the last to be evicted
    ::close(fd);
    return entry;
  }
  ::close(fd);
  // Damaged: remove it, unless another writer has meanwhile renamed a new entry over it.
  struct stat now {};
  if (::stat(path.c_str(), &now) == 0 && now.st_ino == st.st_ino && now.st_dev == st.st_dev &&
      ::unlink(path.c_str()) == 0) {
    add_to_total(-static_cast<std::int64_t>(size));
    std::lock_guard lock(total_mutex_);
    ++damaged_removed_;
  }
  return std::nullopt;
}

std::string DiskCache::write(const TileId& tile, const CacheEntryInfo& info, std::span<const unsigned char> payload) {
  const fs::path path = entry_path(tile);
  auto failure = [&](const std::string& what) { return "tile cache " + path.string() + ": " + what; };
  if (!is_valid(tile)) return failure("not a valid tile id");
  if (payload.size() > kMaxPayloadBytes) return failure("payload too large to cache");
  const std::vector<unsigned char> header = encode_header(info, payload);

  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec) return failure("cannot create the folder: " + ec.message());
  const fs::path temporary = path.parent_path() / temporary_name(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return failure(std::string("cannot create a temporary file: ") + std::strerror(errno));
  bool written = write_all(fd, header) && write_all(fd, payload) && ::fsync(fd) == 0;
  int write_errno = written ? 0 : errno;
  if (::close(fd) != 0 && written) {
    written = false;
    write_errno = errno;
  }
  if (!written) {
    ::unlink(temporary.c_str());
    // errno 0: write() returned 0 bytes, which only a full device does.
    return failure(std::string("cannot write: ") + std::strerror(write_errno != 0 ? write_errno : ENOSPC));
  }
  struct stat old {};
  const std::uint64_t old_size = ::stat(path.c_str(), &old) == 0 ? static_cast<std::uint64_t>(old.st_size) : 0;
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlink(temporary.c_str());
    return failure(std::string("cannot rename the temporary file: ") + std::strerror(rename_errno));
  }
  add_to_total(static_cast<std::int64_t>(header.size() + payload.size()) - static_cast<std::int64_t>(old_size));
  evict_if_over_limit();
  return {};
}

void DiskCache::remove(const TileId& tile) {
  if (!is_valid(tile)) return;
  const fs::path path = entry_path(tile);
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && ::unlink(path.c_str()) == 0)
    add_to_total(-static_cast<std::int64_t>(st.st_size));
}

std::vector<DiskCache::ScannedEntry> DiskCache::scan_folder(bool remove_stale_temporaries) const {
  std::vector<ScannedEntry> entries;
  std::error_code ec;
  fs::recursive_directory_iterator it(folder_, fs::directory_options::skip_permission_denied, ec);
  const auto now = fs::file_time_type::clock::now();
  // Every call takes an error_code: files and folders may vanish under the scan (another
  // process evicting); such an entry is skipped, and a failed step ends the scan early.
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    std::error_code entry_ec;
    if (!it->is_regular_file(entry_ec)) continue;
    const fs::path& path = it->path();
    const std::string name = path.filename().string();
    const auto mtime = it->last_write_time(entry_ec);
    if (entry_ec) continue;
    if (name.find(kTemporaryMarker) != std::string::npos) {
      if (remove_stale_temporaries && now - mtime > kStaleTemporaryAge) fs::remove(path, entry_ec);
      continue;
    }
    if (path.extension() != kEntryExtension) continue;
    const std::uint64_t size = it->file_size(entry_ec);
    if (entry_ec) continue;
    entries.push_back({mtime, size, path});
  }
  return entries;
}

void DiskCache::evict_if_over_limit() {
  if (total_bytes() <= max_bytes_) return;
  std::unique_lock eviction(eviction_mutex_, std::try_to_lock);
  if (!eviction.owns_lock()) return;  // another thread is at it
  std::vector<ScannedEntry> entries = scan_folder(false);
  std::sort(entries.begin(), entries.end(), [](const ScannedEntry& a, const ScannedEntry& b) {
    return a.last_used != b.last_used ? a.last_used < b.last_used : a.path < b.path;
  });
  std::uint64_t total = 0;
  for (const ScannedEntry& entry : entries) total += entry.size;
  const std::uint64_t target = max_bytes_ / 10 * 9;
  for (const ScannedEntry& entry : entries) {
    if (total <= target) break;
    std::error_code ec;
    fs::remove(entry.path, ec);  // gone already (evicted by another process) is as good
    total -= entry.size;
  }
  std::lock_guard lock(total_mutex_);
  total_bytes_ = total;
}

}  // namespace trailray::terrain
