#include "track/io/kml_gx_track.hpp"

#include <cfloat>
#include <cmath>
#include <string>

namespace trailray::track {
namespace {

float* channel_field(TrackPoint& p, ArrayChannel c) {
  switch (c) {
    case ArrayChannel::HeartRate:
      return &p.heart_rate;
    case ArrayChannel::Cadence:
      return &p.cadence;
    case ArrayChannel::Power:
      return &p.power;
    case ArrayChannel::Temperature:
      return &p.temperature;
    case ArrayChannel::None:
      break;
  }
  return nullptr;
}

}  // namespace

std::vector<TrackPoint> GxTrackParts::assemble(WarningCollector& warnings, bool complete) const {
  if (complete && !times.empty() && times.size() != coords.size())
    warnings.add("gx-track-lengths", where,
                 "gx:Track has " + std::to_string(times.size()) + " <when> and " + std::to_string(coords.size()) +
                     " <gx:coord>: times paired with positions by order");
  std::vector<TrackPoint> points;
  points.reserve(coords.size());
  for (std::size_t i = 0; i < coords.size(); ++i) {
    if (!coords[i]) continue;
    TrackPoint p;
    p.lon = coords[i]->lon;
    p.lat = coords[i]->lat;
    p.ele = coords[i]->alt;
    if (i < times.size()) p.time = times[i];
    for (const auto& [channel, values] : arrays) {
      float* field = channel_field(p, channel);
      // A float cast of a value beyond FLT_MAX would be undefined; such a value means nothing.
      if (field && i < values.size() && std::fabs(values[i]) <= static_cast<double>(FLT_MAX))
        *field = static_cast<float>(values[i]);
    }
    points.push_back(p);
  }
  return points;
}

}  // namespace trailray::track
