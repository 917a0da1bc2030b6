// check --terrain: the ground under the checked points. A file of its own: it is what pulls the
// terrain layer (GDAL, HTTP) into a program, and the light `trailray` runs `check` without it.
#include <fmt/format.h>

#include <memory>

#include "app/flight/airspace_check.hpp"
#include "app/flight/check_command.hpp"
#include "app/options/terrain_options.hpp"
#include "terrain/height_sampler.hpp"
#include "terrain/sources/source_factory.hpp"

namespace trailray::app {

void add_ground_heights(const TerrainOptions& terrain, scene::Diagnostics& diagnostics, bool quiet,
                        std::vector<CheckSegments>& tracks) {
  if (terrain.terrain.empty()) return;
  const terrain::TerrainConfig config = resolve_terrain_config(terrain);
  terrain::SourceContext context{config.network, config.cache,
                                 [&diagnostics](std::string w) { diagnostics.warning("terrain: " + w); }};
  std::unique_ptr<terrain::HeightSource> source = terrain::open_height_source(config.terrain, context);
  if (!source) return;
  std::vector<geo::LatLon> where;
  for (const auto& t : tracks)
    for (const auto& s : t)
      for (const auto& p : s) where.push_back({p.lat, p.lon});
  terrain::HeightSampler sampler(*source, {});
  const std::vector<double> heights =
      sampler.sample(where, [&](const terrain::LoadProgress& p, std::size_t, std::size_t) {
        if (!quiet) diagnostics.progress(fmt::format("terrain tiles: {}/{} loaded", p.loaded + p.no_data, p.wanted));
      });
  diagnostics.progress_done();
  std::size_t k = 0;
  for (auto& t : tracks)
    for (auto& s : t)
      for (auto& p : s) p.ground_m = heights[k++];
  if (sampler.report().with_height < where.size())
    diagnostics.warning(fmt::format("terrain: no data at {} of {} points (AGL limits there taken conservatively)",
                                    where.size() - sampler.report().with_height, where.size()));
}

CheckTerrain check_terrain() { return {&add_terrain_options, &add_ground_heights}; }

}  // namespace trailray::app
