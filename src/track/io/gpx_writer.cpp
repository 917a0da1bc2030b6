#include "track/io/gpx_writer.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <string_view>

#include "track/io/text_output.hpp"

namespace trailray::track {
namespace {

// A waypoint's texts, in the order GPX 1.1 wants them after <time>.
struct PointTexts {
  std::string_view name, description, symbol;
};

void point(std::ostream& out, const char* tag, const TrackPoint& p, const char* indent, PointTexts texts = {}) {
  out << indent << '<' << tag << " lat=\"" << format_number(p.lat) << "\" lon=\"" << format_number(p.lon) << "\">";
  const bool hr = !std::isnan(p.heart_rate), cad = !std::isnan(p.cadence), temp = !std::isnan(p.temperature),
             speed = !std::isnan(p.speed), power = !std::isnan(p.power);
  if (p.has_ele()) out << "<ele>" << format_number(p.ele) << "</ele>";
  if (p.has_time()) out << "<time>" << format_iso_time(p.time) << "</time>";
  if (!texts.name.empty()) out << "<name>" << xml_escape(texts.name) << "</name>";
  if (!texts.description.empty()) out << "<desc>" << xml_escape(texts.description) << "</desc>";
  if (!texts.symbol.empty()) out << "<sym>" << xml_escape(texts.symbol) << "</sym>";
  if (hr || cad || temp || speed || power) {
    out << "<extensions>";
    if (power) out << "<power>" << format_number(p.power) << "</power>";
    if (hr || cad || temp || speed) {
      out << "<gpxtpx:TrackPointExtension>";
      if (temp) out << "<gpxtpx:atemp>" << format_number(p.temperature) << "</gpxtpx:atemp>";
      if (hr) out << "<gpxtpx:hr>" << std::lround(p.heart_rate) << "</gpxtpx:hr>";
      if (cad) out << "<gpxtpx:cad>" << std::lround(p.cadence) << "</gpxtpx:cad>";
      if (speed) out << "<gpxtpx:speed>" << format_number(p.speed) << "</gpxtpx:speed>";
      out << "</gpxtpx:TrackPointExtension>";
    }
    out << "</extensions>";
  }
  out << "</" << tag << ">\n";
}

}  // namespace

void write_gpx(const TrackFile& file, std::ostream& out) {
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<gpx version=\"1.1\" creator=\"trailray\" xmlns=\"http://www.topografix.com/GPX/1/1\"\n"
         "     xmlns:gpxtpx=\"http://www.garmin.com/xmlschemas/TrackPointExtension/v2\">\n";
  const Metadata& m = file.metadata;
  if (!m.name.empty() || !m.description.empty() || !std::isnan(m.time)) {
    out << "  <metadata>";
    if (!m.name.empty()) out << "<name>" << xml_escape(m.name) << "</name>";
    if (!m.description.empty()) out << "<desc>" << xml_escape(m.description) << "</desc>";
    if (!std::isnan(m.time)) out << "<time>" << format_iso_time(m.time) << "</time>";
    out << "</metadata>\n";
  }
  for (const auto& w : file.waypoints) point(out, "wpt", w.point, "  ", {w.name, w.description, w.symbol});
  for (const auto& r : file.routes) {
    out << "  <rte>";
    if (!r.name.empty()) out << "<name>" << xml_escape(r.name) << "</name>";
    out << '\n';
    for (const auto& p : r.points) point(out, "rtept", p, "    ");
    out << "  </rte>\n";
  }
  for (const auto& t : file.tracks) {
    out << "  <trk>";
    if (!t.name.empty()) out << "<name>" << xml_escape(t.name) << "</name>";
    if (!t.description.empty()) out << "<desc>" << xml_escape(t.description) << "</desc>";
    if (!t.type.empty()) out << "<type>" << xml_escape(t.type) << "</type>";
    out << '\n';
    for (const auto& s : t.segments) {
      out << "    <trkseg>\n";
      for (const auto& p : s.points) point(out, "trkpt", p, "      ");
      out << "    </trkseg>\n";
    }
    out << "  </trk>\n";
  }
  out << "</gpx>\n";
}

}  // namespace trailray::track
