#include "track/io/csv_writer.hpp"

#include <cmath>
#include <string>

#include "track/io/text_output.hpp"

namespace trailray::track {
namespace {

template <typename T>
std::string optional_number(T v) {
  return std::isnan(v) ? std::string() : format_number(v);
}

void row(std::ostream& out, const char* kind, std::size_t number, const std::string& segment, const std::string& name,
         const TrackPoint& p) {
  out << kind << ',' << number << ',' << segment << ',' << csv_field(name) << ',' << format_number(p.lat) << ','
      << format_number(p.lon) << ',' << optional_number(p.ele) << ','
      << (p.has_time() ? format_iso_time(p.time) : std::string()) << ',' << optional_number(p.heart_rate) << ','
      << optional_number(p.cadence) << ',' << optional_number(p.power) << ',' << optional_number(p.temperature) << ','
      << optional_number(p.speed) << '\n';
}

}  // namespace

void write_csv(const TrackFile& file, std::ostream& out) {
  out << "kind,track,segment,name,lat,lon,ele,time,hr,cad,power,temp,speed\n";
  for (std::size_t t = 0; t < file.tracks.size(); ++t) {
    const Track& track = file.tracks[t];
    for (std::size_t s = 0; s < track.segments.size(); ++s)
      for (const TrackPoint& p : track.segments[s].points)
        row(out, "track", t + 1, std::to_string(s + 1), track.name, p);
  }
  for (std::size_t r = 0; r < file.routes.size(); ++r)
    for (const TrackPoint& p : file.routes[r].points) row(out, "route", r + 1, {}, file.routes[r].name, p);
  for (std::size_t w = 0; w < file.waypoints.size(); ++w)
    row(out, "waypoint", w + 1, {}, file.waypoints[w].name, file.waypoints[w].point);
}

}  // namespace trailray::track
