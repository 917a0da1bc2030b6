#include "app/serve/served_pins.hpp"

#include <fmt/format.h>

#include <cmath>

#include "scene/pins/photo_decode.hpp"
#include "terrain/codecs/image_codec.hpp"

namespace trailray::app::serve {
namespace {

// The photos do not change while the server runs: the browser may keep them for the session.
constexpr const char* kPhotoCacheControl = "max-age=3600";

HttpResponse jpeg_response(std::vector<unsigned char> bytes) {
  HttpResponse r;
  r.content_type = "image/jpeg";
  r.body.assign(bytes.begin(), bytes.end());
  r.headers.emplace_back("Cache-Control", kPhotoCacheControl);
  r.headers.emplace_back("X-Content-Type-Options", "nosniff");
  return r;
}

// NaN as null (nlohmann writes NaN as null too, but says so here).
nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// Where the pin's marker stands: its elevation, never below the ground (build_waypoints' rule),
// null where it stands on the ground.
nlohmann::json marker_elevation(const scene::Waypoint& w) {
  if (!std::isfinite(w.ele_m)) return nullptr;
  return std::isfinite(w.ground_m) ? std::max(w.ele_m, w.ground_m) : w.ele_m;
}

}  // namespace

std::string photo_url(std::size_t index, bool large) {
  return large ? fmt::format("/api/photos/{}/large.jpg", index) : fmt::format("/api/photos/{}.jpg", index);
}

std::vector<unsigned char> encode_photo_jpeg(const scene::RgbaImage& image) {
  terrain::DecodedImage rgb;
  rgb.format = terrain::ImageFormat::jpeg;
  rgb.width = image.width;
  rgb.height = image.height;
  rgb.channels = 3;
  rgb.samples8.reserve(std::size_t{image.width} * image.height * 3);
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
    rgb.samples8.insert(rgb.samples8.end(), image.rgba.begin() + static_cast<std::ptrdiff_t>(i),
                        image.rgba.begin() + static_cast<std::ptrdiff_t>(i + 3));
  return terrain::encode_jpeg(rgb, 88);
}

HttpResponse photo_thumbnail_response(const ServedPhoto& photo) {
  if (photo.thumbnail.empty()) return text_response(404, "this photo could not be decoded");
  return jpeg_response(photo.thumbnail);
}

HttpResponse large_photo_response(const ServedPhoto& photo, terrain::StopToken stop) {
  if (stop.stop_requested()) return text_response(503, "the server is stopping");
  try {
    return jpeg_response(
        encode_photo_jpeg(scene::decode_photo(photo.path, kLargePhotoLongSidePx, photo.orientation)));
  } catch (const scene::PhotoDecodeError& e) {
    return text_response(404, e.what());
  }
}

nlohmann::json photos_json(const std::vector<scene::Waypoint>& pins, const std::vector<ServedPhoto>& photos) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < pins.size() && i < photos.size(); ++i) {
    const scene::Waypoint& w = pins[i];
    const bool decoded = !photos[i].thumbnail.empty();
    out.push_back({{"name", w.name},
                   {"lat", w.lat_deg},
                   {"lon", w.lon_deg},
                   {"ele", marker_elevation(w)},
                   {"ground", number_or_null(w.ground_m)},
                   {"time", number_or_null(w.time_unix_s)},
                   {"thumbnail", decoded ? nlohmann::json(photo_url(i, false)) : nlohmann::json(nullptr)},
                   {"large", decoded ? nlohmann::json(photo_url(i, true)) : nlohmann::json(nullptr)}});
  }
  return out;
}

nlohmann::json places_json(const std::vector<scene::Waypoint>& pins) {
  nlohmann::json out = nlohmann::json::array();
  for (const scene::Waypoint& w : pins)
    out.push_back({{"name", w.name},
                   {"lat", w.lat_deg},
                   {"lon", w.lon_deg},
                   {"ele", marker_elevation(w)},
                   {"ground", number_or_null(w.ground_m)},
                   {"kind", w.symbol},
                   {"priority", w.priority}});
  return out;
}

}  // namespace trailray::app::serve
