#include "render/passes/terrain_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "geo/tile_id.hpp"
#include "render/gl/render_error.hpp"
#include "scene/camera/camera.hpp"
#include "terrain/lod/lod_selection.hpp"

namespace trailray::render {
namespace {

// The continuous sample coordinate (0 = first sample) of a position `t` in [0, 1] across a tile
// of `samples` samples, not clamped: pixel-is-area tiles have no sample on their edge, so the
// outermost half cell lies in [-0.5, 0) or (last, last + 0.5].
double unclamped_sample_coordinate(double t, std::uint32_t samples, terrain::SampleLayout layout) {
  const double last = static_cast<double>(samples - 1);
  return layout == terrain::SampleLayout::pixel_is_point ? t * last : t * samples - 0.5;
}

double sample_coordinate(double t, std::uint32_t samples, terrain::SampleLayout layout) {
  return std::clamp(unclamped_sample_coordinate(t, samples, layout), 0.0, static_cast<double>(samples - 1));
}

// On the outer half cell of a pixel-is-area tile: the height extrapolated linearly from the two
// outermost samples (in each direction), so that two neighbouring tiles put their shared edge at
// nearly the same height (the same to second order on smooth ground) instead of each holding
// its own edge sample flat: the crack a skirt would otherwise show as a dark seam closes. None
// when a sample involved is a hole (the caller then holds the edge sample).
std::optional<float> extrapolated_rim_height(const terrain::HeightTile& tile, double u, double v) {
  if (tile.layout != terrain::SampleLayout::pixel_is_area || tile.width < 2 || tile.height < 2) return std::nullopt;
  const double sx = unclamped_sample_coordinate(u, tile.width, tile.layout);
  const double sy = unclamped_sample_coordinate(v, tile.height, tile.layout);
  const double last_x = tile.width - 1.0, last_y = tile.height - 1.0;
  if (sx >= 0.0 && sx <= last_x && sy >= 0.0 && sy <= last_y) return std::nullopt;  // inside: plain bilinear
  const auto x0 = static_cast<std::uint32_t>(std::clamp(std::floor(sx), 0.0, last_x - 1.0));
  const auto y0 = static_cast<std::uint32_t>(std::clamp(std::floor(sy), 0.0, last_y - 1.0));
  const double fx = sx - x0, fy = sy - y0;  // outside [0, 1] on the rim: extrapolation
  const float h[4] = {tile.at(x0, y0), tile.at(x0 + 1, y0), tile.at(x0, y0 + 1), tile.at(x0 + 1, y0 + 1)};
  for (float value : h)
    if (std::isnan(value)) return std::nullopt;
  return static_cast<float>((1 - fx) * (1 - fy) * h[0] + fx * (1 - fy) * h[1] + (1 - fx) * fy * h[2] + fx * fy * h[3]);
}

void check_tile(const terrain::HeightTile& tile) {
  if (!geo::is_valid(tile.id)) throw std::invalid_argument("terrain mesh: invalid tile id " + geo::to_string(tile.id));
  if (tile.width == 0 || tile.height == 0 || tile.heights.size() != std::size_t{tile.width} * tile.height)
    throw std::invalid_argument("terrain mesh: tile " + geo::to_string(tile.id) + " has " +
                                std::to_string(tile.heights.size()) + " heights for a grid of " +
                                std::to_string(tile.width) + " x " + std::to_string(tile.height));
}

glm::vec3 to_vec3(const glm::dvec3& v) { return glm::vec3(v); }

}  // namespace

std::uint32_t full_resolution_grid(const terrain::HeightTile& tile) {
  const std::uint32_t samples = std::max(tile.width, tile.height);
  return tile.layout == terrain::SampleLayout::pixel_is_point ? std::max(samples, 2u) : samples + 1;
}

float sample_height_bilinear(const terrain::HeightTile& tile, double u, double v) {
  if (const std::optional<float> rim = extrapolated_rim_height(tile, u, v)) return *rim;
  const double sx = sample_coordinate(u, tile.width, tile.layout);
  const double sy = sample_coordinate(v, tile.height, tile.layout);
  const auto x0 = static_cast<std::uint32_t>(sx), y0 = static_cast<std::uint32_t>(sy);
  const std::uint32_t x1 = std::min(x0 + 1, tile.width - 1), y1 = std::min(y0 + 1, tile.height - 1);
  const double fx = sx - x0, fy = sy - y0;
  const double weights[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  const float heights[4] = {tile.at(x0, y0), tile.at(x1, y0), tile.at(x0, y1), tile.at(x1, y1)};
  double sum = 0.0, weight = 0.0;
  for (int k = 0; k < 4; ++k) {
    if (std::isnan(heights[k]) || weights[k] <= 0.0) continue;
    sum += weights[k] * heights[k];
    weight += weights[k];
  }
  if (weight <= 0.0) {
    // Exactly on a sample whose neighbours are holes, or only holes around: the nearest sample.
    const float nearest =
        tile.at(static_cast<std::uint32_t>(std::lround(sx)), static_cast<std::uint32_t>(std::lround(sy)));
    return nearest;
  }
  return static_cast<float>(sum / weight);
}

namespace {

// The grid's vertices (positions relative to the origin, normals from the neighbours) and its
// two triangles per cell.
void add_grid(TerrainMesh& mesh, const std::vector<float>& heights, const std::vector<float>& covered,
              const std::vector<scene::GeoPosition>& where, const std::vector<glm::dvec3>& positions,
              const glm::dvec3& origin) {
  const std::uint32_t n = mesh.grid_vertices;
  const std::uint32_t cells = n - 1;
  mesh.vertices.reserve(positions.size() + 4 * std::size_t{n});
  for (std::uint32_t j = 0; j < n; ++j) {
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::size_t k = std::size_t{j} * n + i;
      // Central differences (one-sided on the edges) of the ECEF positions: the normal follows the
      // height differences and the ellipsoid's curvature alike.
      const glm::dvec3 east =
          positions[std::size_t{j} * n + std::min(i + 1, cells)] - positions[std::size_t{j} * n + (i > 0 ? i - 1 : 0)];
      const glm::dvec3 north =
          positions[std::size_t{j > 0 ? j - 1 : 0} * n + i] - positions[std::size_t{std::min(j + 1, cells)} * n + i];
      glm::dvec3 normal = glm::cross(east, north);
      const double length = glm::length(normal);
      normal = length > 0.0 ? normal / length : scene::enu_axes_at(where[k].lat_deg, where[k].lon_deg).up;
      const glm::vec3 p = to_vec3(positions[k] - origin), nn = to_vec3(normal);
      mesh.vertices.push_back({p.x, p.y, p.z, nn.x, nn.y, nn.z, heights[k],
                               static_cast<float>(i) / static_cast<float>(cells),
                               static_cast<float>(j) / static_cast<float>(cells), covered[k]});
    }
  }
  mesh.indices.reserve(std::size_t{cells} * cells * 6 + std::size_t{cells} * 4 * 6);
  for (std::uint32_t j = 0; j < cells; ++j) {
    for (std::uint32_t i = 0; i < cells; ++i) {
      const std::uint32_t v00 = j * n + i, v10 = v00 + 1, v01 = v00 + n, v11 = v01 + 1;
      mesh.indices.insert(mesh.indices.end(), {v00, v01, v10, v10, v01, v11});
    }
  }
}

// Skirts: the perimeter once around, each vertex with a copy hanging straight down below it.
void add_skirts(TerrainMesh& mesh, const terrain::TileId& id, const std::vector<scene::GeoPosition>& where,
                const std::vector<glm::dvec3>& positions, const glm::dvec3& origin) {
  const std::uint32_t n = mesh.grid_vertices;
  const std::uint32_t cells = n - 1;
  std::vector<std::uint32_t> perimeter;
  for (std::uint32_t i = 0; i < cells; ++i) perimeter.push_back(i);              // north, west to east
  for (std::uint32_t j = 0; j < cells; ++j) perimeter.push_back(j * n + cells);  // east, north to south
  for (std::uint32_t i = cells; i > 0; --i) perimeter.push_back(cells * n + i);  // south, east to west
  for (std::uint32_t j = cells; j > 0; --j) perimeter.push_back(j * n);          // west, south to north
  const double depth = terrain::skirt_depth_m(id, cells);
  const auto first_skirt = static_cast<std::uint32_t>(mesh.vertices.size());
  for (const std::uint32_t edge : perimeter) {
    TerrainVertex v = mesh.vertices[edge];
    const glm::dvec3 up = scene::enu_axes_at(where[edge].lat_deg, where[edge].lon_deg).up;
    const glm::vec3 p = to_vec3(positions[edge] - depth * up - origin);
    v.x = p.x;
    v.y = p.y;
    v.z = p.z;
    mesh.vertices.push_back(v);
  }
  const auto count = static_cast<std::uint32_t>(perimeter.size());
  for (std::uint32_t s = 0; s < count; ++s) {
    const std::uint32_t a = perimeter[s], b = perimeter[(s + 1) % count];
    const std::uint32_t a_low = first_skirt + s, b_low = first_skirt + (s + 1) % count;
    mesh.indices.insert(mesh.indices.end(), {a, b, b_low, a, b_low, a_low});
  }
}

// The source's own triangles (a quantized-mesh tile's), drawn as they are: each vertex placed at
// its place and height, its normal the area-weighted mean of its triangles' (so shared vertices
// shade smoothly), every triangle wound as the grid's; skirts hang from the triangle edges that
// lie on the tile's border.
TerrainMesh triangles_mesh(const terrain::HeightTile& tile, const terrain::TileTriangles& t) {
  const std::size_t n = t.u.size();
  if (t.v.size() != n || t.height_m.size() != n || t.indices.size() % 3 != 0)
    throw std::invalid_argument("terrain mesh: tile " + geo::to_string(tile.id) + " has inconsistent triangles");
  for (std::uint32_t i : t.indices)
    if (i >= n) throw std::invalid_argument("terrain mesh: tile " + geo::to_string(tile.id) + ": index past the vertices");
  TerrainMesh mesh;
  mesh.id = tile.id;
  mesh.grid_vertices = 0;
  double min_h = INFINITY, max_h = -INFINITY;
  for (float h : t.height_m) {
    min_h = std::min(min_h, double{h});
    max_h = std::max(max_h, double{h});
  }
  if (n == 0) min_h = max_h = 0.0;
  const auto centre = geo::latlon_from_tile_pixel(tile.id, 0.5, 0.5, 1);
  mesh.origin = scene::ecef_from({centre->lat, centre->lon, 0.5 * (min_h + max_h)});
  std::vector<glm::dvec3> positions(n), ups(n), normals(n, glm::dvec3(0.0));
  for (std::size_t k = 0; k < n; ++k) {
    const auto ll = geo::latlon_from_tile_pixel(tile.id, t.u[k], t.v[k], 1);
    positions[k] = scene::ecef_from({ll->lat, ll->lon, double{t.height_m[k]}});
    ups[k] = scene::enu_axes_at(ll->lat, ll->lon).up;
  }
  mesh.indices.reserve(t.indices.size());
  for (std::size_t f = 0; f + 2 < t.indices.size(); f += 3) {
    std::uint32_t a = t.indices[f], b = t.indices[f + 1], c = t.indices[f + 2];
    glm::dvec3 face = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
    if (glm::dot(face, ups[a]) < 0.0) {  // the grid's winding: counter-clockwise seen from above
      std::swap(b, c);
      face = -face;
    }
    for (std::uint32_t k : {a, b, c}) normals[k] += face;
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  }
  mesh.vertices.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double length = glm::length(normals[k]);
    const glm::vec3 p = to_vec3(positions[k] - mesh.origin), nn = to_vec3(length > 0.0 ? normals[k] / length : ups[k]);
    mesh.vertices.push_back({p.x, p.y, p.z, nn.x, nn.y, nn.z, t.height_m[k], t.u[k], t.v[k], 1.0f});
  }
  // Skirts under the border edges (both ends on the same side of the tile).
  const auto side = [&](std::uint32_t k) {
    constexpr float e = 1e-6f;
    return (t.u[k] <= e ? 1 : 0) | (t.u[k] >= 1 - e ? 2 : 0) | (t.v[k] <= e ? 4 : 0) | (t.v[k] >= 1 - e ? 8 : 0);
  };
  const double depth = terrain::skirt_depth_m(tile.id, 64);
  const std::size_t surface_indices = mesh.indices.size();  // the skirts' own are not walked
  for (std::size_t f = 0; f + 2 < surface_indices; f += 3)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = mesh.indices[f + e], b = mesh.indices[f + (e + 1) % 3];
      if ((side(a) & side(b)) == 0) continue;
      const auto low = [&](std::uint32_t k) {
        TerrainVertex v = mesh.vertices[k];
        const glm::vec3 p = to_vec3(positions[k] - depth * ups[k] - mesh.origin);
        v.x = p.x;
        v.y = p.y;
        v.z = p.z;
        mesh.vertices.push_back(v);
        return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
      };
      const std::uint32_t a_low = low(a), b_low = low(b);
      mesh.indices.insert(mesh.indices.end(), {a, b, b_low, a, b_low, a_low});
    }
  return mesh;
}

}  // namespace

