// From a finished GeoJSON Feature to the track model (the reader's conventions are in
// geojson_reader.cpp's header comment).
#include <cfloat>
#include <cmath>

#include "track/io/geojson_parts.hpp"
#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"

namespace trailray::track {
namespace {

const char* channel_key(GeoChannel c) {
  switch (c) {
    case GeoChannel::Time:
      return "times";
    case GeoChannel::Heart:
      return "heart";
    case GeoChannel::Cadence:
      return "cadence";
    case GeoChannel::Power:
      return "power";
    case GeoChannel::Temperature:
      return "temperature";
    case GeoChannel::Speed:
      return "speed";
    case GeoChannel::Count:
      break;
  }
  return "?";
}

void set_channel(TrackPoint& p, GeoChannel c, double v) {
  if (std::isnan(v)) return;
  if (c == GeoChannel::Time) {
    p.time = v;
    return;
  }
  if (!(std::fabs(v) <= static_cast<double>(FLT_MAX))) return;  // a float cast would be undefined
  const auto f = static_cast<float>(v);
  switch (c) {
    case GeoChannel::Heart:
      p.heart_rate = f;
      break;
    case GeoChannel::Cadence:
      p.cadence = f;
      break;
    case GeoChannel::Power:
      p.power = f;
      break;
    case GeoChannel::Temperature:
      p.temperature = f;
      break;
    case GeoChannel::Speed:
      p.speed = f;
      break;
    default:
      break;
  }
}

// One line of a track: its points (still with the unusable ones, NaN latitude) in file order.
struct Line {
  std::vector<TrackPoint> points;
};

// The lines of a geometry that is a LineString or MultiLineString (members of a
// GeometryCollection included); points of Point/MultiPoint members go to `singles`.
class Collector {
 public:
  Collector(WarningCollector& warnings) : warnings_(warnings) {}

  void add(GeoObject& g, std::vector<Line>& lines, std::vector<TrackPoint>& singles) {
    const std::string& t = g.type;
    if (t == "GeometryCollection") {
      for (const auto& member : g.geometries)
        if (member) add(*member, lines, singles);
      return;
    }
    const int want = t == "Point" ? 1 : (t == "LineString" || t == "MultiPoint") ? 2 : t == "MultiLineString" ? 3 : 0;
    if (want == 0) {
      skipped(g);
      return;
    }
    if (g.points.empty()) return;  // "coordinates": [] and the like: nothing to draw
    if (g.mixed_levels || g.position_level != want) {
      warnings_.add("geojson-shape", g.where,
                    where(g) + "a " + t + " whose coordinates are not nested as its type requires; skipped");
      return;
    }
    if (t == "Point" || t == "MultiPoint") {
      singles.insert(singles.end(), g.points.begin(), g.points.end());
      return;
    }
    if (g.part_ends.size() == 1 && g.part_ends[0] == g.points.size() && g.part_levels[0] == want - 1) {
      lines.push_back({std::move(g.points)});  // one line, the common case: no copy of a big track
      return;
    }
    std::size_t begin = 0;
    for (std::size_t i = 0; i < g.part_ends.size(); ++i) {
      if (g.part_levels[i] != want - 1) continue;
      Line line;
      line.points.assign(g.points.begin() + static_cast<std::ptrdiff_t>(begin),
                         g.points.begin() + static_cast<std::ptrdiff_t>(g.part_ends[i]));
      begin = g.part_ends[i];
      lines.push_back(std::move(line));
    }
  }

  void skipped(const GeoObject& g) {
    const std::string type = g.type.empty() ? std::string("untyped") : g.type.substr(0, 40);
    warnings_.add(
        "geojson-skip-" + type, g.where,
        where(g) + "a " + type + " geometry skipped (lines and points are read; polygons and other types are not)");
  }

  static std::string where(const GeoObject& g) { return g.path.empty() ? std::string() : g.path + ": "; }

