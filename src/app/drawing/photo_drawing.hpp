#pragma once
// --photos in the commands that draw (`render`, `video`, `view`): the photos read and placed on
// the scene's tracks (app/options/photo_options), their thumbnails decoded (scene/pins/photo_decode) and their
// pins (scene/pins/photo_pins) added to the scene's waypoints, where the labels pass draws them.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/options/photo_options.hpp"
#include "scene/diagnostics.hpp"
#include "scene/pins/photo_image.hpp"
#include "scene/pins/waypoint_building.hpp"
#include "scene/pins/waypoints.hpp"
#include "scene/tracks/track_set.hpp"
#include "track/photos/photo.hpp"

namespace trailray::app {

struct ScenePhotos {
  std::vector<track::PlacedPhoto> placed;  // PlacedPhoto::track indexes the scene's tracks
  std::vector<std::shared_ptr<const scene::PhotoImage>> thumbnails;  // parallel; nullptr: not decoded
};

// The tracks photos are placed on: each of the set's recorded tracks (cleaned, as drawn), a null
// pointer for routes (a planned route says nothing of where a photo was taken), so that
// PlacedPhoto::track is the track's index in the set.
std::vector<const track::Track*> photo_tracks(const scene::TrackSet& tracks);

// Reads and places the photos of `args` on `tracks`, decodes their thumbnails and appends their
// pins to `waypoints` (bumping its revision). Nothing without --photos. Warnings (a photo not
// placed, not decoded) go to `diagnostics`; throws PhotoArgumentError for a path that does not exist.
ScenePhotos add_scene_photos(const PhotoArgs& args, const scene::TrackSet& tracks, scene::WaypointSet& waypoints,
                             const scene::WaypointBuildOptions& placing, scene::Diagnostics& diagnostics);

// "DSCN0010.jpg · 16:28:39 +02:00": the photo's local time, with its own offset, else
// `default_offset_s` (--photo-tz), else in UTC; the name alone without a time.
std::string photo_caption(const track::PlacedPhoto& photo, std::optional<int> default_offset_s = std::nullopt);

}  // namespace trailray::app
