#include "terrain/codecs/quantized_mesh.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace trailray::terrain {
namespace {

constexpr std::size_t kMaxInflated = std::size_t{64} << 20;
constexpr std::size_t kHeaderBytes = 88;

bool is_gzip(std::span<const unsigned char> b) { return b.size() >= 2 && b[0] == 0x1f && b[1] == 0x8b; }

std::vector<unsigned char> inflate_gzip(std::span<const unsigned char> in) {
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) throw QuantizedMeshError(0, "cannot start inflating the gzip stream");
  std::vector<unsigned char> out;
  z.next_in = const_cast<unsigned char*>(in.data());
  z.avail_in = static_cast<uInt>(in.size());
  unsigned char chunk[65536];
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    z.next_out = chunk;
    z.avail_out = sizeof chunk;
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      inflateEnd(&z);
      throw QuantizedMeshError(in.size() - z.avail_in, "the gzip stream is damaged or cut short");
    }
    out.insert(out.end(), chunk, chunk + (sizeof chunk - z.avail_out));
    if (out.size() > kMaxInflated) {
      inflateEnd(&z);
      throw QuantizedMeshError(0, "inflates to more than 64 MiB: not a terrain tile");
    }
    if (rc == Z_OK && z.avail_in == 0 && z.avail_out != 0) {
      inflateEnd(&z);
      throw QuantizedMeshError(in.size(), "the gzip stream is cut short");
    }
  }
  inflateEnd(&z);
  return out;
}

// Little-endian reads with the position, each checked against the end.
class Reader {
 public:
  explicit Reader(std::span<const unsigned char> b) : b_(b) {}
  std::size_t at() const { return at_; }
  std::size_t left() const { return b_.size() - at_; }
  void need(std::size_t n, const char* what) const {
    if (n > left())
      throw QuantizedMeshError(at_, std::string(what) + ": " + std::to_string(n) + " bytes needed, " +
                                        std::to_string(left()) + " left");
  }
  template <class T>
  T read(const char* what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, b_.data() + at_, sizeof(T));  // the format and every target are little-endian
    at_ += sizeof(T);
    return v;
  }
  void skip(std::size_t n, const char* what) {
    need(n, what);
    at_ += n;
  }
  void align(std::size_t to) {
    const std::size_t pad = (to - at_ % to) % to;
    skip(pad, "padding");
  }

 private:
  std::span<const unsigned char> b_;
  std::size_t at_ = 0;
};

std::int32_t zigzag(std::uint16_t v) { return static_cast<std::int32_t>(v >> 1) ^ -static_cast<std::int32_t>(v & 1); }

std::vector<std::uint16_t> delta_channel(Reader& r, std::size_t n, const char* what) {
  r.need(2 * n, what);
  std::vector<std::uint16_t> out(n);
  std::int32_t value = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t byte = r.at();
    value += zigzag(r.read<std::uint16_t>(what));
    if (value < 0 || value > kQuantizedMax)
      throw QuantizedMeshError(byte, std::string(what) + " of vertex " + std::to_string(i) + " is " +
                                         std::to_string(value) + ", outside 0..32767");
    out[i] = static_cast<std::uint16_t>(value);
  }
  return out;
}

template <class Index>
std::vector<std::uint32_t> indices(Reader& r, std::size_t count, std::size_t vertices, bool high_water, const char* what) {
  r.need(sizeof(Index) * count, what);
  std::vector<std::uint32_t> out(count);
  std::uint32_t highest = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t byte = r.at();
    const std::uint32_t code = r.read<Index>(what);
    std::uint32_t index = code;
    if (high_water) {
      if (code > highest) throw QuantizedMeshError(byte, std::string(what) + ": code past the high water mark");
      index = highest - code;
      if (code == 0) ++highest;
    }
    if (index >= vertices)
      throw QuantizedMeshError(byte, std::string(what) + ": index " + std::to_string(index) + " of " +
                                         std::to_string(vertices) + " vertices");
    out[i] = index;
  }
  return out;
}

