#pragma once
// Where on the tracks each photo was taken. Pure math over the track model (no files):
// 1. by its GPS position, when the nearest point of any track's polyline is within
//    `max_snap_m`: snapped there (the nearest point on a step between two fixes, not only the
//    fixes), the distance along the track, its time and altitude interpolated there;
// 2. else by its time (the camera's clock minus its UTC offset, plus `clock_offset_s`) on the
//    timeline of a track whose time span holds it: the position, distance and altitude
//    interpolated between the fixes before and after (a photo taken at a fix's time lands exactly
//    at that fix's distance); where several tracks hold it, the one passing nearest to its GPS
//    position (if it has one), else the first; in a gap between segments, at the nearer end;
// 3. else not placed, with the reason.
// Distances along a track are compute_metrics' cumulative 2D distances (track/metrics.hpp), the
// figures `stats` reports: the distance of a photo at a fix equals the fix's exactly.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/model.hpp"
#include "track/photos/photo.hpp"

namespace trailray::track {

struct PhotoPlacementOptions {
  double max_snap_m = 100.0;             // a GPS position at most this far from a track is snapped to it
  std::optional<int> default_offset_s;   // the UTC offset of photos that do not say theirs (--photo-tz)
  double clock_offset_s = 0.0;           // added to every photo's time: the camera's clock was this slow
  // Said where a photo's time has no zone: how the user gives one (the command line's option).
  std::string time_zone_hint = "give the photos' time zone";
};

struct UnplacedPhoto {
  std::size_t photo = 0;   // index into the photos given
  Diagnostic reason;       // "<path>: not placed: ..."
};

struct PhotoPlacement {
  std::vector<PlacedPhoto> placed;          // in the order of the photos given
  std::vector<std::size_t> placed_photo;    // parallel to `placed`: the index of each in the photos given
  std::vector<UnplacedPhoto> unplaced;
  std::vector<Diagnostic> warnings;         // placed, but worth saying (by time, its GPS position far away)
};

// The photo's time in UTC: taken_local_s minus its own offset (else `default_offset_s`) plus
// `clock_offset_s`; NaN when it has no time or no offset is known.
double photo_utc_time(const PhotoMetadata& photo, const PhotoPlacementOptions& options);

// `tracks[i]` is track i of PlacedPhoto::track; a null pointer is skipped (keeps the indices).
PhotoPlacement place_photos(const std::vector<PhotoMetadata>& photos, const std::vector<const Track*>& tracks,
                            const PhotoPlacementOptions& options = {});

// The UTC offset a photo's GPS time stamp suggests for its camera clock (the difference of the two
// to the nearest 15 minutes, the date ignored: cameras write GPS dates a day off), when it is within
// two minutes of a whole zone; nullopt without both times.
std::optional<int> offset_suggested_by_gps_time(const PhotoMetadata& photo);

}  // namespace trailray::track
