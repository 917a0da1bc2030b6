#include "app/drawing/photo_drawing.hpp"

#include <fmt/format.h>

#include <cmath>

#include "scene/pins/photo_decode.hpp"
#include "scene/pins/photo_pins.hpp"
#include "track/photos/exif_time.hpp"

namespace trailray::app {

std::vector<const track::Track*> photo_tracks(const scene::TrackSet& tracks) {
  std::vector<const track::Track*> out;
  for (const scene::Track& t : tracks.tracks()) out.push_back(t.is_route ? nullptr : &t.cleaned);
  return out;
}

ScenePhotos add_scene_photos(const PhotoArgs& args, const scene::TrackSet& tracks, scene::WaypointSet& waypoints,
                             const scene::WaypointBuildOptions& placing, scene::Diagnostics& diagnostics) {
  ScenePhotos out;
  if (!args.any()) return out;
  out.placed = read_and_place_photos(args, photo_tracks(tracks), diagnostics);
  out.thumbnails = scene::decode_thumbnails(out.placed, scene::kThumbnailLongSidePx, diagnostics);
  for (scene::Waypoint& w : scene::photo_waypoints(out.placed, out.thumbnails, placing))
    waypoints.points.push_back(std::move(w));
  ++waypoints.revision;
  diagnostics.note(fmt::format("{} photo{} placed on the tracks", out.placed.size(), out.placed.size() == 1 ? "" : "s"));
  return out;
}

std::string photo_caption(const track::PlacedPhoto& photo, std::optional<int> default_offset_s) {
  const std::string name = scene::photo_name(photo.photo.path);
  if (!std::isfinite(photo.time_unix_s)) return name;
  const std::optional<int> zone_s = photo.photo.offset_s ? photo.photo.offset_s : default_offset_s;
  const int offset = zone_s.value_or(0);
  const auto local = static_cast<long long>(std::floor(photo.time_unix_s)) + offset;
  const long long day = ((local % 86400) + 86400) % 86400;
  const std::string zone = zone_s ? track::format_utc_offset(offset) : std::string("UTC");
  return fmt::format("{} \u00b7 {:02d}:{:02d}:{:02d} {}", name, day / 3600, day / 60 % 60, day % 60, zone);
}

}  // namespace trailray::app
