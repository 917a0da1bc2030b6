#include "terrain/sources/quantized_mesh_source.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "geo/tile_id.hpp"
#include "terrain/loading/http_client.hpp"

namespace trailray::terrain {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kKeptMeshes = 64;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool is_url(const std::string& s) {
  const std::string l = lower(s);
  return l.starts_with("http://") || l.starts_with("https://");
}

std::optional<std::string> read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replace_all(std::string text, const std::string& what, const std::string& with) {
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + with.size()))
    text.replace(at, what.size(), with);
  return text;
}

// A point of a triangle being clipped: its place in the Mercator tile (fractions) and height.
struct ClipPoint {
  double x, y, h;
};

// Sutherland-Hodgman: the polygon's part on the inner side of one border of [0, 1] x [0, 1].
std::vector<ClipPoint> clip_side(const std::vector<ClipPoint>& in, int side) {
  const auto inside = [side](const ClipPoint& p) {
    switch (side) {
      case 0: return p.x >= 0.0;
      case 1: return p.x <= 1.0;
      case 2: return p.y >= 0.0;
      default: return p.y <= 1.0;
    }
  };
  const auto cross = [side](const ClipPoint& a, const ClipPoint& b) {
    const double edge = side == 0 ? 0.0 : side == 1 ? 1.0 : side == 2 ? 0.0 : 1.0;
    const double t = side < 2 ? (edge - a.x) / (b.x - a.x) : (edge - a.y) / (b.y - a.y);
    return ClipPoint{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.h + t * (b.h - a.h)};
  };
  std::vector<ClipPoint> out;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const ClipPoint &a = in[i], &b = in[(i + 1) % in.size()];
    if (inside(a)) {
      out.push_back(a);
      if (!inside(b)) out.push_back(cross(a, b));
    } else if (inside(b)) {
      out.push_back(cross(a, b));
    }
  }
  return out;
}

std::uint64_t key_of(const geo::TileId& t) {
  return (std::uint64_t(t.zoom) << 58) | (std::uint64_t(t.x) << 29) | std::uint64_t(t.y);
}

// The folder (or URL directory) layer.json sits in, with a trailing '/'.
std::string base_of(const std::string& location, bool remote) {
  if (!remote) return location.ends_with("/") ? location : location + "/";
  const std::string without_query = location.substr(0, location.find('?'));
  return without_query.substr(0, without_query.rfind('/') + 1);
}

}  // namespace

QuantizedMeshLayer parse_quantized_mesh_layer(const std::string& text, const std::string& name) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw SourceError(name + ": not JSON: " + e.what());
  }
  if (!j.is_object()) throw SourceError(name + ": not a layer.json (not a JSON object)");
  QuantizedMeshLayer layer;
  const std::string format = j.value("format", std::string("quantized-mesh-1.0"));
  if (!format.starts_with("quantized-mesh"))
    throw SourceError(name + ": format \"" + format + "\", not quantized-mesh-1.0");
  if (!j.contains("tiles") || !j["tiles"].is_array() || j["tiles"].empty() || !j["tiles"][0].is_string())
    throw SourceError(name + ": no \"tiles\" template");
  layer.tiles = j["tiles"][0].get<std::string>();
  if (j.contains("version") && j["version"].is_string()) layer.version = j["version"].get<std::string>();
  if (j.contains("scheme") && j["scheme"].is_string()) layer.tms = lower(j["scheme"].get<std::string>()) != "xyz";
  if (j.contains("projection") && j["projection"].is_string()) {
    const std::string p = j["projection"].get<std::string>();
    if (p == "EPSG:3857")
      layer.geographic = false;
    else if (p != "EPSG:4326")
      throw SourceError(name + ": projection " + p + " (quantized-mesh layers are EPSG:4326 or EPSG:3857)");
  }
  const auto zoom = [&](const char* key, int fallback) {
    return j.contains(key) && j[key].is_number_integer() ? std::clamp(j[key].get<int>(), 0, 30) : fallback;
  };
  int available_max = 0;
  if (j.contains("available") && j["available"].is_array())
    available_max = std::max(0, static_cast<int>(j["available"].size()) - 1);
  layer.min_zoom = zoom("minzoom", 0);
  layer.max_zoom = std::max(layer.min_zoom, zoom("maxzoom", available_max));
  if (j.contains("bounds") && j["bounds"].is_array() && j["bounds"].size() == 4 && j["bounds"][0].is_number()) {
    geo::LatLonBounds b;
    b.add(j["bounds"][1].get<double>(), j["bounds"][0].get<double>());
    b.add(j["bounds"][3].get<double>(), j["bounds"][2].get<double>());
    layer.bounds = b;
  }
  return layer;
}

