#pragma once
// A film's cameras, one per frame, all known before the first frame (`trailray video`): `follow`
// (behind and above the followed track's position, looking ahead along the way it goes) and
// `orbit` (circling a point while the replay runs). Both are smoothed so the picture never jerks
// (centred moving averages over the whole path, which is known in advance) and kept out of the
// terrain: where the camera would stand under the ground or a ridge would hide the point it looks
// at, it looks down more steeply from higher up, raised early and lowered late (the steepness is
// the largest over a window, then averaged), never below `clearance_m` over the terrain.

#include <functional>
#include <span>
#include <vector>

#include "geo/web_mercator.hpp"
#include "scene/camera/camera.hpp"

namespace trailray::scene {

// Terrain heights under points, in one batch (NaN: unknown there, taken as no obstacle).
using HeightBatch = std::function<std::vector<double>(std::span<const geo::LatLon>)>;

struct FilmCameraSettings {
  double distance_m = 800.0;  // from the camera to the point it looks at
  double pitch_deg = -25.0;   // as seen at that point, before raising (negative looks down)
  double clearance_m = 25.0;  // the camera stays at least this high over the terrain
  // Half-widths of the centred moving averages: of the followed point and of its direction of
  // travel in replay seconds (so they do not depend on the frame rate), of the raise in frames.
  double position_window_s = 5.0;
  double heading_window_s = 60.0;
  int raise_window = 30;
};

// One look per frame: where the camera looks (ECEF), from which heading and pitch, how far.
struct FilmLook {
  glm::dvec3 target{0.0};
  double heading_deg = 0.0, pitch_deg = 0.0, distance_m = 0.0;
};

// Where the followed track is at a replay time (ECEF).
using PositionAt = std::function<glm::dvec3(double time_unix_s)>;

// `follow`: a look per frame time (`times`): at the followed position averaged over the position
// window, along the direction of travel (where the track will be minus where it was) averaged
// over the heading window (kept while it stands still), raised over `heights` (empty function:
// no terrain).
std::vector<FilmLook> follow_looks(std::span<const double> times, const PositionAt& position,
                                   const FilmCameraSettings& settings, const HeightBatch& heights);

// `orbit`: `frames` looks at `centre` turning once around it clockwise from `start_heading_deg`.
std::vector<FilmLook> orbit_looks(const glm::dvec3& centre, std::size_t frames, double start_heading_deg,
                                  const FilmCameraSettings& settings, const HeightBatch& heights);

// Where a look puts the camera (ECEF).
glm::dvec3 camera_position(const FilmLook& look);

// The camera of a look, its depth range from the terrain height below it (`ground_m`, NaN: the
// camera's height minus the clearance). Throws std::invalid_argument for a look with no camera.
Camera camera_of(const FilmLook& look, const Lens& lens, double ground_m);

}  // namespace trailray::scene
