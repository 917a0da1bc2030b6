#include "web/page_pins.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <span>
#include <stdexcept>

#include "scene/pins/photo_pins.hpp"
#include "scene/pins/waypoint_building.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "track/io/readers.hpp"

namespace trailray::web {
namespace {

double number_or_nan(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : std::nan("");
}

std::string text_or_empty(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// A pin placed as build_waypoints places one (scene::place_on_ground).
bool place_pin(const nlohmann::json& j, scene::WaypointKind kind, double neutral_ground_m, scene::Waypoint& w) {
  if (!j.is_object()) return false;
  w.lat_deg = number_or_nan(j, "lat");
  w.lon_deg = number_or_nan(j, "lon");
  if (!track::valid_coordinates(w.lat_deg, w.lon_deg)) return false;
  w.kind = kind;
  w.name = text_or_empty(j, "name");
  w.ele_m = number_or_nan(j, "ele");
  w.ground_m = number_or_nan(j, "ground");
  w.time_unix_s = number_or_nan(j, "time");
  scene::place_on_ground(w, neutral_ground_m);
  return true;
}

const nlohmann::json& list_of(const nlohmann::json& doc, const char* key) {
  static const nlohmann::json empty = nlohmann::json::array();
  const auto it = doc.find(key);
  if (it == doc.end() || it->is_null()) return empty;
  if (!it->is_array()) throw std::runtime_error(std::string("served pins: \"") + key + "\" is not a list");
  return *it;
}

}  // namespace

ServedPins served_pins(std::string_view json, double neutral_ground_m) {
  const nlohmann::json doc = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
  if (!doc.is_object()) throw std::runtime_error("served pins: not a JSON object");
  ServedPins out;
  for (const nlohmann::json& p : list_of(doc, "places")) {
    scene::Waypoint w;
    if (!place_pin(p, scene::WaypointKind::Place, neutral_ground_m, w)) continue;
    w.symbol = text_or_empty(p, "kind");
    w.source = "--places";
    const auto priority = p.find("priority");
    w.priority = priority != p.end() && priority->is_number_integer() ? priority->get<int>() : 0;
    out.points.push_back(std::move(w));
  }
  out.first_photo = out.points.size();
  for (const nlohmann::json& p : list_of(doc, "photos")) {
    scene::Waypoint w;
    // A photo left out would shift the others' indices: one without a place stays, hidden.
    if (!place_pin(p, scene::WaypointKind::Photo, neutral_ground_m, w)) w.visible = false;
    w.kind = scene::WaypointKind::Photo;
    w.source = text_or_empty(p, "thumbnail");
    w.priority = scene::kPhotoPriority;
    out.points.push_back(std::move(w));
    out.large_urls.push_back(text_or_empty(p, "large"));
  }
  return out;
}

std::shared_ptr<const scene::PhotoImage> decode_photo_bytes(std::string_view bytes) {
  const terrain::DecodedImage image =
      terrain::decode_image(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
  scene::RgbaImage pixels;
  pixels.width = image.width;
  pixels.height = image.height;
  pixels.rgba = terrain::to_rgba8(image);
  return scene::make_photo_image(std::move(pixels));
}

}  // namespace trailray::web