bool is_quantized_mesh_folder(const std::string& folder) {
  std::error_code ec;
  return std::filesystem::is_regular_file(std::filesystem::path(folder) / "layer.json", ec);
}

bool is_quantized_mesh_url(const std::string& url) {
  const std::string path = lower(url.substr(0, url.find('?')));
  return is_url(url) && path.ends_with("/layer.json");
}

QuantizedMeshSource::QuantizedMeshSource(const std::string& location, const NetworkSettings& network)
    : location_(location), remote_(is_url(location)), offline_(network.offline) {
  std::string text;
  if (remote_) {
    if (offline_) throw SourceError(location + ": a quantized-mesh server, and --offline is set");
    HttpClientOptions o;
    o.connect_timeout = std::chrono::milliseconds(static_cast<std::int64_t>(network.connect_timeout_s * 1000));
    o.total_timeout = std::chrono::milliseconds(static_cast<std::int64_t>(network.timeout_s * 1000));
    o.retry.max_retries = network.retries;
    http_ = std::make_unique<HttpClient>(o);
    const HttpResponse r = http_->get({location, {}, {}, {}});
    if (r.status != 200)
      throw SourceError(location + ": layer.json: " + (r.status == 0 ? r.error : "HTTP " + std::to_string(r.status)));
    text.assign(r.body.begin(), r.body.end());
  } else {
    const std::optional<std::string> read = read_text(std::filesystem::path(location) / "layer.json");
    if (!read) throw SourceError(location + ": no layer.json in the folder");
    text = *read;
  }
  layer_ = parse_quantized_mesh_layer(text, remote_ ? location : location + "/layer.json");
  info_.name = location;
  info_.min_zoom = 0;
  // Mercator tiles as fine as the mesh's finest: a geographic level's tiles are half as wide.
  info_.max_zoom = std::min(layer_.max_zoom + (layer_.geographic ? 1 : 0), 24);
  info_.bounds = layer_.bounds;
  info_.format = "quantized-mesh";
  info_.encoding = HeightEncoding::float32;
}

QuantizedMeshSource::~QuantizedMeshSource() = default;

std::optional<QuantizedMeshSource::MeshPlace> QuantizedMeshSource::mesh_place(double lat, double lon, int zoom) const {
  if (!std::isfinite(lat) || !std::isfinite(lon) || zoom < 0 || zoom > 29) return std::nullopt;
  if (!layer_.geographic) {
    const std::optional<geo::TileCoord> c = geo::fractional_tile_coord(lat, lon, zoom);
    const std::optional<geo::TileId> id = geo::tile_containing(lat, lon, zoom);
    if (!c || !id) return std::nullopt;
    return MeshPlace{*id, c->x - id->x, 1.0 - (c->y - id->y)};
  }
  // EPSG:4326: two tiles at zoom 0, each 180 degrees square, rows from the north.
  const double size = 180.0 / double(std::uint64_t{1} << zoom);
  const double wrapped = lon - 360.0 * std::floor((lon + 180.0) / 360.0);
  const double column = (wrapped + 180.0) / size, row = (90.0 - std::clamp(lat, -90.0, 90.0)) / size;
  const auto columns = std::uint32_t(2u << zoom), rows = std::uint32_t(1u << zoom);
  const auto x = std::min(columns - 1, static_cast<std::uint32_t>(std::floor(column)));
  const auto y = std::min(rows - 1, static_cast<std::uint32_t>(std::floor(row)));
  return MeshPlace{geo::TileId{zoom, x, y}, column - x, 1.0 - (row - y)};
}

std::optional<geo::TileId> QuantizedMeshSource::mesh_tile_at(double lat, double lon, int zoom) const {
  const std::optional<MeshPlace> place = mesh_place(lat, lon, zoom);
  if (!place) return std::nullopt;
  return place->tile;
}