template <class Index>
void read_indices(Reader& r, QuantizedMesh& m) {
  const std::size_t n = m.vertex_count();
  const std::size_t count_at = r.at();
  const std::uint32_t triangles = r.read<std::uint32_t>("triangle count");
  if (std::uint64_t{triangles} * 3 * sizeof(Index) > r.left())
    throw QuantizedMeshError(count_at, std::to_string(triangles) + " triangles do not fit in the bytes left");
  m.triangles = indices<Index>(r, std::size_t{triangles} * 3, n, true, "triangle indices");
  for (auto* edge : {&m.west, &m.south, &m.east, &m.north}) {
    const std::size_t at = r.at();
    const std::uint32_t count = r.read<std::uint32_t>("edge vertex count");
    if (std::uint64_t{count} * sizeof(Index) > r.left())
      throw QuantizedMeshError(at, std::to_string(count) + " edge vertices do not fit in the bytes left");
    *edge = indices<Index>(r, count, n, false, "edge indices");
  }
}

template <class T>
void put(std::vector<unsigned char>& out, T v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}

std::uint16_t zigzag_encode(std::int32_t d) { return static_cast<std::uint16_t>((d << 1) ^ (d >> 31)); }

}  // namespace

QuantizedMesh decode_quantized_mesh(std::span<const unsigned char> bytes) {
  std::vector<unsigned char> inflated;
  if (is_gzip(bytes)) {
    inflated = inflate_gzip(bytes);
    bytes = inflated;
  }
  Reader r(bytes);
  r.need(kHeaderBytes, "the header");
  QuantizedMesh m;
  for (double& c : m.center_ecef) c = r.read<double>("the header");
  m.min_height_m = r.read<float>("the header");
  m.max_height_m = r.read<float>("the header");
  // Earth's heights lie within a few kilometres of sea level; far beyond is a damaged header.
  constexpr float kFarthest = 100000.0f;
  if (!std::isfinite(m.min_height_m) || !std::isfinite(m.max_height_m) || m.min_height_m > m.max_height_m ||
      std::abs(m.min_height_m) > kFarthest || std::abs(m.max_height_m) > kFarthest)
    throw QuantizedMeshError(24, "the height range " + std::to_string(m.min_height_m) + ".." +
                                     std::to_string(m.max_height_m) + " m is not one of the Earth's");
  r.skip(kHeaderBytes - 32, "the header");  // bounding sphere, horizon occlusion point
  const std::size_t count_at = r.at();
  const std::uint32_t n = r.read<std::uint32_t>("vertex count");
  if (std::uint64_t{n} * 6 > r.left())
    throw QuantizedMeshError(count_at, std::to_string(n) + " vertices do not fit in the bytes left");
  m.u = delta_channel(r, n, "u");
  m.v = delta_channel(r, n, "v");
  m.h = delta_channel(r, n, "height");
  if (n > 65536) {
    r.align(4);
    read_indices<std::uint32_t>(r, m);
  } else {
    r.align(2);
    read_indices<std::uint16_t>(r, m);
  }
  // Extensions (normals, water mask, metadata): each an id, a length and its bytes; skipped.
  while (r.left() > 0) {
    r.read<std::uint8_t>("extension id");
    const std::uint32_t length = r.read<std::uint32_t>("extension length");
    r.skip(length, "extension");
  }
  return m;
}

std::vector<unsigned char> encode_quantized_mesh(const QuantizedMesh& m) {
  std::vector<unsigned char> out;
  for (double c : m.center_ecef) put(out, c);
  put(out, m.min_height_m);
  put(out, m.max_height_m);
  for (int i = 0; i < 7; ++i) put(out, 0.0);  // bounding sphere (4), horizon occlusion point (3)
  const auto n = static_cast<std::uint32_t>(m.u.size());
  put(out, n);
  for (const auto* channel : {&m.u, &m.v, &m.h}) {
    std::int32_t previous = 0;
    for (std::uint16_t value : *channel) {
      if (value > kQuantizedMax)
        throw std::invalid_argument("encode_quantized_mesh: a quantized value of " + std::to_string(value) +
                                    " (0..32767)");
      put(out, zigzag_encode(static_cast<std::int32_t>(value) - previous));
      previous = value;
    }
  }
  const bool wide = n > 65536;
  while (out.size() % (wide ? 4 : 2) != 0) out.push_back(0);
  const auto index = [&](std::uint32_t i) {
    if (wide)
      put(out, i);
    else
      put(out, static_cast<std::uint16_t>(i));
  };
  put(out, static_cast<std::uint32_t>(m.triangles.size() / 3));
  std::uint32_t highest = 0;
  for (std::uint32_t i : m.triangles) {
    // High water mark: vertices must first appear in order (0, 1, 2, ...), as encoders ensure.
    if (i > highest) throw std::invalid_argument("encode_quantized_mesh: vertex " + std::to_string(i) + " before " +
                                                 std::to_string(highest) + " (number them by first use)");
    index(highest - i);
    if (i == highest) ++highest;
  }
  for (const auto* edge : {&m.west, &m.south, &m.east, &m.north}) {
    put(out, static_cast<std::uint32_t>(edge->size()));
    for (std::uint32_t i : *edge) index(i);
  }
  return out;
}

