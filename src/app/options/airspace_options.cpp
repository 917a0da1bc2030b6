#include "app/options/airspace_options.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geo/wgs84.hpp"
#include "scene/volumes/airspace_volumes.hpp"
#include "scene/volumes/volume_shapes.hpp"
#include "track/airspace/openair_reader.hpp"

namespace trailray::app {
namespace {

// Around a camera without tracks: what it sees of a country's airspaces.
constexpr double kCameraRegionMarginM = 40000.0;
// Levelling: airspaces whose floor is more than this above the flight's highest point are left
// out, and ceilings are drawn up to a cap above it (faded there); without tracks, fixed heights.
constexpr double kFloorAboveFlightM = 2000.0;
constexpr double kMinFloorLimitM = 4500.0;
constexpr double kCapAboveFloorLimitM = 1500.0;

}  // namespace

void add_airspace_options(CLI::App& command, AirspaceArgs& args) {
  command
      .add_option("--airspace", args.files,
                  "Airspaces from an OpenAir file (as `trailray check` reads), drawn as translucent walls "
                  "coloured by class around the tracks: those near the tracks, up to 2000 m above their "
                  "highest point; flight levels drawn by the standard atmosphere. Repeatable")
      ->type_name("FILE")
      ->allow_extra_args(false);  // one file per --airspace: the words after it are tracks
}

AirspaceRegion airspace_region(const scene::TrackSet& tracks, const scene::WaypointSet& waypoints,
                               const CameraRequest& camera) {
  AirspaceRegion out;
  geo::LatLonBounds box;
  for (const scene::Track& t : tracks.tracks()) {
    if (!t.visible) continue;
    for (const scene::TrackPolyline& segment : t.geometry.segments)
      for (const glm::dvec3& p : segment.points_ecef) {
        const geo::Geodetic g = geo::geodetic_from_ecef(p);
        box.add(g.lat_deg, g.lon_deg);
        out.highest_m = std::isnan(out.highest_m) ? g.height_m : std::max(out.highest_m, g.height_m);
      }
  }
  if (box.empty())
    for (const scene::Waypoint& w : waypoints.points)
      if (w.visible) box.add(w.lat_deg, w.lon_deg);
  if (box.empty() && (camera.placement || camera.look_at)) {
    const scene::GeoPosition& where = camera.placement ? camera.placement->position : camera.look_at->target;
    box.add(where.lat_deg, where.lon_deg);
    const double dlat = kCameraRegionMarginM / 111320.0;
    const double dlon = dlat / std::max(std::cos(where.lat_deg * M_PI / 180.0), 0.05);
    box.add(where.lat_deg - dlat, where.lon_deg - dlon);
    box.add(where.lat_deg + dlat, where.lon_deg + dlon);
  }
  if (!box.empty()) out.bounds = box;
  return out;
}

void add_airspace_volumes(scene::VolumeSet& set, const std::vector<std::string>& files, const AirspaceRegion& region,
                          terrain::HeightSource* heights, scene::Diagnostics& diagnostics) {
  scene::AirspaceDrawOptions options;
  options.region = region.bounds;
  options.max_floor_m =
      std::isnan(region.highest_m) ? kMinFloorLimitM : std::max(kMinFloorLimitM, region.highest_m + kFloorAboveFlightM);
  options.ceiling_cap_m = options.max_floor_m + kCapAboveFloorLimitM;
  for (const std::string& path : files) {
    const track::airspace::AirspaceReadResult read = track::airspace::load_openair_file(path);
    for (const track::Diagnostic& w : read.warnings) diagnostics.warning(w.to_string());
    if (read.error) throw std::runtime_error(read.error->to_string());
    scene::AirspaceVolumes built = scene::airspace_volumes(read.file, path, options);
    const std::size_t left_out = built.outside_region + built.above_floor + built.over_cap;
    diagnostics.note(fmt::format("{}: {} of {} airspaces drawn ({} boundary points of {})", path, built.volumes.size(),
                                 read.file.airspaces.size(), built.points_after, built.points_before));
    // Culled and levelled as intended: a note; the cap reached (near airspaces not drawn): a warning.
    if (built.over_cap > 0)
      diagnostics.warning(fmt::format("{}: {} airspaces near the tracks not drawn (at most {} are): the nearest kept",
                                      path, built.over_cap, options.max_volumes));
    if (left_out > 0)
      diagnostics.note(fmt::format(
          "{}: left out {} away from the tracks, {} with a floor above {:.0f} m, {} over "
          "the limit of {} drawn",
          path, built.outside_region, built.above_floor, options.max_floor_m, built.over_cap, options.max_volumes));
    for (scene::Volume& v : built.volumes) set.volumes.push_back(std::move(v));
  }
  scene::place_volumes_on_ground(set, heights);
  ++set.revision;
}

}  // namespace trailray::app
