#pragma once
// Photos placed on tracks (track/photos/photo.hpp) as pins of the scene (WaypointKind::Photo):
// each stands on the track where the photo was taken, topped by the photo's thumbnail, which the
// labels pass draws in place of a name (so photos and labels are de-cluttered together, and the
// terrain ghosts or hides a thumbnail as it does a label). GL-free, in the browser's build too;
// the thumbnails themselves are decoded by scene/pins/photo_decode.hpp (not in the browser's build).

#include <memory>
#include <string>
#include <vector>

#include "scene/pins/photo_image.hpp"
#include "scene/pins/waypoint_building.hpp"
#include "scene/pins/waypoints.hpp"
#include "track/photos/photo.hpp"

namespace trailray::scene {

// Photos' pins win over waypoints' names: they are what the user brought to see.
inline constexpr int kPhotoPriority = 3;

// The long side of the thumbnails decoded for pins (the pass draws them PinStyle::photo_px tall
// or wide, times the pixel ratio, so a high-DPI picture still has the texels it needs).
inline constexpr int kThumbnailLongSidePx = 128;

// The photo's file name without its folders: its pin's name in lists and tooltips.
std::string photo_name(const std::string& path);

// One pin per placed photo, in order: on the track where it was placed (its altitude there, never
// below the ground), the stem from the ground below; `thumbnails[i]` (when there are as many,
// each possibly nullptr) on photo i's pin. The name is the file's name, `source` its path,
// `time_unix_s` when it was taken (UTC).
std::vector<Waypoint> photo_waypoints(const std::vector<track::PlacedPhoto>& photos,
                                      const std::vector<std::shared_ptr<const PhotoImage>>& thumbnails,
                                      const WaypointBuildOptions& options);

}  // namespace trailray::scene
