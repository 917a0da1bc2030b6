#include "app/serve/serve_command.hpp"

#include <CLI/CLI.hpp>
#include <sys/resource.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

#include "app/common/interrupt_guard.hpp"
#include "app/common/parallel_jobs.hpp"
#include "app/common/terminal_diagnostics.hpp"
#include "app/common/track_arguments.hpp"
#include "app/common/track_reading.hpp"
#include "app/drawing/photo_drawing.hpp"
#include "app/drawing/scene_setup.hpp"
#include "app/options/camera_options.hpp"
#include "app/options/photo_options.hpp"
#include "app/options/places_options.hpp"
#include "app/options/style_options.hpp"
#include "app/options/terrain_options.hpp"
#include "app/options/track_options.hpp"
#include "app/serve/http_server.hpp"
#include "app/serve/serve_config.hpp"
#include "app/serve/serve_site.hpp"
#include "app/serve/served_pins.hpp"
#include "scene/pins/place_labels.hpp"

#ifndef TRAILRAY_WEB_ROOT
#define TRAILRAY_WEB_ROOT "web"
#endif

namespace trailray::app {
namespace {

struct ServeArgs {
  std::vector<std::string> tracks;
  int port = 8123;
  std::string bind = "127.0.0.1";
  std::string web_root = TRAILRAY_WEB_ROOT;
  unsigned max_connections = 256;
  std::optional<unsigned> max_connections_per_address;
  unsigned idle_timeout_s = 30;
  CameraArgs camera;
  StyleArgs style;
  TrackOptions track_options;  // --strict, --igc-altitude and the cleaning
  TerrainOptions terrain;
  PhotoArgs photos;         // --photos: pins with thumbnails on the page
  std::string places_file;  // --places: labels on the page
  std::vector<const CLI::Option*> page_options;  // those the page takes, told in /api/config.json
};

// Each TRACK file read once at start: a file that cannot be read is an error here (file and
// position), not a page that shows nothing. The files as read are handed to `keep` when given
// (--surface finds the tracks under cover from them).
std::vector<serve::ServedTrack> read_served_tracks(const ServeArgs& a, TerminalDiagnostics& diagnostics,
                                                   std::vector<scene::LoadedTrackFile>* keep) {
  const std::vector<std::string> paths = expand_track_arguments(a.tracks);
  for (const std::string& path : paths)
    if (path == "-") throw CLI::ValidationError("TRACK", "- (standard input) cannot be served: give files");
  std::vector<TrackFileOutcome> outcomes = read_track_file_outcomes(paths, a.track_options.read, {}, &diagnostics);
  diagnostics.progress_done();
  std::vector<serve::ServedTrack> tracks;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    for (const std::string& w : outcomes[i].warnings) diagnostics.warning(w);
    if (outcomes[i].error) throw std::runtime_error(*outcomes[i].error);
    tracks.push_back({paths[i], std::filesystem::path(paths[i]).filename().string()});
    if (keep && outcomes[i].loaded) keep->push_back(std::move(*outcomes[i].loaded));
  }
  return tracks;
}

// --photos and --places for the page: the photos placed on the served tracks (a warning for each
// one that is not), their thumbnails decoded once; the places read around the tracks. Their pins
// described in `photos` and `places` (serve/served_pins.hpp), the thumbnails kept in the site.
void serve_photos_and_places(const ServeArgs& a, const scene::TrackSet& tracks,
                             const scene::WaypointBuildOptions& placing, serve::ServeSite& site,
                             nlohmann::json& photos, nlohmann::json& places, TerminalDiagnostics& diagnostics) {
  if (a.photos.any()) {
    scene::WaypointSet pins;  // the page makes its own pins from the JSON
    const ScenePhotos scene_photos = add_scene_photos(a.photos, tracks, pins, placing, diagnostics);
    for (std::size_t i = 0; i < scene_photos.placed.size(); ++i) {
      serve::ServedPhoto& p = site.photos.emplace_back();
      p.path = scene_photos.placed[i].photo.path;
      p.orientation = scene_photos.placed[i].photo.orientation;
      if (scene_photos.thumbnails[i]) p.thumbnail = serve::encode_photo_jpeg(scene_photos.thumbnails[i]->pixels);
    }
    photos = serve::photos_json(pins.points, site.photos);
  }
  if (!a.places_file.empty())
    places = serve::places_json(osm_place_labels(a.places_file, tracks, scene::WaypointSet{}, placing, diagnostics));
}

// Each connection holds a socket: make room for the limit when the soft limit is lower.
void raise_file_limit(unsigned connections) {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return;
  const rlim_t wanted = static_cast<rlim_t>(connections) + 256;
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur < wanted) {
    limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? wanted : std::min(wanted, limit.rlim_max);
    setrlimit(RLIMIT_NOFILE, &limit);
  }
}

