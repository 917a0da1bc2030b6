#pragma once
// The pins `trailray serve` hands the page beside its tracks (app/serve/served_pins.hpp): the
// places of --places as scene waypoints of kind Place and the photos of --photos as pins of kind
// Photo, plain pins until their thumbnails arrive (the page's JavaScript fetches them and passes
// the bytes in); the labels pass draws both, as `render` and `view` draw them.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "scene/pins/photo_image.hpp"
#include "scene/pins/waypoints.hpp"

namespace trailray::web {

struct ServedPins {
  std::vector<scene::Waypoint> points;  // the places, then the photos (in the order served)
  std::size_t first_photo = 0;          // the index of photo 0 among `points`
  std::vector<std::string> large_urls;  // photo i's larger picture ("": none)
};

// From the JSON of serve's /api/config.json ({"photos": [...], "places": [...]}: either may be
// absent); each marker at its "ele", else on its "ground", else on `neutral_ground_m`. Entries
// without valid coordinates are left out. Throws std::runtime_error on JSON that is not an
// object of such lists.
ServedPins served_pins(std::string_view json, double neutral_ground_m);

// A photo's picture (JPEG, PNG or WebP bytes, as the tiles are decoded) for its pin. Throws
// terrain::TileDecodeError for bytes that are no such image.
std::shared_ptr<const scene::PhotoImage> decode_photo_bytes(std::string_view bytes);

}  // namespace trailray::web
