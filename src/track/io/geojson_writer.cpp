#include "track/io/geojson_writer.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "track/io/text_output.hpp"

namespace trailray::track {
namespace {

using Line = const std::vector<TrackPoint>*;

void position(std::ostream& out, const TrackPoint& p) {
  out << '[' << format_number(p.lon) << ',' << format_number(p.lat);
  if (p.has_ele()) out << ',' << format_number(p.ele);
  out << ']';
}

void coordinates(std::ostream& out, const std::vector<Line>& lines) {
  const bool multi = lines.size() > 1;
  out << "\"geometry\":{\"type\":\"" << (multi ? "MultiLineString" : "LineString") << "\",\"coordinates\":";
  if (multi) out << '[';
  for (std::size_t l = 0; l < lines.size(); ++l) {
    if (l > 0) out << ",\n";
    out << '[';
    for (std::size_t i = 0; i < lines[l]->size(); ++i) {
      if (i > 0) out << ',';
      position(out, (*lines[l])[i]);
    }
    out << ']';
  }
  if (multi) out << ']';
  out << '}';
}

// A per-point channel, the togeojson key it is written under, and how a value is written.
struct Channel {
  const char* key;
  bool (*has)(const TrackPoint&);
  void (*write)(std::ostream&, const TrackPoint&);
};

const Channel kChannels[] = {
    {"times", [](const TrackPoint& p) { return p.has_time(); },
     [](std::ostream& o, const TrackPoint& p) { o << '"' << format_iso_time(p.time) << '"'; }},
    {"heart", [](const TrackPoint& p) { return !std::isnan(p.heart_rate); },
     [](std::ostream& o, const TrackPoint& p) { o << format_number(p.heart_rate); }},
    {"cads", [](const TrackPoint& p) { return !std::isnan(p.cadence); },
     [](std::ostream& o, const TrackPoint& p) { o << format_number(p.cadence); }},
    {"powers", [](const TrackPoint& p) { return !std::isnan(p.power); },
     [](std::ostream& o, const TrackPoint& p) { o << format_number(p.power); }},
    {"atemps", [](const TrackPoint& p) { return !std::isnan(p.temperature); },
     [](std::ostream& o, const TrackPoint& p) { o << format_number(p.temperature); }},
    {"speeds", [](const TrackPoint& p) { return !std::isnan(p.speed); },
     [](std::ostream& o, const TrackPoint& p) { o << format_number(p.speed); }},
};

// ,"coordinateProperties":{...} when any point has any channel.
void coordinate_properties(std::ostream& out, const std::vector<Line>& lines) {
  bool first = true;
  for (const Channel& c : kChannels) {
    bool any = false;
    for (Line l : lines)
      for (const auto& p : *l) any = any || c.has(p);
    if (!any) continue;
    out << (first ? ",\"coordinateProperties\":{" : ",\n") << '"' << c.key << "\":";
    first = false;
    const bool multi = lines.size() > 1;
    if (multi) out << '[';
    for (std::size_t k = 0; k < lines.size(); ++k) {
      if (k > 0) out << ',';
      out << '[';
      for (std::size_t i = 0; i < lines[k]->size(); ++i) {
        if (i > 0) out << ',';
        const TrackPoint& p = (*lines[k])[i];
        if (c.has(p))
          c.write(out, p);
        else
          out << "null";
      }
      out << ']';
    }
    if (multi) out << ']';
  }
  if (!first) out << '}';
}

void text_property(std::ostream& out, const char* key, const std::string& value) {
  if (!value.empty()) out << ",\"" << key << "\":" << json_string(value);
}

class FeatureWriter {
 public:
  explicit FeatureWriter(std::ostream& out) : out_(out) {}

  void line_feature(const char* gpx_type, const std::string& name, const std::string& desc, const std::string& type,
                    const std::vector<Line>& lines) {
    if (lines.empty()) return;
    begin();
    out_ << "\"properties\":{\"_gpxType\":\"" << gpx_type << '"';
    text_property(out_, "name", name);
    text_property(out_, "desc", desc);
    text_property(out_, "type", type);
    coordinate_properties(out_, lines);
    out_ << "},\n";
    coordinates(out_, lines);
    out_ << '}';
  }

  void point_feature(const Waypoint& w) {
    begin();
    out_ << "\"properties\":{";
    std::string props;
    if (!w.name.empty()) props += ",\"name\":" + json_string(w.name);
    if (!w.description.empty()) props += ",\"desc\":" + json_string(w.description);
    if (!w.symbol.empty()) props += ",\"sym\":" + json_string(w.symbol);
    if (w.point.has_time()) props += ",\"time\":\"" + format_iso_time(w.point.time) + '"';
    out_ << (props.empty() ? props : props.substr(1)) << "},\"geometry\":{\"type\":\"Point\",\"coordinates\":";
    position(out_, w.point);
    out_ << "}}";
  }

 private:
  void begin() {
    out_ << (first_ ? "\n" : ",\n") << "{\"type\":\"Feature\",";
    first_ = false;
  }
  std::ostream& out_;
  bool first_ = true;
};

}  // namespace

void write_geojson(const TrackFile& file, std::ostream& out) {
  out << "{\"type\":\"FeatureCollection\"";
  const Metadata& m = file.metadata;
  if (!m.name.empty()) out << ",\"name\":" << json_string(m.name);
  if (!m.description.empty()) out << ",\"description\":" << json_string(m.description);
  if (!std::isnan(m.time)) out << ",\"time\":\"" << format_iso_time(m.time) << '"';
  out << ",\"features\":[";
  FeatureWriter features(out);
  for (const Track& t : file.tracks) {
    std::vector<Line> lines;
    for (const Segment& s : t.segments)
      if (!s.points.empty()) lines.push_back(&s.points);
    features.line_feature("trk", t.name, t.description, t.type, lines);
  }
  for (const Route& r : file.routes)
    if (!r.points.empty()) features.line_feature("rte", r.name, {}, {}, {&r.points});
  for (const Waypoint& w : file.waypoints) features.point_feature(w);
  out << "\n]}\n";
}

}  // namespace trailray::track