std::shared_ptr<const MeshHeights> QuantizedMeshSource::mesh(const geo::TileId& id, StopToken stop,
                                                             std::string* error) {
  const std::uint64_t key = key_of(id);
  {
    std::lock_guard lock(mutex_);
    if (missing_.contains(key)) return nullptr;
    for (auto it = recent_.begin(); it != recent_.end(); ++it)
      if (it->first == key) {
        recent_.splice(recent_.begin(), recent_, it);
        return it->second;
      }
  }
  const std::uint32_t row = layer_.tms ? (1u << id.zoom) - 1 - id.y : id.y;
  std::string path = layer_.tiles;
  path = replace_all(path, "{z}", std::to_string(id.zoom));
  path = replace_all(path, "{x}", std::to_string(id.x));
  path = replace_all(path, "{y}", std::to_string(row));
  path = replace_all(path, "{version}", layer_.version);
  const std::string where = is_url(path) ? path : base_of(location_, remote_) + path;
  std::vector<unsigned char> bytes;
  bool found = false;
  if (remote_ || is_url(where)) {
    if (offline_ || !http_) {
      if (error) *error = where + ": --offline";
      return nullptr;
    }
    const HttpResponse r = http_->get({where, {}, {}, {}}, stop);
    if (r.status == 200) {
      bytes = r.body;
      found = true;
    } else if (r.status != 404 && r.status != 204) {
      if (error) *error = where + ": " + (r.status == 0 ? r.error : "HTTP " + std::to_string(r.status));
      return nullptr;
    }
  } else {
    const std::string file = where.substr(0, where.find('?'));
    if (const std::optional<std::string> text = read_text(file)) {
      bytes.assign(text->begin(), text->end());
      found = true;
    }
  }
  std::shared_ptr<const MeshHeights> decoded;
  if (found) {
    try {
      decoded = std::make_shared<const MeshHeights>(decode_quantized_mesh(bytes));
    } catch (const QuantizedMeshError& e) {
      if (error) *error = where + ": " + e.what();
      return nullptr;
    }
  }
  std::lock_guard lock(mutex_);
  if (!decoded) {
    missing_.insert(key);
    return nullptr;
  }
  recent_.emplace_front(key, decoded);
  if (recent_.size() > kKeptMeshes) recent_.pop_back();
  return decoded;
}

double QuantizedMeshSource::height_at(double lat, double lon, int zoom, StopToken stop, std::string* error,
                                      LastMesh* last) {
  for (int z = std::min(zoom, layer_.max_zoom); z >= layer_.min_zoom; --z) {
    const std::optional<MeshPlace> place = mesh_place(lat, lon, z);
    if (!place) return kNaN;
    std::shared_ptr<const MeshHeights> m;
    if (last && last->key == key_of(place->tile)) {
      m = last->mesh;
    } else {
      m = mesh(place->tile, stop, error);
      if (error && !error->empty()) return kNaN;
      if (last) *last = {key_of(place->tile), m};
    }
    if (!m) continue;  // no tile at this level: a coarser one may have the place
    return m->at(std::clamp(place->x, 0.0, 1.0), std::clamp(place->y, 0.0, 1.0));
  }
  return kNaN;
}