std::string url_of(const std::string& bind, int port) {
  const std::string host = bind == "localhost" ? "127.0.0.1" : bind;
  return host.find(':') != std::string::npos ? fmt::format("http://[{}]:{}/", host, port)
                                             : fmt::format("http://{}:{}/", host, port);
}

int run_serve(const ServeArgs& a) {
  // The page's options are checked as `render` checks them, so a typo fails here, not in the page.
  (void)parse_style(a.style);
  (void)parse_sun_time(a.style.time);
  (void)parse_camera_request(a.camera, true);
  (void)parse_lens("1920x1080", a.camera.fov_deg);
  TerminalDiagnostics diagnostics;

  serve::ServeSite site;
  // The files are kept when the tracks are built here too: --surface, --photos, --places.
  const bool build_here = !a.terrain.surface.empty() || a.photos.any() || !a.places_file.empty();
  std::vector<scene::LoadedTrackFile> files;
  site.tracks = read_served_tracks(a, diagnostics, build_here ? &files : nullptr);
  site.web_root = serve::WebRoot(a.web_root);
  const TerrainSources sources = open_terrain_sources(a.terrain, diagnostics, /*imagery_without_terrain=*/true);
  nlohmann::json photos = nlohmann::json::array(), places = nlohmann::json::array();
  if (build_here) {
    // The tracks as `render` builds them: --surface's cut follows them, the photos are placed on
    // them and the places read around them.
    const scene::RecordedPoints recorded = scene::recorded_points(files);
    scene::TrackBuildOptions build{sources.heights.get(), 0.0, {}};
    build.surface = sources.surface.get();
    build.analysis = a.track_options.analysis;
    build.neutral_ground_m = recorded.lowest_or_sea_level();
    scene::TrackSet served;
    for (scene::Track& t : scene::build_tracks(files, parse_style(a.style).tracks, build, diagnostics))
      served.add(std::move(t));
    // --surface: the page draws what it is served as terrain, the surface with the canopy cut
    // along the tracks under cover (found here, as `render` finds them); points without an
    // elevation then stand on the ground there, and the open needs no cut.
    if (sources.drawn_surface) sources.cut_canopy(served);
    const scene::WaypointBuildOptions placing{sources.drawn(), build.neutral_ground_m};
    serve_photos_and_places(a, served, placing, site, photos, places, diagnostics);
  }
  site.heights = sources.drawn();
  site.imagery = sources.imagery.get();
  if (site.heights != nullptr)
    site.terrain_max_zoom = std::min(site.heights->info().max_zoom, a.terrain.terrain_zoom.value_or(geo::kMaxTileZoom));
  if (site.imagery != nullptr) site.imagery_max_zoom = site.imagery->info().max_zoom;
  site.config_json =
      serve::serve_config(site.tracks,
                          serve::tile_layer(site.heights ? &site.heights->info() : nullptr,
                                            "/tiles/terrain/{z}/{x}/{y}.png", site.terrain_max_zoom, true),
                          serve::tile_layer(site.imagery ? &site.imagery->info() : nullptr,
                                            "/tiles/imagery/{z}/{x}/{y}", site.imagery_max_zoom, false),
                          serve::given_options(a.page_options), sources.overlay_legend,
                          std::move(photos), std::move(places))
          .dump(2);
  const bool loopback = serve::is_loopback_address(a.bind);
  site.loopback_hosts_only = loopback;
  if (!site.web_root.has_index())
    diagnostics.warning(
        fmt::format("no web app in {} (build it with scripts/web.sh, or give --web-root DIR); / says so", a.web_root));

  serve::HttpServerOptions options;
  options.bind = a.bind;
  options.port = a.port;
  options.max_connections = a.max_connections;
  // On loopback every client is this machine's user; beyond it one address may not take all.
  options.max_connections_per_address =
      a.max_connections_per_address.value_or(loopback ? 0u : std::max(1u, a.max_connections / 8));
  options.idle_timeout_s = a.idle_timeout_s;
  // Tiles from a server wait on round trips, not on the CPU.
  const bool online = (site.heights && site.heights->info().name.starts_with("http")) ||
                      (site.imagery && site.imagery->info().name.starts_with("http"));
  options.workers = std::max(2u, default_job_threads()) + (online ? 8u : 0u);
  raise_file_limit(a.max_connections);

  InterruptGuard interrupt;  // before the first line: a SIGTERM right after it stops cleanly
  serve::HttpServer server(options, [&site](const serve::HttpRequest& r) { return serve::answer_request(site, r); });
  std::cout << "trailray: serving on " << url_of(a.bind, server.port()) << std::endl;
  if (!loopback) {
    const bool everywhere = a.bind == "0.0.0.0" || a.bind == "::";
    diagnostics.warning(fmt::format(
        "listening on {} (--bind): every machine that reaches this one can read the tracks "
        "and tiles served{}",
        a.bind,
        everywhere ? fmt::format("; on this machine open http://127.0.0.1:{}/", server.port()) : std::string()));
  }
  while (!interrupt_requested()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::cerr << "trailray: stopping\n";
  return 0;
}

}  // namespace

