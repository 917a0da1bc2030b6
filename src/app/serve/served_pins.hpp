#pragma once
// What `trailray serve` adds to the page's scene beside the tracks: the photos of --photos
// (placed on the served tracks at start, their thumbnails decoded once and kept as JPEG; the
// larger picture the page shows when a pin is clicked decoded again on request) and the places of
// --places (read around the tracks at start). Both are described in /api/config.json:
//   "photos": [{"name": "DSCN0010.jpg", "lat", "lon", "ele", "ground", "time",
//               "thumbnail": "/api/photos/0.jpg", "large": "/api/photos/0/large.jpg"}, ...]
//   "places": [{"name": "Eiger 3967 m", "lat", "lon", "ele", "ground", "kind": "peak", "priority"}, ...]
// "ele" where the pin's marker stands (null: on the ground), "ground" the terrain below it
// (null: unknown), "time" seconds since 1970 UTC (null: unknown); "thumbnail" and "large" null
// for a photo that could not be decoded (a plain pin).

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "app/serve/http_server.hpp"
#include "scene/pictures/rgba_image.hpp"
#include "scene/pins/waypoints.hpp"
#include "terrain/loading/stop_token.hpp"

namespace trailray::app::serve {

// The larger picture's long side: what the desktop viewer decodes to show a photo enlarged
// (PinStyle::photo_px x kEnlargedPhotoScale x 2, rounded up).
inline constexpr int kLargePhotoLongSidePx = 640;

struct ServedPhoto {
  std::string path;                     // the photo's file, read again for the larger picture
  int orientation = 1;                  // its EXIF orientation
  std::vector<unsigned char> thumbnail;  // JPEG; empty: the photo could not be decoded
};

// "/api/photos/3.jpg", or "/api/photos/3/large.jpg".
std::string photo_url(std::size_t index, bool large);

// Pixels as a JPEG (quality 88: a photo, not a tile of heights); alpha is dropped.
std::vector<unsigned char> encode_photo_jpeg(const scene::RgbaImage& image);

// The thumbnail kept at start (404 when there is none).
HttpResponse photo_thumbnail_response(const ServedPhoto& photo);
// The photo decoded again at kLargePhotoLongSidePx (on the job pool: a 12 MP JPEG takes tens of
// milliseconds); 404 when it can no longer be read.
HttpResponse large_photo_response(const ServedPhoto& photo, terrain::StopToken stop);

// "photos" above from the photos' pins (scene/pins/photo_pins, in the order served) and whether each
// has a thumbnail; "places" from the places' pins (scene/pins/place_labels).
nlohmann::json photos_json(const std::vector<scene::Waypoint>& pins, const std::vector<ServedPhoto>& photos);
nlohmann::json places_json(const std::vector<scene::Waypoint>& pins);

}  // namespace trailray::app::serve
