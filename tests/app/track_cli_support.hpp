#pragma once
// What the app-level track tests share: synthetic GPX files (straight lines of points a given
// number of metres apart, with or without times and elevations, in one or more segments and
// tracks), the `trailray render` command line with a private config and cache, the rendered PNG
// read back as RGBA, and the camera the command frames the tracks with (so a test can tell
// where a point lands in the picture).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <ctime>
#include <fstream>
#include <limits>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "run_command.hpp"
#include "scene/camera/camera.hpp"
#include "scene/camera/framing.hpp"
#include "terrain/codecs/image_codec.hpp"
#include "terrain/tile_fixtures.hpp"
#include "test_support.hpp"

namespace trailray::test {

inline constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

struct GpxPoint {
  double lat = 0.0, lon = 0.0;
  double ele = kNoValue;   // NaN: no <ele>
  double time = kNoValue;  // unix seconds; NaN: no <time>
  double heart_rate = kNoValue;  // beats per minute in Garmin's TrackPointExtension; NaN: none
};

struct GpxTrack {
  std::string name;  // empty: no <name>
  std::vector<std::vector<GpxPoint>> segments;
};

// A point `east_m` metres east and `north_m` north of (lat, lon): a local flat approximation,
// good to well under a metre over the few kilometres the tests use.
inline GpxPoint offset_point(double lat, double lon, double east_m, double north_m) {
  constexpr double kMetresPerDegree = 6378137.0 * 3.14159265358979323846 / 180.0;
  return {lat + north_m / kMetresPerDegree,
          lon + east_m / (kMetresPerDegree * std::cos(lat * 3.14159265358979323846 / 180.0))};
}

inline std::string iso8601(double unix_s) {
  const std::time_t t = static_cast<std::time_t>(std::floor(unix_s));
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

inline std::string gpx_text(const std::vector<GpxTrack>& tracks) {
  std::ostringstream out;
  out.precision(10);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<gpx version=\"1.1\" creator=\"trailray tests\" xmlns=\"http://www.topografix.com/GPX/1/1\" "
         "xmlns:h=\"http://www.garmin.com/xmlschemas/TrackPointExtension/v1\">\n";
  for (const GpxTrack& t : tracks) {
    out << " <trk>\n";
    if (!t.name.empty()) out << "  <name>" << t.name << "</name>\n";
    for (const auto& segment : t.segments) {
      if (segment.empty()) {
        out << "  <trkseg/>\n";
        continue;
      }
      out << "  <trkseg>\n";
      for (const GpxPoint& p : segment) {
        out << "   <trkpt lat=\"" << p.lat << "\" lon=\"" << p.lon << "\">";
        if (!std::isnan(p.ele)) out << "<ele>" << p.ele << "</ele>";
        if (!std::isnan(p.time)) out << "<time>" << iso8601(p.time) << "</time>";
        if (!std::isnan(p.heart_rate))
          out << "<extensions><h:TrackPointExtension><h:hr>" << p.heart_rate
              << "</h:hr></h:TrackPointExtension></extensions>";
        out << "</trkpt>\n";
      }
      out << "  </trkseg>\n";
    }
    out << " </trk>\n";
  }
  out << "</gpx>\n";
  return out.str();
}

// Points along a line heading east from `start_east_m` metres east of (lat, lon), `count`
// points `spacing_m` apart and `interval_s` apart in time from `t0` (NaN: no times), at `ele`.
inline std::vector<GpxPoint> east_line(double lat, double lon, double start_east_m, int count, double spacing_m,
                                       double t0, double interval_s, double ele, double north_m = 0.0) {
  std::vector<GpxPoint> points;
  for (int i = 0; i < count; ++i) {
    GpxPoint p = offset_point(lat, lon, start_east_m + i * spacing_m, north_m);
    p.ele = ele;
    p.time = std::isnan(t0) ? kNoValue : t0 + i * interval_s;
    points.push_back(p);
  }
  return points;
}

// The command line of `trailray render` with its own (empty) config and cache and no imagery.
struct RenderEnv {
  TempDir home;
  std::string prefix() const {
    return "XDG_CONFIG_HOME=" + shell_quote((home.path() / "config").string()) +
           " XDG_CACHE_HOME=" + shell_quote((home.path() / "cache").string()) +
           " TRAILRAY_CONFIG= " + shell_quote(TRAILRAY_BINARY) + " render --imagery none ";
  }
  std::string file(const std::string& name) const { return (home.path() / name).string(); }
  // Writes a GPX file in the temporary folder and returns its path.
  std::string write_gpx(const std::string& name, const std::vector<GpxTrack>& tracks) const {
    const std::string path = file(name);
    std::ofstream(path, std::ios::binary) << gpx_text(tracks);
    return path;
  }
};

// A PNG read back as 8-bit RGBA, top row first.
struct Picture {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;

  struct Rgb {
    int r = 0, g = 0, b = 0;
  };
  Rgb at(std::uint32_t x, std::uint32_t y) const {
    const std::size_t i = (std::size_t{y} * width + x) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2]};
  }
  bool inside(double x, double y) const { return x >= 0.0 && y >= 0.0 && x < width && y < height; }
};

inline Picture read_picture(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  const std::string bytes = s.str();
  if (bytes.empty()) throw std::runtime_error("no picture at " + path);
  const auto image =
      terrain::decode_image(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
  return {image.width, image.height, terrain::to_rgba8(image)};
}

// The framing `trailray render` gives these points when no camera is given and no legend is
// drawn (same lens, the framing's defaults, the points' lowest height as the ground); with
// `keep_clear`, the framing around a legend there.
inline scene::Framing framing(const std::vector<GpxPoint>& points, std::uint32_t width, std::uint32_t height,
                               const scene::KeptClearCorner& keep_clear = {}) {
  std::vector<scene::GeoPosition> positions;
  for (const GpxPoint& p : points) positions.push_back({p.lat, p.lon, p.ele});
  scene::FramingOptions options;
  options.lens = {scene::kDefaultVerticalFovDeg, width, height};
  options.keep_clear = keep_clear;
  auto framed = scene::frame_points(positions, options);
  if (!framed.ok()) throw std::runtime_error("cannot frame: " + framed.error);
  return *framed.value;
}

// Its camera.
inline scene::Camera framing_camera(const std::vector<GpxPoint>& points, std::uint32_t width, std::uint32_t height) {
  return framing(points, width, height).camera;
}

}  // namespace trailray::test
