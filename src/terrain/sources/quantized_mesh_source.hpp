#pragma once
// Quantized-mesh terrain as a height source: Cesium's layer.json and its .terrain tiles, from a
// folder or a server (what cesium-terrain-builder, Cesium ion exports and AlpineMaps' terrain
// builder write). layer.json gives the tiles' template ("{z}/{x}/{y}.terrain?v={version}"), the
// scheme (tms, rows from the south, unless "xyz"), the projection (EPSG:4326: two tiles at zoom
// 0, each 180 degrees square; or EPSG:3857), the zoom range and the bounds.
//
// Heights are read off the triangles as they are: sample_native (what `elevation` and every
// track's ground use) finds the finest level's triangle under a point and weighs its vertices
// barycentrically, no grid in between. The renderer's tiles are Web Mercator tiles: load() gives
// each the layer's own triangles clipped to it (HeightTile::triangles, drawn as they are), and
// its grid of samples from the mesh the same exact way (what the level of detail and the
// in-memory sampling read).
//
// Tiles missing from the folder or answered 404 are no data; tiles from a server are not kept in
// the disk cache (the decoded meshes of the last tiles used are kept in memory).

#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_set>

#include "terrain/codecs/quantized_mesh.hpp"
#include "terrain/sources/terrain_config.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::terrain {

class HttpClient;

// layer.json as read.
struct QuantizedMeshLayer {
  std::string tiles;          // the first template, relative to layer.json's folder or URL
  std::string version = "1.0.0";
  bool tms = true;            // rows from the south
  bool geographic = true;     // EPSG:4326 (else EPSG:3857)
  int min_zoom = 0, max_zoom = 0;
  std::optional<geo::LatLonBounds> bounds;
};

// Throws SourceError naming the file for JSON that is not a quantized-mesh layer.
QuantizedMeshLayer parse_quantized_mesh_layer(const std::string& json_text, const std::string& name);

// Whether `folder` holds a layer.json (the quantized-mesh folder layout), and whether `url` names one.
bool is_quantized_mesh_folder(const std::string& folder);
bool is_quantized_mesh_url(const std::string& url);

class QuantizedMeshSource final : public HeightSource {
 public:
  // `location`: a folder holding layer.json, or the URL of a layer.json. Throws SourceError when
  // layer.json cannot be had or read.
  QuantizedMeshSource(const std::string& location, const NetworkSettings& network = {});
  ~QuantizedMeshSource() override;

  const SourceInfo& info() const override { return info_; }
  TileResult<HeightTile> load(const TileId& tile, StopToken stop) override;
  std::optional<double> sample_native(double lat, double lon) override;

  // The mesh tile (z, x, y in the layer's own numbering: XYZ rows from the north) holding a place.
  std::optional<geo::TileId> mesh_tile_at(double lat, double lon, int zoom) const;

 private:
  // A place in a mesh tile: the tile, and fractions across it from its south-west corner (the
  // mesh's u, v), or the inverse: a mesh tile's fractions as a place (lat, lon).
  struct MeshPlace {
    geo::TileId tile;
    double x = 0.0, y = 0.0;
  };
  std::optional<MeshPlace> mesh_place(double lat, double lon, int zoom) const;
  // The mesh last used, so the 65,536 samples of a tile do not each lock and search the kept ones.
  struct LastMesh {
    std::optional<std::uint64_t> key;
    std::shared_ptr<const MeshHeights> mesh;  // null: no tile there
  };
  std::shared_ptr<const MeshHeights> mesh(const geo::TileId& id, StopToken stop, std::string* error);
  // The layer's triangles over a Mercator tile, clipped to it; null when none (or too many tiles).
  std::shared_ptr<const TileTriangles> triangles_over(const TileId& id, int mesh_zoom, StopToken stop);
  double height_at(double lat, double lon, int zoom, StopToken stop, std::string* error, LastMesh* last = nullptr);

  std::string location_;
  bool remote_ = false;
  QuantizedMeshLayer layer_;
  SourceInfo info_;
  std::unique_ptr<HttpClient> http_;
  bool offline_ = false;
  std::mutex mutex_;
  std::list<std::pair<std::uint64_t, std::shared_ptr<const MeshHeights>>> recent_;  // most recent first
  std::unordered_set<std::uint64_t> missing_;                                        // tiles with no data
};

}  // namespace trailray::terrain
