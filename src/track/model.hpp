#pragma once
// The track model: file -> tracks -> segments -> points, plus routes, waypoints and
// metadata. File order and segment boundaries are kept as read: a segment boundary is a
// gap, and nothing downstream measures, smooths or draws across it.
//
// Optional values are NaN when absent (see has_*()); this keeps a point at 64 bytes, which
// matters for million-point tracks. Code that derives numbers must check has_*() first.

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace trailray::track {

inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();
inline constexpr float kMissingF = std::numeric_limits<float>::quiet_NaN();

struct TrackPoint {
  double lat = 0.0;        // degrees, WGS84
  double lon = 0.0;        // degrees, WGS84
  double ele = kMissing;   // metres
  double time = kMissing;  // seconds since 1970-01-01T00:00:00Z (UTC), sub-second allowed
  // Recorded channels from extensions (NaN when the device did not record them).
  float heart_rate = kMissingF;   // beats per minute
  float cadence = kMissingF;      // revolutions (or steps) per minute
  float temperature = kMissingF;  // degrees Celsius
  float power = kMissingF;        // watts
  float speed = kMissingF;        // metres per second, as recorded by the device
  // IGC pressure altitude in metres against the ISA standard atmosphere (1013.25 hPa), kept
  // whichever altitude `ele` holds (ReadOptions::igc_altitude): a flight has two altitudes and
  // the viewer shows both. Cleaning smooths it like `ele`. It fills what was padding.
  float pressure_altitude = kMissingF;
  // IGC GNSS altitude in metres, kept likewise whichever altitude `ele` holds, so that with
  // `--igc-altitude pressure` the flight still has both. It grows the point from 56 to 64 bytes
  // (8 more per point; a 10-hour 1 Hz flight: 288 kB): a float beside a float, no padding left.
  float gnss_altitude = kMissingF;

  bool has_ele() const { return !std::isnan(ele); }
  bool has_time() const { return !std::isnan(time); }
  bool has_pressure_altitude() const { return !std::isnan(pressure_altitude); }
  bool has_gnss_altitude() const { return !std::isnan(gnss_altitude); }
};

static_assert(sizeof(TrackPoint) == 64, "a track point is 64 bytes: million-point tracks are common");

struct Segment {
  std::vector<TrackPoint> points;
};

struct Track {
  std::string name;
  std::string description;
  std::string type;  // activity type as written by the device (e.g. "running", "9")
  std::vector<Segment> segments;

  std::size_t point_count() const {
    std::size_t n = 0;
    for (const auto& s : segments) n += s.points.size();
    return n;
  }
};

struct Route {
  std::string name;
  std::vector<TrackPoint> points;
};

struct Waypoint {
  TrackPoint point;
  std::string name;
  std::string description;
  std::string symbol;
};

struct Metadata {
  std::string name;
  std::string description;
  std::string creator;
  std::string activity_type;
  double time = kMissing;  // seconds since epoch, UTC
  // Format-specific header fields in file order, e.g. IGC pilot, glider type, site.
  std::vector<std::pair<std::string, std::string>> fields;
};

enum class Format { Gpx, Igc, Tcx, Fit, Kml, Kmz, GeoJson };

inline const char* format_name(Format f) {
  switch (f) {
    case Format::Gpx:
      return "gpx";
    case Format::Igc:
      return "igc";
    case Format::Tcx:
      return "tcx";
    case Format::Fit:
      return "fit";
    case Format::Kml:
      return "kml";
    case Format::Kmz:
      return "kmz";
    case Format::GeoJson:
      return "geojson";
  }
  return "unknown";
}

struct TrackFile {
  Format format = Format::Gpx;
  Metadata metadata;
  std::vector<Track> tracks;
  std::vector<Route> routes;
  std::vector<Waypoint> waypoints;
};

}  // namespace trailray::track
