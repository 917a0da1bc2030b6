#pragma once
// Test helpers for the HTTP tile source: a tile server on 127.0.0.1 with fault routes, a "black
// hole" that accepts connections and never answers, and PNG bytes made on the spot.
//
// The server is a small HTTP/1.1 server on plain sockets (keep-alive, GET only), not
// cpp-httplib: Debian's libcpp-httplib-dev ships httplib.h as declarations for a compiled
// libcpp-httplib.so, which the test and bench targets do not link. Owning the socket code also
// lets a route do what a library would not, such as stall without answering.
//
// Routes (z/x/y.png at the end of each):
//   /tiles/    a 256 x 256 PNG (from the folder given, else generated from z, x, y); with
//              set_cache_control / set_etags / add_tile_header, those headers, and 304 to a
//              matching If-None-Match
//   /corrupt/  200 with bytes that are not an image
//   /wrongsize/ 200 with a valid PNG of 100 x 37
//   /missing/  404                  /empty/  204
//   /flaky/    set_fail_count(n): each path answers 503 n times, then the PNG
//   /fail/<status>/  always that status (e.g. /fail/503/..., /fail/403/...)
//   /nostore/  the PNG with Cache-Control: no-store
//   /slow/     answers only after release_slow() or stop()
// and files (serve_file): /files/NAME with HTTP range requests (206 Partial Content, as object
// stores and static file servers answer), /norange/NAME always whole (200, Range ignored).
// HEAD is answered too (the headers of the GET, no body).
// Every request is counted (by path prefix too), with the headers and target of the last one,
// and the largest number of requests being handled at once.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "unique_temp_dir.hpp"

namespace trailray::test::http {

// --- PNG bytes -------------------------------------------------------------------------------

inline void append_be32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>((v >> shift) & 0xff));
}

inline void append_png_chunk(std::vector<unsigned char>& out, const char* type, std::span<const unsigned char> data) {
  append_be32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t type_at = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  const auto crc = crc32_z(0, out.data() + type_at, out.size() - type_at);
  append_be32(out, static_cast<std::uint32_t>(crc));
}

