#pragma once
// What `trailray serve` answers, path by path (the HTTP contract the web page reads):
//   GET /, /<file>                       the web app's files from the web root (a page that says
//                                        how to build the app where the root has no index.html)
//   GET /api/config.json                 what the page shows: tracks, tile URLs, options, photos, places
//   GET /api/photos/<index>.jpg          a --photos photo's thumbnail (served_pins.hpp)
//   GET /api/photos/<index>/large.jpg    the same photo larger, for the page's enlarged view
//   GET /tracks/<index>/<name>           the index-th TRACK file, its bytes as on disk
//   GET /tiles/terrain/{z}/{x}/{y}.png   heights as Terrarium PNG (tile_answers.hpp)
//   GET /tiles/imagery/{z}/{x}/{y}       imagery tiles
// Anything else 404; methods other than GET and HEAD 405; a target that could climb out of a
// folder 400 (request_path.hpp). Bound to loopback, only requests naming a loopback host are
// answered (a web page whose name was made to point at 127.0.0.1, DNS rebinding, gets 403).

#include <string>
#include <vector>

#include "app/serve/http_server.hpp"
#include "app/serve/served_pins.hpp"
#include "app/serve/web_root.hpp"
#include "terrain/sources/tile_source.hpp"

namespace trailray::app::serve {

struct ServedTrack {
  std::string path;  // as given (expanded)
  std::string name;  // its file name, the last segment of its URL
};

struct ServeSite {
  WebRoot web_root{std::filesystem::path()};
  std::vector<ServedTrack> tracks;
  terrain::HeightSource* heights = nullptr;  // nullptr: --terrain none
  int terrain_max_zoom = 0;
  terrain::ImagerySource* imagery = nullptr;  // nullptr: --imagery none
  int imagery_max_zoom = 0;
  std::vector<ServedPhoto> photos;  // --photos, in the order of config.json's "photos"
  std::string config_json;  // the body of /api/config.json
  bool loopback_hosts_only = true;
};

// The URL of track `index` ("/tracks/0/flight.igc", its name percent-encoded).
std::string track_url(std::size_t index, const std::string& name);

// Quick answers now, tiles later (on the server's job pool).
HttpAnswer answer_request(const ServeSite& site, const HttpRequest& request);

// Whether a Host header names a loopback host (127.x.y.z, localhost, [::1], with or without a port).
bool is_loopback_host(std::string_view host);

}  // namespace trailray::app::serve
