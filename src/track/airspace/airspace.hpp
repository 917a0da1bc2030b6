#pragma once
// Airspaces as read from an OpenAir file: a class, a name, a floor and a ceiling, and the
// lateral boundary as one closed ring of WGS84 points (arcs and circles already turned into
// points, see arc_geometry.hpp). GL-free, so checks and the 3D drawing share one model.

#include <string>
#include <vector>

#include "geo/web_mercator.hpp"
#include "track/diagnostics.hpp"

namespace trailray::track::airspace {

// What a vertical limit is measured against.
enum class AltitudeReference {
  Msl,        // above mean sea level (AMSL/MSL, or no reference given): compare with GNSS altitude
  Agl,        // above the ground (AGL, GND, SFC, ASFC): needs the terrain height below
  Std,        // pressure altitude against 1013.25 hPa (FL, STD): compare with pressure altitude
  Unlimited,  // UNL, UNLIM, UNLIMITED: no limit
};

struct AltitudeLimit {
  AltitudeReference reference = AltitudeReference::Msl;
  double metres = 0.0;  // height above the reference (FL n = n * 100 ft); 0 for Unlimited
  std::string text;     // as written in the file, for messages

  bool is_ground() const { return reference == AltitudeReference::Agl && metres == 0.0; }
};

struct Airspace {
  std::string airspace_class;  // AC: A..G, CTR, R, Q, P, GP, W, TMZ, RMZ, ...
  std::string name;            // AN, in UTF-8
  AltitudeLimit floor;         // AL
  AltitudeLimit ceiling;       // AH
  // Closed ring, first point not repeated. Two points are a line (cables in Skytraxx files,
  // floor = ceiling): drawn, never entered. Longitudes are continuous along the ring
  // (geo::unwrap_longitudes): one crossing the antimeridian runs past +-180 degrees.
  std::vector<geo::LatLon> boundary;
  std::int64_t line = 0;  // the line of its AC record
};

struct AirspaceFile {
  std::vector<Airspace> airspaces;
};

struct AirspaceReadResult {
  AirspaceFile file;
  std::size_t skipped = 0;  // airspaces the file declares (AC records) that could not be used: warned
  std::vector<Diagnostic> warnings;
  std::optional<Diagnostic> error;

  bool ok() const { return !error.has_value(); }
};

}  // namespace trailray::track::airspace
