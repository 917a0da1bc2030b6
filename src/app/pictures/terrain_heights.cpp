#include "app/pictures/terrain_heights.hpp"

#include <fmt/format.h>

#include <limits>
#include <memory>

#include "terrain/height_sampler.hpp"
#include "terrain/sources/source_factory.hpp"

namespace trailray::app {

TerrainHeights terrain_heights(const std::vector<geo::LatLon>& where, const TerrainOptions& terrain,
                               scene::Diagnostics& diagnostics, const std::string& file) {
  const terrain::TerrainConfig config = resolve_terrain_config(terrain);
  terrain::SourceContext context{config.network, config.cache,
                                 [&diagnostics](std::string w) { diagnostics.warning("terrain: " + w); }};
  std::unique_ptr<terrain::HeightSource> source = terrain::open_height_source(config.terrain, context);
  TerrainHeights out;
  out.source_name = source ? source->info().name : std::string("none");
  out.heights.assign(where.size(), std::numeric_limits<double>::quiet_NaN());
  if (!source) return out;
  terrain::HeightSamplerOptions options;
  if (terrain.terrain_zoom) options.zoom = *terrain.terrain_zoom;
  // Network sources wait on round trips, not on the CPU.
  if (source->info().name.starts_with("http")) options.threads = static_cast<unsigned>(config.network.max_parallel) + 2;
  terrain::HeightSampler sampler(*source, options);
  out.heights = sampler.sample(where, [&](const terrain::LoadProgress& p, std::size_t batch, std::size_t batches) {
    diagnostics.progress(fmt::format("terrain tiles: {}/{} loaded{}{}", p.loaded + p.no_data, p.wanted,
                                     p.failed ? fmt::format(", {} failed", p.failed) : "",
                                     batches > 1 ? fmt::format(" (part {}/{})", batch + 1, batches) : ""));
  });
  diagnostics.progress_done();
  const terrain::SamplingReport& r = sampler.report();
  out.tiles_failed = r.tiles_failed;
  if (r.tiles_failed > 0)
    diagnostics.warning(fmt::format("terrain: {} tile{} failed; first: {}", r.tiles_failed,
                                    r.tiles_failed == 1 ? "" : "s", r.errors.empty() ? "?" : r.errors.front()));
  if (!where.empty() && r.with_height == 0)
    diagnostics.warning(fmt::format("terrain: {} has no data at any point of {}", out.source_name, file));
  else if (r.with_height < where.size())
    diagnostics.warning(fmt::format("terrain: no data at {} of {} points", where.size() - r.with_height, where.size()));
  return out;
}

TerrainHeights surface_heights(const std::vector<geo::LatLon>& where, const TerrainOptions& terrain,
                               scene::Diagnostics& diagnostics, const std::string& file) {
  if (terrain.surface.empty()) return {};
  TerrainOptions surface = terrain;
  surface.terrain = terrain.surface;
  return terrain_heights(where, surface, diagnostics, file);
}

}  // namespace trailray::app