std::shared_ptr<const TileTriangles> QuantizedMeshSource::triangles_over(const TileId& id, int mesh_zoom,
                                                                         StopToken stop) {
  const std::optional<geo::LatLonBounds> box = geo::tile_bounds_latlon(id);
  if (!box) return nullptr;
  const double inset = 1e-9;
  const std::optional<geo::TileId> nw = mesh_tile_at(box->max_lat - inset, box->min_lon + inset, mesh_zoom);
  const std::optional<geo::TileId> se = mesh_tile_at(box->min_lat + inset, box->max_lon - inset, mesh_zoom);
  if (!nw || !se || se->x < nw->x || se->y < nw->y) return nullptr;
  // Far coarser than the layer's tiles: the grid alone (the triangles would be too many to draw).
  if (std::uint64_t{se->x - nw->x + 1} * (se->y - nw->y + 1) > 16) return nullptr;
  auto out = std::make_shared<TileTriangles>();
  for (std::uint32_t qy = nw->y; qy <= se->y; ++qy)
    for (std::uint32_t qx = nw->x; qx <= se->x; ++qx) {
      const std::shared_ptr<const MeshHeights> heights = mesh({mesh_zoom, qx, qy}, stop, nullptr);
      if (!heights) continue;
      const QuantizedMesh& m = heights->mesh();
      // Each vertex's place in the Mercator tile (fractions from its north-west corner).
      std::vector<ClipPoint> at(m.vertex_count());
      for (std::size_t i = 0; i < at.size(); ++i) {
        const double fu = double(m.u[i]) / kQuantizedMax, fv = double(m.v[i]) / kQuantizedMax;
        std::optional<geo::TileCoord> c;
        if (layer_.geographic) {
          const double size = 180.0 / double(std::uint64_t{1} << mesh_zoom);
          c = geo::fractional_tile_coord(90.0 - (qy + 1) * size + fv * size, -180.0 + (qx + fu) * size, id.zoom);
        } else {
          const double scale = std::ldexp(1.0, id.zoom - mesh_zoom);
          c = geo::TileCoord{(qx + fu) * scale, (qy + 1.0 - fv) * scale};
        }
        at[i] = c ? ClipPoint{c->x - id.x, c->y - id.y, m.height_m(i)} : ClipPoint{-1e9, -1e9, 0.0};
      }
      std::vector<std::int64_t> shared(at.size(), -1);  // unclipped vertices, added once
      const auto add = [&](const ClipPoint& p) {
        out->u.push_back(static_cast<float>(std::clamp(p.x, 0.0, 1.0)));
        out->v.push_back(static_cast<float>(std::clamp(p.y, 0.0, 1.0)));
        out->height_m.push_back(static_cast<float>(p.h));
        return static_cast<std::uint32_t>(out->u.size() - 1);
      };
      const auto inside = [](const ClipPoint& p) { return p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0; };
      for (std::size_t f = 0; f < m.triangle_count(); ++f) {
        const std::uint32_t k[3] = {m.triangles[3 * f], m.triangles[3 * f + 1], m.triangles[3 * f + 2]};
        const ClipPoint &a = at[k[0]], &b = at[k[1]], &c = at[k[2]];
        if ((a.x < 0 && b.x < 0 && c.x < 0) || (a.x > 1 && b.x > 1 && c.x > 1) || (a.y < 0 && b.y < 0 && c.y < 0) ||
            (a.y > 1 && b.y > 1 && c.y > 1))
          continue;
        if (inside(a) && inside(b) && inside(c)) {
          for (const std::uint32_t i : k) {
            if (shared[i] < 0) shared[i] = add(at[i]);
            out->indices.push_back(static_cast<std::uint32_t>(shared[i]));
          }
          continue;
        }
        std::vector<ClipPoint> polygon{a, b, c};
        for (int side = 0; side < 4 && !polygon.empty(); ++side) polygon = clip_side(polygon, side);
        if (polygon.size() < 3) continue;
        const std::uint32_t first = add(polygon[0]);
        std::uint32_t previous = add(polygon[1]);
        for (std::size_t i = 2; i < polygon.size(); ++i) {
          const std::uint32_t next = add(polygon[i]);
          out->indices.insert(out->indices.end(), {first, previous, next});
          previous = next;
        }
      }
    }
  if (out->indices.empty()) return nullptr;
  return out;
}

std::optional<double> QuantizedMeshSource::sample_native(double lat, double lon) {
  return height_at(lat, lon, layer_.max_zoom, {}, nullptr);
}

TileResult<HeightTile> QuantizedMeshSource::load(const TileId& id, StopToken stop) {
  const std::optional<geo::LatLonBounds> box = geo::tile_bounds_latlon(id);
  if (!box) return {TileStatus::failed, {}, location_ + " " + geo::to_string(id) + ": not a tile"};
  if (layer_.bounds && (box->max_lat < layer_.bounds->min_lat || box->min_lat > layer_.bounds->max_lat ||
                        box->max_lon < layer_.bounds->min_lon || box->min_lon > layer_.bounds->max_lon))
    return {TileStatus::no_data, {}, {}};
  const int mesh_zoom = std::clamp(id.zoom - (layer_.geographic ? 1 : 0), layer_.min_zoom, layer_.max_zoom);
  HeightTile t;
  t.id = id;
  t.width = t.height = 256;
  t.heights.assign(256 * 256, kNoHeight);
  std::string error;
  LastMesh last;
  for (std::uint32_t row = 0; row < 256; ++row) {
    if (stop.stop_requested()) return {TileStatus::cancelled, {}, {}};
    for (std::uint32_t col = 0; col < 256; ++col) {
      const std::optional<geo::LatLon> p = geo::latlon_from_tile_pixel(id, col + 0.5, row + 0.5, 256);
      if (!p) continue;
      const double h = height_at(p->lat, p->lon, mesh_zoom, stop, &error, &last);
      if (!error.empty()) return {TileStatus::failed, {}, location_ + " " + geo::to_string(id) + ": " + error};
      t.heights[std::size_t{row} * 256 + col] = static_cast<float>(h);
    }
  }
  update_height_range(t);
  if (!t.has_data()) return {TileStatus::no_data, {}, {}};
  // Drawn as the layer's own triangles, clipped to the tile (the samples stay what sampling reads).
  t.triangles = triangles_over(id, mesh_zoom, stop);
  return {TileStatus::ok, std::move(t), {}};
}

}  // namespace trailray::terrain