 private:
  WarningCollector& warnings_;
};

// Per-point values of channel `c` onto the lines. A series whose arrays do not match the lines'
// lengths is ignored with a warning (togeojson leaves out the times of points without one, so
// its times cannot be placed then); after a cut, the last line may be shorter than its values.
void apply_series(const GeoSeries& s, GeoChannel c, std::vector<Line>& lines, bool cut, WarningCollector& warnings) {
  if (!s.present || lines.empty()) return;
  std::size_t total = 0;
  for (const auto& l : lines) total += l.points.size();
  auto mismatch = [&](const std::string& detail) {
    warnings.add(std::string("geojson-series-") + channel_key(c), s.where,
                 s.path + ": " + detail + "; these " + channel_key(c) + " are ignored");
  };
  // A flat array for several lines: accepted when it covers all their points in order.
  if (!s.nested && lines.size() > 1) {
    if (s.values.size() != total && !(cut && s.values.size() > total)) {
      mismatch(std::to_string(s.values.size()) + " values for " + std::to_string(total) + " points");
      return;
    }
    std::size_t k = 0;
    for (auto& l : lines)
      for (auto& p : l.points) set_channel(p, c, s.values[k++]);
    return;
  }
  if (s.parts() != lines.size() && !(cut && s.parts() > lines.size())) {
    mismatch(std::to_string(s.parts()) + " arrays for " + std::to_string(lines.size()) + " lines");
    return;
  }
  for (std::size_t j = 0; j < lines.size(); ++j) {
    const std::size_t n = s.part_end(j) - s.part_begin(j);
    const bool last = j + 1 == lines.size();
    if (n != lines[j].points.size() && !(cut && last && n > lines[j].points.size())) {
      mismatch(std::to_string(n) + " values for the " + std::to_string(lines[j].points.size()) + " points of line " +
               std::to_string(j + 1));
      return;
    }
  }
  for (std::size_t j = 0; j < lines.size(); ++j) {
    const std::size_t b = s.part_begin(j);
    for (std::size_t i = 0; i < lines[j].points.size(); ++i) set_channel(lines[j].points[i], c, s.values[b + i]);
  }
}

std::vector<TrackPoint> usable(std::vector<TrackPoint>&& points) {
  std::erase_if(points, [](const TrackPoint& p) { return std::isnan(p.lat); });  // warned when read
  return std::move(points);
}

std::string trimmed(const std::string& s) { return std::string(trim(s)); }

}  // namespace

bool is_geojson_geometry_type(const std::string& t) {
  return t == "Point" || t == "MultiPoint" || t == "LineString" || t == "MultiLineString" || t == "Polygon" ||
         t == "MultiPolygon" || t == "GeometryCollection";
}

void add_geojson_feature(GeoObject& feature, bool cut, TrackFile& file, WarningCollector& warnings) {
  GeoObject* geometry = feature.geometry ? feature.geometry.get() : nullptr;
  if (!geometry && is_geojson_geometry_type(feature.type)) geometry = &feature;  // a bare geometry
  if (!geometry) {
    if (!cut)
      warnings.add("geojson-no-geometry", feature.where,
                   Collector::where(feature) + "a feature without a geometry skipped");
    return;
  }
  static const GeoProperties kNone;
  const GeoProperties& props = feature.properties ? *feature.properties : kNone;

  Collector collector(warnings);
  std::vector<Line> lines;
  std::vector<TrackPoint> singles;
  collector.add(*geometry, lines, singles);

  for (int c = 0; c < static_cast<int>(GeoChannel::Count); ++c)
    apply_series(props.series[c], static_cast<GeoChannel>(c), lines, cut, warnings);

  const std::string name = trimmed(props.name), description = trimmed(props.description);
  if (!lines.empty()) {
    if (props.gpx_type == "rte") {
      for (auto& l : lines) {
        Route r;
        r.name = name;
        r.points = usable(std::move(l.points));
        if (!r.points.empty()) file.routes.push_back(std::move(r));
      }
    } else {
      Track t;
      t.name = name;
      t.description = description;
      t.type = trimmed(props.type);
      for (auto& l : lines) {
        Segment s;
        s.points = usable(std::move(l.points));
        if (!s.points.empty()) t.segments.push_back(std::move(s));
      }
      if (!t.segments.empty()) file.tracks.push_back(std::move(t));
    }
  }
  const auto time = parse_iso8601(trim(props.time));
  for (TrackPoint& p : singles) {
    if (std::isnan(p.lat)) continue;
    Waypoint w;
    w.point = p;
    if (time) w.point.time = *time;
    w.name = name;
    w.description = description;
    w.symbol = trimmed(props.symbol);
    file.waypoints.push_back(std::move(w));
  }
}

}  // namespace trailray::track
