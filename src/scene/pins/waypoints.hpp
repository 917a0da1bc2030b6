#pragma once
// Named points of a scene, drawn as pins (a thin stem from the ground up to a marker) with their
// name as a label: the waypoints the files carry (GPX wpt, KML Point placemarks, FIT course
// points) and place labels added by the user (--labels FILE: peaks, huts). Built once from the
// files (ECEF positions and the ground below them); the renderer draws them and the labels pass
// lays their names out; nothing here touches GL.

#include <glm/glm.hpp>

#include "scene/pins/photo_image.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace trailray::scene {

enum class WaypointKind {
  Waypoint,  // carried by a track file: a pin and a label
  Place,     // a place label from a points file (--labels): a label, and a smaller pin
  Thermal,   // a thermal of a flight (--thermals, scene/pins/thermal_markers.hpp): a pin at its top
  Photo,     // a photo placed on a track (--photos, scene/pins/photo_pins.hpp): a pin topped by its thumbnail
};

inline constexpr double kEnlargedPhotoScale = 4.0;

struct Waypoint {
  std::string name;
  std::string description;
  std::string symbol;  // as the file names it (GPX sym, FIT course point type), may be empty
  std::string source;  // the file it came from
  WaypointKind kind = WaypointKind::Waypoint;

  double lat_deg = 0.0, lon_deg = 0.0;
  double ele_m = std::numeric_limits<double>::quiet_NaN();        // as recorded (NaN: none)
  double ground_m = std::numeric_limits<double>::quiet_NaN();     // terrain below (NaN: unknown)
  double time_unix_s = std::numeric_limits<double>::quiet_NaN();  // as recorded (NaN: none)

  // Where it is drawn: the marker (at its elevation, else on the ground or the neutral ground)
  // and the stem's foot on the ground below it.
  glm::dvec3 marker_ecef{0.0};
  glm::dvec3 ground_ecef{0.0};

  // A photo's pin: its thumbnail, drawn above the pin in place of the name (nullptr: a photo that
  // could not be decoded, or not a photo; its name is the label). `source` is the photo's path.
  std::shared_ptr<const PhotoImage> thumbnail;
  // The photo the viewer shows larger (clicked in its list or on its pin): drawn
  // kEnlargedPhotoScale times the style's size, before every other photo.
  bool enlarged = false;

  // Which label wins where two would overlap: higher first (then the nearer one).
  int priority = 0;
  bool visible = true;
};

// The waypoints of a scene; `revision` changes whenever what is drawn of them changes, so the
// renderer can keep their GPU buffer until then.
struct WaypointSet {
  std::vector<Waypoint> points;
  std::uint64_t revision = 0;
};

}  // namespace trailray::scene