TerrainMesh build_terrain_mesh(const terrain::HeightTile& tile, std::uint32_t grid_vertices, float fill_height_m) {
  check_tile(tile);
  if (tile.triangles && !tile.triangles->indices.empty()) return triangles_mesh(tile, *tile.triangles);
  if (grid_vertices < 2)
    throw std::invalid_argument("terrain mesh: tile " + geo::to_string(tile.id) +
                                " needs at least 2 grid vertices, not " + std::to_string(grid_vertices));
  const std::uint32_t n = grid_vertices;
  const std::uint32_t cells = n - 1;

  // Heights and places of the grid first: the origin needs the mean height, the normals need the
  // neighbours' positions.
  std::vector<float> heights(std::size_t{n} * n);
  std::vector<float> covered(heights.size());
  std::vector<scene::GeoPosition> where(heights.size());
  double min_h = INFINITY, max_h = -INFINITY;
  for (std::uint32_t j = 0; j < n; ++j) {
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::size_t k = std::size_t{j} * n + i;
      float h = sample_height_bilinear(tile, static_cast<double>(i) / cells, static_cast<double>(j) / cells);
      covered[k] = std::isnan(h) ? 0.0f : 1.0f;
      if (std::isnan(h)) h = fill_height_m;
      heights[k] = h;
      min_h = std::min(min_h, static_cast<double>(h));
      max_h = std::max(max_h, static_cast<double>(h));
      const auto ll = geo::latlon_from_tile_pixel(tile.id, i, j, cells);
      where[k] = {ll->lat, ll->lon, h};
    }
  }

  TerrainMesh mesh;
  mesh.id = tile.id;
  mesh.grid_vertices = n;
  const auto centre = geo::latlon_from_tile_pixel(tile.id, 0.5, 0.5, 1);
  const glm::dvec3 origin = scene::ecef_from({centre->lat, centre->lon, 0.5 * (min_h + max_h)});
  mesh.origin = origin;

  std::vector<glm::dvec3> positions(heights.size());
  for (std::size_t k = 0; k < positions.size(); ++k) positions[k] = scene::ecef_from(where[k]);

  add_grid(mesh, heights, covered, where, positions, origin);
  add_skirts(mesh, tile.id, where, positions, origin);
  return mesh;
}

