#include "track/io/kml_writer.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "track/io/text_output.hpp"

namespace trailray::track {
namespace {

struct ArrayField {
  const char* name;
  const char* type;
  const char* display;
  float TrackPoint::*member;
};

const ArrayField kFields[] = {
    {"heartrate", "int", "Heart rate (bpm)", &TrackPoint::heart_rate},
    {"cadence", "int", "Cadence (rpm)", &TrackPoint::cadence},
    {"power", "float", "Power (W)", &TrackPoint::power},
    {"temperature", "float", "Temperature (C)", &TrackPoint::temperature},
    {"speed", "float", "Speed (m/s)", &TrackPoint::speed},
};

bool any_ele(const std::vector<TrackPoint>& points) {
  for (const auto& p : points)
    if (p.has_ele()) return true;
  return false;
}

bool any_time(const std::vector<TrackPoint>& points) {
  for (const auto& p : points)
    if (p.has_time()) return true;
  return false;
}

// "lon lat ele" (gx:coord) or "lon,lat,ele" (coordinates); ele only where known.
std::string coord(const TrackPoint& p, char sep) {
  std::string s = format_number(p.lon) + sep + format_number(p.lat);
  if (p.has_ele()) s += sep + format_number(p.ele);
  return s;
}

void altitude_mode(std::ostream& out, const std::vector<TrackPoint>& points, const char* indent) {
  if (any_ele(points)) out << indent << "<altitudeMode>absolute</altitudeMode>\n";
}

void line_string(std::ostream& out, const std::vector<TrackPoint>& points, const char* indent) {
  out << indent << "<LineString>\n";
  out << indent << "  <tessellate>1</tessellate>\n";
  altitude_mode(out, points, (std::string(indent) + "  ").c_str());
  out << indent << "  <coordinates>";
  for (std::size_t i = 0; i < points.size(); ++i) out << (i > 0 ? " " : "") << coord(points[i], ',');
  out << "</coordinates>\n" << indent << "</LineString>\n";
}

void gx_track(std::ostream& out, const std::vector<TrackPoint>& points, const char* indent) {
  const std::string in = std::string(indent) + "  ";
  out << indent << "<gx:Track>\n";
  altitude_mode(out, points, in.c_str());
  for (const auto& p : points)
    out << in << (p.has_time() ? "<when>" + format_iso_time(p.time) + "</when>" : std::string("<when/>")) << '\n';
  for (const auto& p : points) out << in << "<gx:coord>" << coord(p, ' ') << "</gx:coord>\n";
  bool any_field = false;
  for (const ArrayField& f : kFields) {
    bool present = false;
    for (const auto& p : points) present = present || !std::isnan(p.*f.member);
    if (!present) continue;
    if (!any_field) out << in << "<ExtendedData>\n" << in << "  <SchemaData schemaUrl=\"#trailray_channels\">\n";
    any_field = true;
    out << in << "    <gx:SimpleArrayData name=\"" << f.name << "\">";
    for (const auto& p : points) {
      const float v = p.*f.member;
      out << (std::isnan(v) ? std::string("<gx:value/>") : "<gx:value>" + format_number(v) + "</gx:value>");
    }
    out << "</gx:SimpleArrayData>\n";
  }
  if (any_field) out << in << "  </SchemaData>\n" << in << "</ExtendedData>\n";
  out << indent << "</gx:Track>\n";
}

void segment(std::ostream& out, const std::vector<TrackPoint>& points, const char* indent) {
  if (any_time(points))
    gx_track(out, points, indent);
  else
    line_string(out, points, indent);
}

void texts(std::ostream& out, const std::string& name, const std::string& description) {
  if (!name.empty()) out << "    <name>" << xml_escape(name) << "</name>\n";
  if (!description.empty()) out << "    <description>" << xml_escape(description) << "</description>\n";
}

void track(std::ostream& out, const Track& t) {
  std::vector<const std::vector<TrackPoint>*> segments;
  for (const auto& s : t.segments)
    if (!s.points.empty()) segments.push_back(&s.points);
  if (segments.empty()) return;
  out << "  <Placemark>\n";
  texts(out, t.name, t.description);
  if (segments.size() == 1) {
    segment(out, *segments[0], "    ");
  } else {
    out << "    <gx:MultiTrack>\n      <gx:interpolate>0</gx:interpolate>\n";
    for (const auto* s : segments) segment(out, *s, "      ");
    out << "    </gx:MultiTrack>\n";
  }
  out << "  </Placemark>\n";
}

}  // namespace

void write_kml(const TrackFile& file, std::ostream& out) {
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<kml xmlns=\"http://www.opengis.net/kml/2.2\" xmlns:gx=\"http://www.google.com/kml/ext/2.2\">\n"
         "<Document>\n";
  if (!file.metadata.name.empty()) out << "  <name>" << xml_escape(file.metadata.name) << "</name>\n";
  if (!file.metadata.description.empty())
    out << "  <description>" << xml_escape(file.metadata.description) << "</description>\n";
  out << "  <Schema id=\"trailray_channels\">\n";
  for (const ArrayField& f : kFields)
    out << "    <gx:SimpleArrayField name=\"" << f.name << "\" type=\"" << f.type << "\"><displayName>" << f.display
        << "</displayName></gx:SimpleArrayField>\n";
  out << "  </Schema>\n";
  for (const Track& t : file.tracks) track(out, t);
  for (const Route& r : file.routes) {
    if (r.points.empty()) continue;
    out << "  <Placemark>\n";
    texts(out, r.name, {});
    out << "    <ExtendedData><Data name=\"type\"><value>route</value></Data></ExtendedData>\n";
    line_string(out, r.points, "    ");
    out << "  </Placemark>\n";
  }
  for (const Waypoint& w : file.waypoints) {
    out << "  <Placemark>\n";
    texts(out, w.name, w.description);
    if (w.point.has_time()) out << "    <TimeStamp><when>" << format_iso_time(w.point.time) << "</when></TimeStamp>\n";
    if (!w.symbol.empty())
      out << "    <ExtendedData><Data name=\"sym\"><value>" << xml_escape(w.symbol)
          << "</value></Data></ExtendedData>\n";
    out << "    <Point>\n";
    if (w.point.has_ele()) out << "      <altitudeMode>absolute</altitudeMode>\n";
    out << "      <coordinates>" << coord(w.point, ',') << "</coordinates>\n    </Point>\n  </Placemark>\n";
  }
  out << "</Document>\n</kml>\n";
}

}  // namespace trailray::track
