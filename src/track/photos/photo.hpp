#pragma once
// A photo as trailray sees it: what its EXIF block says (position, the camera's clock, its
// orientation), and where it was placed on a track (by its GPS position, snapped to the track,
// or by its time on the track's timeline). Plain data: the EXIF reading (exiv2) and the
// placement live beside this header; the scene and the reports take these structs.

#include <cstddef>
#include <limits>
#include <optional>
#include <string>

namespace trailray::track {

// What a photo's EXIF block says; NaN or empty where it says nothing.
struct PhotoMetadata {
  std::string path;
  // GPSLatitude/GPSLongitude with their refs; GPSAltitude with GPSAltitudeRef (1: below sea level).
  double lat_deg = std::numeric_limits<double>::quiet_NaN();
  double lon_deg = std::numeric_limits<double>::quiet_NaN();
  double alt_m = std::numeric_limits<double>::quiet_NaN();
  bool has_position() const { return lat_deg == lat_deg && lon_deg == lon_deg; }
  // DateTimeOriginal (with SubSecTimeOriginal) as seconds since 1970 read as if it were UTC: the
  // camera's wall clock, whose zone is `offset_s` when the photo says it (OffsetTimeOriginal, or a
  // zone written inside the field), else unknown.
  double taken_local_s = std::numeric_limits<double>::quiet_NaN();
  std::optional<int> offset_s;
  // GPSDateStamp + GPSTimeStamp, UTC (some cameras write it a day off: a hint, never trusted alone).
  double gps_time_utc_s = std::numeric_limits<double>::quiet_NaN();
  int orientation = 1;           // EXIF Orientation, 1..8 (1: as stored)
  int width = 0, height = 0;     // pixels as stored (before Orientation), when the file says
  bool has_exif = false;         // the file has an EXIF block at all (a photo without one cannot be placed)
};

enum class PhotoPlacedBy { gps, time };

// A photo placed on one of the tracks it was matched against.
struct PlacedPhoto {
  PhotoMetadata photo;
  PhotoPlacedBy placed_by = PhotoPlacedBy::gps;
  std::size_t track = 0;   // index of the track among those it was placed against
  double distance_m = 0;   // metres along that track where it was taken
  // Where it is drawn: on the track (by time, or snapped within reach of its GPS position).
  double lat_deg = 0, lon_deg = 0;
  double ele_m = std::numeric_limits<double>::quiet_NaN();        // the track's altitude there (NaN: none)
  double time_unix_s = std::numeric_limits<double>::quiet_NaN();  // UTC when known
  // How far its own GPS position is from where it was placed (NaN: it has none).
  double gps_offset_m = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace trailray::track
