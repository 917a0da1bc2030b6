#pragma once
// A gx:Track as it is read: KML writes its times (<when>), positions (<gx:coord>) and recorded
// channels (ExtendedData/SchemaData/gx:SimpleArrayData/gx:value) as separate lists that pair up
// by index, interleaved or one after the other, so the points are assembled at the end.

#include <optional>
#include <utility>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/io/kml_values.hpp"
#include "track/model.hpp"

namespace trailray::track {

struct GxTrackParts {
  SourcePosition where;                              // the gx:Track element
  std::vector<double> times;                         // NaN where a <when> was empty or unreadable
  std::vector<std::optional<KmlCoordinate>> coords;  // nullopt where unusable (warned when read)
  std::vector<std::pair<ArrayChannel, std::vector<double>>> arrays;

  // The points with usable coordinates, each with the time and channel values of its index. A
  // complete track whose lists differ in length gets a warning (the pairing is then by order); a
  // cut one (`complete` false) is expected to.
  std::vector<TrackPoint> assemble(WarningCollector& warnings, bool complete) const;
};

}  // namespace trailray::track