// An 8-bit RGB PNG: a gradient that depends on `seed` plus a little noise, so that tiles differ
// and compress about as badly as real terrain tiles do.
inline std::vector<unsigned char> make_png(std::uint32_t width, std::uint32_t height, std::uint32_t seed = 0) {
  std::vector<unsigned char> raw;
  raw.reserve(static_cast<std::size_t>(height) * (1 + 3 * std::size_t{width}));
  std::uint32_t noise = seed * 2654435761u + 1;
  for (std::uint32_t y = 0; y < height; ++y) {
    raw.push_back(0);  // filter: none
    for (std::uint32_t x = 0; x < width; ++x) {
      noise = noise * 1664525u + 1013904223u;
      raw.push_back(static_cast<unsigned char>((x + seed) & 0xff));
      raw.push_back(static_cast<unsigned char>((y + (seed >> 8)) & 0xff));
      raw.push_back(static_cast<unsigned char>((noise >> 24) & 0x0f));
    }
  }
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<unsigned char> packed(packed_size);
  if (compress2(packed.data(), &packed_size, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK) {
    throw std::runtime_error("make_png: zlib failed");
  }
  packed.resize(packed_size);

  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<unsigned char> header;
  append_be32(header, width);
  append_be32(header, height);
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, no filter set, no interlace
  append_png_chunk(png, "IHDR", header);
  append_png_chunk(png, "IDAT", packed);
  append_png_chunk(png, "IEND", {});
  return png;
}

struct PngSize {
  std::uint32_t width = 0, height = 0;
};

// Width and height from a PNG's signature and IHDR chunk; nullopt for anything else.
inline std::optional<PngSize> png_size(std::span<const unsigned char> bytes) {
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 24 || !std::equal(std::begin(kSignature), std::end(kSignature), bytes.begin()))
    return std::nullopt;
  if (std::string_view(reinterpret_cast<const char*>(bytes.data() + 12), 4) != "IHDR") return std::nullopt;
  auto be32 = [&](std::size_t at) {
    return (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
           (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
  };
  return PngSize{be32(16), be32(20)};
}

// A fresh folder under the system's temporary folder, removed with everything in it at scope end.
class TempFolder {
 public:
  TempFolder() {
    path_ = make_unique_temp_dir("trailray-http-test-");
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Files under `folder` whose name contains `part` (".tile", ".tmp-").
inline std::vector<std::filesystem::path> files_containing(const std::filesystem::path& folder, std::string_view part) {
  std::vector<std::filesystem::path> found;
  std::error_code ec;
  for (std::filesystem::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file() && it->path().filename().string().find(part) != std::string::npos) {
      found.push_back(it->path());
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

// --- sockets ---------------------------------------------------------------------------------

// A TCP socket listening on 127.0.0.1 at a port the kernel picks.
inline int listen_on_loopback(int& port, int backlog) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw std::runtime_error("test server: socket() failed");
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  socklen_t length = sizeof address;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(fd, backlog) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    ::close(fd);
    throw std::runtime_error("test server: cannot listen on 127.0.0.1");
  }
  port = ntohs(address.sin_port);
  return fd;
}

// Accepts TCP connections (the kernel completes the handshake into the backlog) and never reads
// or answers: a server that hangs.
class BlackHoleServer {
 public:
  BlackHoleServer() { fd_ = listen_on_loopback(port_, 64); }
  ~BlackHoleServer() { ::close(fd_); }
  BlackHoleServer(const BlackHoleServer&) = delete;
  BlackHoleServer& operator=(const BlackHoleServer&) = delete;
  int port() const { return port_; }
  std::string url(std::string_view path) const {
    return "http://127.0.0.1:" + std::to_string(port_) + std::string(path);
  }

 private:
  int fd_ = -1;
  int port_ = 0;
};

// --- the tile server -------------------------------------------------------------------------

class LocalTileServer {
 public:
  using Headers = std::map<std::string, std::string>;  // lowercase names

  explicit LocalTileServer(std::filesystem::path tile_folder = {}) : tile_folder_(std::move(tile_folder)) {
    listen_fd_ = listen_on_loopback(port_, 128);
    acceptor_ = std::thread([this] { accept_loop(); });
  }
  ~LocalTileServer() { stop(); }
  LocalTileServer(const LocalTileServer&) = delete;
  LocalTileServer& operator=(const LocalTileServer&) = delete;

  // Closes the listening socket and every connection, and waits for the threads: afterwards a
  // connection to the port is refused. Idempotent.
  void stop() {
    if (stopping_.exchange(true)) return;
    if (acceptor_.joinable()) acceptor_.join();
    ::close(listen_fd_);
    std::vector<std::thread> connections;
    {
      std::lock_guard lock(mutex_);
      connections.swap(connections_);
    }
    for (std::thread& t : connections) t.join();
  }

  int port() const { return port_; }
  std::string url(std::string_view path) const {
    return "http://127.0.0.1:" + std::to_string(port_) + std::string(path);
  }

  void set_cache_control(std::string value) {
    std::lock_guard lock(mutex_);
    cache_control_ = std::move(value);
  }
  // Sent as well with every /tiles/ answer (Expires, Date, ...).
  void add_tile_header(std::string name, std::string value) {
    std::lock_guard lock(mutex_);
    extra_tile_headers_.emplace_back(std::move(name), std::move(value));
  }
  void set_etags(bool on) { etags_ = on; }
  void set_fail_count(int count) { fail_count_ = count; }
  // Each request is held this long before it is answered (to make requests overlap).
  void set_delay(std::chrono::milliseconds delay) { delay_ms_ = static_cast<int>(delay.count()); }
  void release_slow() { slow_released_ = true; }
  // Serves the file at `path` as /files/NAME and /norange/NAME.
  void serve_file(const std::string& name, const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes(std::istreambuf_iterator<char>(in), {});
    std::lock_guard lock(mutex_);
    files_[name] = std::move(bytes);
  }
  // Body bytes sent so far (GET answers), all routes together.
  std::size_t body_bytes_sent() const { return body_bytes_sent_; }

  int request_count() const { return requests_; }
  int request_count(std::string_view path_prefix) const {
    std::lock_guard lock(mutex_);
    int n = 0;
    for (const auto& [target, count] : per_target_) n += target.starts_with(path_prefix) ? count : 0;
    return n;
  }
  int not_modified_count() const { return not_modified_; }
  int max_concurrency() const { return max_in_flight_; }
  Headers last_request_headers() const {
    std::lock_guard lock(mutex_);
    return last_headers_;
  }
  std::string last_request_target() const {
    std::lock_guard lock(mutex_);
    return last_target_;
  }
  // The body /tiles/ serves for a tile.
  std::vector<unsigned char> tile_bytes(int z, std::uint32_t x, std::uint32_t y) const {
    if (tile_folder_.empty()) {
      // Made once per tile (deflate takes milliseconds): a benchmark measures the client.
      const std::string key = std::to_string(z) + "/" + std::to_string(x) + "/" + std::to_string(y);
      std::lock_guard lock(mutex_);
      auto [it, added] = generated_.try_emplace(key);
      if (added) it->second = make_png(256, 256, (x * 7919u) ^ (y * 104729u) ^ static_cast<std::uint32_t>(z));
      return it->second;
    }
    for (const char* extension : {".png", ".jpg", ".jpeg", ".webp"}) {
      const auto path = tile_folder_ / std::to_string(z) / std::to_string(x) / (std::to_string(y) + extension);
      std::ifstream in(path, std::ios::binary);
      if (in) return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
    }
    return {};
  }

 private:
  struct Response {
    int status = 200;
    std::vector<unsigned char> body;
    std::vector<std::pair<std::string, std::string>> headers;
  };

  void accept_loop() {
    while (!stopping_) {
      pollfd p{listen_fd_, POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
      if (fd < 0) continue;
      std::lock_guard lock(mutex_);
      connections_.emplace_back([this, fd] { serve_connection(fd); });
    }
  }

  // Reads until "\r\n\r\n"; false when the peer closed or the server is stopping.
  bool read_request_head(int fd, std::string& buffer, std::string& head) {
    for (;;) {
      if (const std::size_t end = buffer.find("\r\n\r\n"); end != std::string::npos) {
        head = buffer.substr(0, end);
        buffer.erase(0, end + 4);
        return true;
      }
      if (stopping_) return false;
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      char chunk[4096];
      const ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
      if (n <= 0) return false;
      buffer.append(chunk, static_cast<std::size_t>(n));
    }
  }

  static bool send_all(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
      const ssize_t n = ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
      if (n <= 0) return false;
      bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
  }

  void serve_connection(int fd) {
    std::string buffer, head;
    while (read_request_head(fd, buffer, head)) {
      const std::size_t line_end = head.find("\r\n");
      const std::string request_line = head.substr(0, line_end);
      const std::size_t space1 = request_line.find(' '), space2 = request_line.rfind(' ');
      if (space1 == std::string::npos || space2 <= space1) break;
      const std::string target = request_line.substr(space1 + 1, space2 - space1 - 1);
      const bool head_only = request_line.starts_with("HEAD ");
      Headers headers;
      std::size_t at = line_end == std::string::npos ? head.size() : line_end + 2;
      while (at < head.size()) {
        std::size_t next = head.find("\r\n", at);
        if (next == std::string::npos) next = head.size();
        const std::string line = head.substr(at, next - at);
        if (const std::size_t colon = line.find(':'); colon != std::string::npos) {
          std::string name = line.substr(0, colon);
          for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
          std::size_t value_at = colon + 1;
          while (value_at < line.size() && line[value_at] == ' ') ++value_at;
          headers[name] = line.substr(value_at);
        }
        at = next + 2;
      }
      const Response response = handle(target, headers);
      std::string out = "HTTP/1.1 " + std::to_string(response.status) + " " + reason(response.status) + "\r\n";
      out += "Content-Length: " + std::to_string(response.body.size()) + "\r\n";
      for (const auto& [name, value] : response.headers) out += name + ": " + value + "\r\n";
      out += "\r\n";
      if (!head_only) {
        out.append(response.body.begin(), response.body.end());
        body_bytes_sent_ += response.body.size();
      }
      if (!send_all(fd, out)) break;
      if (headers["connection"] == "close") break;
    }
    ::close(fd);
  }

  static std::string reason(int status) {
    switch (status) {
      case 200:
        return "OK";
      case 204:
        return "No Content";
      case 206:
        return "Partial Content";
      case 416:
        return "Range Not Satisfiable";
      case 304:
        return "Not Modified";
      case 403:
        return "Forbidden";
      case 404:
        return "Not Found";
      case 503:
        return "Service Unavailable";
      default:
        return "Status";
    }
  }

  // "/<route>/.../z/x/y.ext[?query]" -> route, z, x, y.
  struct Target {
    std::string route;
    int status_override = 0;  // /fail/<status>/
    int z = -1;
    std::uint32_t x = 0, y = 0;
  };
  static std::optional<Target> parse_target(std::string path) {
    path = path.substr(0, path.find('?'));
    std::vector<std::string> parts;
    for (std::size_t at = 1; at <= path.size();) {
      std::size_t slash = path.find('/', at);
      if (slash == std::string::npos) slash = path.size();
      parts.push_back(path.substr(at, slash - at));
      at = slash + 1;
    }
    if (parts.size() < 4) return std::nullopt;
    Target t;
    t.route = parts[0];
    if (t.route == "fail") t.status_override = std::atoi(parts[1].c_str());
    const std::size_t n = parts.size();
    const std::string y = parts[n - 1].substr(0, parts[n - 1].find('.'));
    t.z = std::atoi(parts[n - 3].c_str());
    t.x = static_cast<std::uint32_t>(std::strtoul(parts[n - 2].c_str(), nullptr, 10));
    t.y = static_cast<std::uint32_t>(std::strtoul(y.c_str(), nullptr, 10));
    return t;
  }

  static std::string etag_of(std::span<const unsigned char> body) {
    return "\"" + std::to_string(crc32_z(0, body.data(), body.size())) + "-" + std::to_string(body.size()) + "\"";
  }

  Response handle(const std::string& target, const Headers& headers) {
    const int in_flight = ++in_flight_;
    for (int seen = max_in_flight_; in_flight > seen && !max_in_flight_.compare_exchange_weak(seen, in_flight);) {
    }
    ++requests_;
    {
      std::lock_guard lock(mutex_);
      ++per_target_[target];
      last_headers_ = headers;
      last_target_ = target;
    }
    if (delay_ms_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms_.load()));
    Response response = route(target, headers);
    --in_flight_;
    return response;
  }

  // /files/NAME (ranges) and /norange/NAME; nullopt for other targets.
  std::optional<Response> file_route(const std::string& target, const Headers& headers) {
    const bool ranges = target.starts_with("/files/");
    if (!ranges && !target.starts_with("/norange/")) return std::nullopt;
    std::vector<unsigned char> bytes;
    {
      std::lock_guard lock(mutex_);
      const std::string path = target.substr(0, target.find('?'));  // a query names no other file
      const auto it = files_.find(path.substr(path.find('/', 1) + 1));
      if (it == files_.end()) return Response{404, {}, {}};
      bytes = it->second;
    }
    Response r;
    r.headers.emplace_back("Content-Type", "image/tiff");
    const auto range = headers.find("range");
    if (!ranges || range == headers.end()) {
      if (ranges) r.headers.emplace_back("Accept-Ranges", "bytes");
      r.body = std::move(bytes);
      return r;
    }
    // "bytes=FIRST-LAST" (LAST optional), the one form GDAL sends.
    const std::string spec = range->second.substr(range->second.find('=') + 1);
    const std::size_t dash = spec.find('-');
    const std::size_t first = std::strtoull(spec.substr(0, dash).c_str(), nullptr, 10);
    std::size_t last = dash + 1 < spec.size() ? std::strtoull(spec.substr(dash + 1).c_str(), nullptr, 10)
                                              : bytes.size() - 1;
    if (first >= bytes.size()) return Response{416, {}, {{"Content-Range", "bytes */" + std::to_string(bytes.size())}}};
    last = std::min(last, bytes.size() - 1);
    r.status = 206;
    r.headers.emplace_back("Accept-Ranges", "bytes");
    r.headers.emplace_back("Content-Range", "bytes " + std::to_string(first) + "-" + std::to_string(last) + "/" +
                                                std::to_string(bytes.size()));
    r.body.assign(bytes.begin() + static_cast<std::ptrdiff_t>(first), bytes.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    return r;
  }

  Response route(const std::string& target, const Headers& headers) {
    if (std::optional<Response> file = file_route(target, headers)) return *file;
    Response r;
    const std::optional<Target> t = parse_target(target);
    if (!t) return Response{404, {}, {}};
    auto png = [&] { return tile_bytes(t->z, t->x, t->y); };  // takes mutex_: call it unlocked
    if (t->route == "tiles" || t->route == "nostore") {
      r.body = png();
      if (r.body.empty()) return Response{404, {}, {}};
      r.headers.emplace_back("Content-Type", "image/png");
      std::string cache_control;
      {
        std::lock_guard lock(mutex_);
        cache_control = t->route == "nostore" ? "no-store" : cache_control_;
      }
      if (!cache_control.empty()) r.headers.emplace_back("Cache-Control", cache_control);
      {
        std::lock_guard lock(mutex_);
        r.headers.insert(r.headers.end(), extra_tile_headers_.begin(), extra_tile_headers_.end());
      }
      if (etags_ && t->route == "tiles") {
        const std::string etag = etag_of(r.body);
        r.headers.emplace_back("ETag", etag);
        const auto match = headers.find("if-none-match");
        if (match != headers.end() && match->second == etag) {
          ++not_modified_;
          r.status = 304;
          r.body.clear();
        }
      }
      return r;
    }
    if (t->route == "corrupt") {
      const std::string garbage = "<html>this is not a tile</html>";
      r.body.assign(garbage.begin(), garbage.end());
      r.headers.emplace_back("Content-Type", "image/png");
      return r;
    }
    if (t->route == "wrongsize") {
      r.body = make_png(100, 37);
      r.headers.emplace_back("Content-Type", "image/png");
      return r;
    }
    if (t->route == "missing") return Response{404, {}, {}};
    if (t->route == "empty") return Response{204, {}, {}};
    if (t->route == "fail") return Response{t->status_override, {}, {}};
    if (t->route == "flaky") {
      int failures_so_far = 0;
      {
        std::lock_guard lock(mutex_);
        failures_so_far = flaky_failures_[target];
        if (failures_so_far < fail_count_) ++flaky_failures_[target];
      }
      if (failures_so_far < fail_count_) return Response{503, {}, {}};
      r.body = png();
      return r;
    }
    if (t->route == "slow") {
      while (!slow_released_ && !stopping_) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      r.body = png();
      return r;
    }
    return Response{404, {}, {}};
  }

  std::filesystem::path tile_folder_;
  int listen_fd_ = -1;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::thread acceptor_;

  mutable std::mutex mutex_;
  std::vector<std::thread> connections_;
  std::map<std::string, int> per_target_;
  std::map<std::string, int> flaky_failures_;
  mutable std::map<std::string, std::vector<unsigned char>> generated_;
  std::map<std::string, std::vector<unsigned char>> files_;
  std::atomic<std::size_t> body_bytes_sent_{0};
  Headers last_headers_;
  std::string last_target_;
  std::string cache_control_;
  std::vector<std::pair<std::string, std::string>> extra_tile_headers_;

  std::atomic<bool> etags_{false}, slow_released_{false};
  std::atomic<int> fail_count_{0}, delay_ms_{0};
  std::atomic<int> requests_{0}, not_modified_{0}, in_flight_{0}, max_in_flight_{0};
};

}  // namespace trailray::test::http
