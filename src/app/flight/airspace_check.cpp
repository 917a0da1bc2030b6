#include "app/flight/airspace_check.hpp"

#include <cmath>

namespace trailray::app {
namespace {

using track::airspace::CheckPoint;
using IgcAltitude = track::ReadOptions::IgcAltitude;

// The points as checked: their elevation against MSL (and AGL) limits; with `pressure`, an IGC's
// pressure altitude (kept beside the elevation whichever --igc-altitude picked) against FL/STD.
CheckSegments segments_of(const track::TrackFile& f, bool pressure) {
  CheckSegments out;
  for (const auto& t : f.tracks)
    for (const auto& s : t.segments) {
      std::vector<CheckPoint> points;
      points.reserve(s.points.size());
      for (const auto& p : s.points) {
        const double std_m = pressure && p.has_pressure_altitude() ? p.pressure_altitude : track::kMissing;
        points.push_back({p.lat, p.lon, p.time, p.ele, std_m, track::kMissing});
      }
      out.push_back(std::move(points));
    }
  return out;
}

bool any_pressure_altitude(const CheckSegments& segments) {
  for (const auto& s : segments)
    for (const auto& p : s)
      if (!std::isnan(p.std_m)) return true;
  return false;
}

}  // namespace

CheckedPoints checked_points(const std::string& display_path, const track::TrackFile& file,
                             IgcAltitude igc_altitude) {
  CheckedPoints out;
  const bool igc = file.format == track::Format::Igc;
  // GNSS mode: the GNSS altitude for every limit, as asked; otherwise FL/STD limits take the
  // pressure altitude where the file has one (in pressure mode it is the elevation too).
  out.segments = segments_of(file, igc && igc_altitude != IgcAltitude::Gnss);
  out.track = CheckedTrack{display_path, 0, "", {}};
  for (const auto& s : out.segments) {
    out.track.points += s.size();
    for (const auto& p : s) out.without_altitude += std::isnan(p.msl_m);
  }
  if (!igc)
    out.track.altitudes = "one elevation per point: compared with every limit (FL too, as if it were pressure altitude)";
  else if (igc_altitude == IgcAltitude::Gnss)
    out.track.altitudes = "IGC GNSS altitude for every limit (FL too)";
  else if (igc_altitude == IgcAltitude::Pressure)
    out.track.altitudes = "IGC pressure altitude (--igc-altitude pressure) for every limit";
  else if (!any_pressure_altitude(out.segments))
    out.track.altitudes = "IGC without pressure altitude: FL limits compared with the GNSS altitude";
  else
    out.track.altitudes =
        "IGC: FL/STD limits with the pressure altitude (against 1013.25 hPa), MSL/AGL limits with the GNSS altitude";
  return out;
}

}  // namespace trailray::app
