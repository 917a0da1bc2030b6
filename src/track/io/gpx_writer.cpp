#include "track/io/gpx_writer.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <string_view>

namespace trailray::track {
namespace {

std::string escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// Shortest text that reads back as the same double ("%.17g" would print 46.700000000000003).
std::string number(double v) {
  char buf[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

// ISO 8601 UTC, milliseconds only when the time has a fraction.
std::string iso_time(double t) {
  const double whole = std::floor(t);
  const auto seconds = static_cast<std::time_t>(whole);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char buf[40];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  std::string out = buf;
  const long millis = std::lround((t - whole) * 1000.0);
  if (millis > 0 && millis < 1000) {
    std::snprintf(buf, sizeof buf, ".%03ld", millis);
    out += buf;
  }
  return out + "Z";
}

void point(std::ostream& out, const char* tag, const TrackPoint& p, const char* indent, std::string_view name = {}) {
  out << indent << '<' << tag << " lat=\"" << number(p.lat) << "\" lon=\"" << number(p.lon) << "\">";
  const bool hr = !std::isnan(p.heart_rate), cad = !std::isnan(p.cadence), temp = !std::isnan(p.temperature),
             speed = !std::isnan(p.speed), power = !std::isnan(p.power);
  if (p.has_ele()) out << "<ele>" << number(p.ele) << "</ele>";
  if (p.has_time()) out << "<time>" << iso_time(p.time) << "</time>";
  if (!name.empty()) out << "<name>" << escape(name) << "</name>";
  if (hr || cad || temp || speed || power) {
    out << "<extensions>";
    if (power) out << "<power>" << number(p.power) << "</power>";
    if (hr || cad || temp || speed) {
      out << "<gpxtpx:TrackPointExtension>";
      if (temp) out << "<gpxtpx:atemp>" << number(p.temperature) << "</gpxtpx:atemp>";
      if (hr) out << "<gpxtpx:hr>" << std::lround(p.heart_rate) << "</gpxtpx:hr>";
      if (cad) out << "<gpxtpx:cad>" << std::lround(p.cadence) << "</gpxtpx:cad>";
      if (speed) out << "<gpxtpx:speed>" << number(p.speed) << "</gpxtpx:speed>";
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
    if (!m.name.empty()) out << "<name>" << escape(m.name) << "</name>";
    if (!m.description.empty()) out << "<desc>" << escape(m.description) << "</desc>";
    if (!std::isnan(m.time)) out << "<time>" << iso_time(m.time) << "</time>";
    out << "</metadata>\n";
  }
  for (const auto& w : file.waypoints) point(out, "wpt", w.point, "  ", w.name);
  for (const auto& r : file.routes) {
    out << "  <rte>";
    if (!r.name.empty()) out << "<name>" << escape(r.name) << "</name>";
    out << '\n';
    for (const auto& p : r.points) point(out, "rtept", p, "    ");
    out << "  </rte>\n";
  }
  for (const auto& t : file.tracks) {
    out << "  <trk>";
    if (!t.name.empty()) out << "<name>" << escape(t.name) << "</name>";
    if (!t.description.empty()) out << "<desc>" << escape(t.description) << "</desc>";
    if (!t.type.empty()) out << "<type>" << escape(t.type) << "</type>";
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