TerrainTileGpu upload_terrain_mesh(const TerrainMesh& mesh) {
  TerrainTileGpu gpu;
  gpu.origin = mesh.origin;
  for (const TerrainVertex& v : mesh.vertices)
    gpu.bounding_radius_m = std::max(gpu.bounding_radius_m, std::hypot(double{v.x}, double{v.y}, double{v.z}));
  gpu.vertex_array = VertexArray::create();
  gpu.vertices = Buffer::create();
  gpu.indices = Buffer::create();
  glBindVertexArray(gpu.vertex_array.id());
  glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(TerrainVertex)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  constexpr auto stride = static_cast<GLsizei>(sizeof(TerrainVertex));
  const auto attribute = [](GLuint location, GLint size, std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
  };
  attribute(0, 3, offsetof(TerrainVertex, x));
  attribute(1, 3, offsetof(TerrainVertex, nx));
  attribute(2, 1, offsetof(TerrainVertex, height_m));
  attribute(3, 2, offsetof(TerrainVertex, u));
  attribute(4, 1, offsetof(TerrainVertex, covered));
  glBindVertexArray(0);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
    throw RenderError("uploading the terrain mesh of tile " + geo::to_string(mesh.id) + " failed (GL error " +
                      std::to_string(error) + ")");
  gpu.index_count = static_cast<GLsizei>(mesh.indices.size());
  gpu.gpu_bytes = mesh.vertices.size() * sizeof(TerrainVertex) + mesh.indices.size() * sizeof(std::uint32_t);
  gpu.has_holes =
      std::any_of(mesh.vertices.begin(), mesh.vertices.end(), [](const TerrainVertex& v) { return v.covered < 1.0f; });
  return gpu;
}

const TerrainTileGpu& TerrainMeshCache::get_or_upload(const terrain::HeightTile& tile, std::uint32_t grid_vertices,
                                                      float fill_height_m) {
  const Key key{tile.id, grid_vertices};
  const bool in_use = tiles_.used_this_frame(key);
  if (const Entry* entry = tiles_.find(key)) {
    if (!entry->gpu.has_holes || entry->fill_height_m == fill_height_m) return entry->gpu;
    // Replacing it would leave this frame's draw list pointing at a deleted mesh.
    if (in_use)
      throw std::logic_error("terrain mesh of tile " + geo::to_string(tile.id) +
                             " asked for with two fill heights in one frame");
  }
  TerrainTileGpu gpu = upload_terrain_mesh(build_terrain_mesh(tile, grid_vertices, fill_height_m));
  const std::size_t bytes = gpu.gpu_bytes;
  return tiles_.insert(key, Entry{std::move(gpu), fill_height_m}, bytes).gpu;
}

}  // namespace trailray::render