void add_serve_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ServeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "serve", "Serve the web app, the given tracks and the terrain and imagery as tiles over HTTP, for any browser");
  cmd->footer(
      "Open the printed URL in a browser: the page shows the tracks on the terrain with the style and camera\n"
      "options given here. Paths (read-only, GET and HEAD):\n"
      "  /                                 the web app (--web-root)\n"
      "  /api/config.json                  tracks, tile URLs and options for the page\n"
      "  /tracks/N/NAME                    the N-th TRACK file as it is on disk\n"
      "  /api/photos/N.jpg                 the N-th placed photo's thumbnail (--photos)\n"
      "  /api/photos/N/large.jpg           the same photo larger, shown when its pin is clicked\n"
      "  /tiles/terrain/{z}/{x}/{y}.png    heights from --terrain as Terrarium PNG\n"
      "  /tiles/imagery/{z}/{x}/{y}        imagery tiles from --imagery (PNG, JPEG or WebP)\n"
      "Only 127.0.0.1 by default; --bind 0.0.0.0 opens it to the network. Stops on Ctrl-C or SIGTERM.\n"
      "Exit status: 0 stopped, 1 a file, source or the port failed, 2 a usage error.");
  cmd->add_option("TRACK", args->tracks,
                  "Track files (GPX, IGC, TCX, FIT, KML, KMZ, GeoJSON), folders of them, or patterns ('flights/*.igc')")
      ->type_name("FILE");
  cmd->add_option("--port", args->port, "TCP port (default 8123; 0 picks a free one)")
      ->check(CLI::Range(0, 65535))
      ->type_name("N");
  cmd->add_option("--bind", args->bind,
                  "Address to listen on (default 127.0.0.1: this machine only; 0.0.0.0 or :: for every network)")
      ->type_name("ADDR");
  cmd->add_option("--web-root", args->web_root,
                  std::string("Folder of the built web app (default ") + TRAILRAY_WEB_ROOT + ")")
      ->type_name("DIR");
  cmd->add_option("--max-connections", args->max_connections, "Connections served at once (default 256)")
      ->check(CLI::Range(1u, 100000u))
      ->type_name("N");
  cmd->add_option("--max-connections-per-address", args->max_connections_per_address,
                  "Connections one client address may hold (default: no limit on loopback, else an eighth of "
                  "--max-connections)")
      ->check(CLI::Range(1u, 100000u))
      ->type_name("N");
  cmd->add_option("--idle-timeout", args->idle_timeout_s,
                  "Seconds a connection may stay silent before it is closed (default 30)")
      ->check(CLI::Range(1u, 3600u))
      ->type_name("S");
  add_terrain_options(*cmd, args->terrain);
  add_imagery_option(*cmd, args->terrain);
  add_photo_options(*cmd, args->photos);
  add_places_option(*cmd, args->places_file, PlacesUse::labels);
  // Everything added from here on is an option of the page, told to it in /api/config.json.
  const std::size_t before_page_options = cmd->get_options().size();
  add_camera_options(*cmd, args->camera);
  add_track_style_options(*cmd, args->style);
  add_shading_options(*cmd, args->style);
  add_label_options(*cmd, args->style);
  add_track_options(*cmd, args->track_options);
  args->page_options = serve::options_added_since(*cmd, before_page_options);
  cmd->callback([args, &exit_code] { exit_code = run_serve(*args); });
}

}  // namespace trailray::app