MeshHeights::MeshHeights(QuantizedMesh mesh) : mesh_(std::move(mesh)), cells_(kCells * kCells) {
  const auto cell = [](std::uint16_t q) { return std::min(kCells - 1, int(q) * kCells / (kQuantizedMax + 1)); };
  struct Bounds {
    int x0, x1, y0, y1;
  };
  const auto bounds = [&](std::uint32_t t) {
    Bounds b{kCells, -1, kCells, -1};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = mesh_.triangles[3 * t + k];
      b.x0 = std::min(b.x0, cell(mesh_.u[i]));
      b.x1 = std::max(b.x1, cell(mesh_.u[i]));
      b.y0 = std::min(b.y0, cell(mesh_.v[i]));
      b.y1 = std::max(b.y1, cell(mesh_.v[i]));
    }
    return b;
  };
  // Counted first: a fan of long slivers in a flat tile may each span the tile, but only a
  // mesh of overlapping triangles needs more than this.
  const std::size_t triangles = mesh_.triangle_count();
  const std::uint64_t budget = 32 * std::uint64_t{triangles} + 256 * std::uint64_t{kCells * kCells};
  std::uint64_t entries = 0;
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const Bounds b = bounds(t);
    entries += std::uint64_t(b.x1 - b.x0 + 1) * std::uint64_t(b.y1 - b.y0 + 1);
  }
  if (entries > budget)
    throw QuantizedMeshError(0, "its " + std::to_string(triangles) + " triangles overlap far more than a " +
                                    "terrain mesh's (they cover the tile " +
                                    std::to_string(entries / (kCells * kCells)) + " times over)");
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const Bounds b = bounds(t);
    for (int y = b.y0; y <= b.y1; ++y)
      for (int x = b.x0; x <= b.x1; ++x) cells_[std::size_t(y) * kCells + x].push_back(t);
  }
}

double MeshHeights::at(double x, double y) const {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (!(x >= 0.0 && x <= 1.0 && y >= 0.0 && y <= 1.0)) return nan;
  const double px = x * kQuantizedMax, py = y * kQuantizedMax;
  const int cx = std::min(kCells - 1, int(px * kCells / (kQuantizedMax + 1)));
  const int cy = std::min(kCells - 1, int(py * kCells / (kQuantizedMax + 1)));
  for (const std::uint32_t t : cells_[std::size_t(cy) * kCells + cx]) {
    const std::uint32_t a = mesh_.triangles[3 * t], b = mesh_.triangles[3 * t + 1], c = mesh_.triangles[3 * t + 2];
    const double ax = mesh_.u[a], ay = mesh_.v[a], bx = mesh_.u[b], by = mesh_.v[b], cx2 = mesh_.u[c], cy2 = mesh_.v[c];
    const double det = (by - cy2) * (ax - cx2) + (cx2 - bx) * (ay - cy2);
    if (det == 0.0) continue;  // a degenerate triangle holds no area
    const double wa = ((by - cy2) * (px - cx2) + (cx2 - bx) * (py - cy2)) / det;
    const double wb = ((cy2 - ay) * (px - cx2) + (ax - cx2) * (py - cy2)) / det;
    const double wc = 1.0 - wa - wb;
    constexpr double eps = -1e-9;  // a point on a shared edge belongs to either triangle
    if (wa < eps || wb < eps || wc < eps) continue;
    // Within the triangle: weights never below 0, so the height never leaves its vertices' range.
    const double ua = std::max(wa, 0.0), ub = std::max(wb, 0.0), uc = std::max(wc, 0.0), sum = ua + ub + uc;
    return (ua * mesh_.height_m(a) + ub * mesh_.height_m(b) + uc * mesh_.height_m(c)) / sum;
  }
  return nan;
}

}  // namespace trailray::terrain
