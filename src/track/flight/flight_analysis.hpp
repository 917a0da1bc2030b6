#pragma once
// Flight analysis for pilots: take-off and landing, several flights in one track, and per flight
// the phases (circling left or right, gliding), each thermal's climb, drift and the wind it
// implies, each glide's distance and glide ratio, and a summary with the wind per altitude band.
// GL-free and terrain-free; works on any track with times (IGC, GPX, ...), on the altitude the
// reader chose (points' `ele`).
//
// How it decides (constants in FlightOptions, defaults below):
// - Take-off and landing: the scoring layer's launch detection (10 s averages of ground speed and
//   vertical speed, scoring/launch_landing.hpp), each flight then trimmed to its first and last
//   fix with more than a walking ground speed, so a hike before take-off is not flight time.
// - Turn rate: the track's heading change per second, summed over a centred window of
//   `turn_window_s`. Circling starts at |rate| >= `circling_enter_deg_s` and lasts while
//   |rate| >= `circling_exit_deg_s` (hysteresis); positive = clockwise = circling right. Circling
//   shorter than `min_thermal_s` is gliding (an S-turn or a single 360 is not a thermal); gliding
//   shorter than `min_glide_s` between two circlings belongs to the thermal. Where the window
//   spans a gap (segment boundary, or a step over `max_gap_s` and over 3 times the median step)
//   the phase is Unknown.
// - Wind from a thermal: the centre of every full turn (the time-mean of the positions over 360
//   degrees of heading, the air mass's circle centre) is fitted by a straight line in time; its
//   velocity is the wind. A thermal of less than 2 full turns uses its start-to-end
//   displacement over its duration instead (wind_from_centres false; less exact).
//
// Phases tile each flight: phase k runs from sample `start` to sample `end`, and phase k+1
// starts at that same fix, so durations add up to the flight's duration exactly.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "track/model.hpp"

namespace trailray::track::flight {

enum class Phase : std::uint8_t { Ground, CirclingLeft, CirclingRight, Gliding, Unknown };

const char* phase_name(Phase p);  // "ground", "circling-left", "circling-right", "gliding", "unknown"
inline bool is_circling(Phase p) { return p == Phase::CirclingLeft || p == Phase::CirclingRight; }

struct FlightOptions {
  double turn_window_s = 20.0;           // window of the turn rate (about one thermalling circle)
  double circling_enter_deg_s = 7.0;     // |turn rate| that starts circling (a 51 s circle)
  double circling_exit_deg_s = 4.0;      // |turn rate| below which circling ends
  double min_thermal_s = 40.0;           // shorter circling is gliding
  double min_thermal_gain_m = 20.0;      // circling that gains less (a spiral down, turns in sink) is
                                         // circling time, not a thermal
  double min_glide_s = 20.0;             // shorter gliding between two circlings is thermalling
  double max_gap_s = 15.0;               // a longer step (and over 3 median steps) is a gap: Unknown
  double best_climb_window_s = 20.0;     // Thermal::best_climb_ms is the best climb over this long
  double best_glide_min_m = 2000.0;      // Flight::best_glide considers glides at least this long
  double best_glide_min_loss_m = 100.0;  // ... that lost at least this much height
  double wind_band_m = 500.0;            // height of the altitude bands of Flight::wind
};

// A fix of the analysed track.
struct Place {
  double time = kMissing;  // seconds since 1970-01-01 UTC
  double lat = 0.0, lon = 0.0;
  double alt = kMissing;  // metres (the point's ele; NaN when the track has none)
  std::size_t point = 0;  // index among the track's points, counted across segments in order
};

struct PhaseSpan {
  Phase phase = Phase::Unknown;
  Place start, end;  // end is the next phase's start (or the landing)
  double duration_s() const { return end.time - start.time; }
};

struct Thermal {
  Place start, end;  // entry and exit (altitudes: entry and exit altitude)
  Phase direction = Phase::CirclingRight;
  double duration_s = 0.0;
  double gain_m = kMissing;         // exit minus entry altitude (negative when it lost height)
  double mean_climb_ms = kMissing;  // gain / duration
  double best_climb_ms = kMissing;  // best over FlightOptions::best_climb_window_s (the mean if shorter)
  double turns = 0.0;               // full circles flown (heading change / 360)
  double drift_m = 0.0;             // how far the air mass carried the circles during the thermal
  double drift_to_deg = kMissing;   // the direction it carried them to (degrees from north)
  double wind_speed_ms = kMissing;  // wind implied by the drift, m/s
  double wind_from_deg = kMissing;  // meteorological: where the wind blows from, [0, 360)
  bool wind_from_centres = false;   // true: fitted circle centres; false: start-to-end position
  std::size_t phase = 0;            // index into Flight::phases
};

struct Glide {
  Place start, end;
  double duration_s = 0.0;
  double distance_m = 0.0;          // along the track over the ground
  double height_lost_m = kMissing;  // start minus end altitude (negative: it climbed)
  double glide_ratio = kMissing;    // distance / height lost; NaN when it lost no height
  double mean_speed_ms = 0.0;       // distance / duration
  std::size_t phase = 0;            // index into Flight::phases
};

// The wind in an altitude band: from the thermals whose mean altitude is in it and whose wind
// came from their circle centres (wind_from_centres; the start-to-end estimate is too rough).
struct WindBand {
  double floor_m = 0.0, ceiling_m = 0.0;  // altitude band of the thermals' mean altitude
  double speed_ms = 0.0;                  // length of the duration-weighted mean wind vector
  double from_deg = kMissing;             // meteorological direction of that vector
  int thermals = 0;
};

struct Flight {
  Place takeoff, landing;
  double duration_s = 0.0;
  std::vector<PhaseSpan> phases;  // tile takeoff..landing in order
  std::vector<Thermal> thermals;
  std::vector<Glide> glides;
  std::vector<WindBand> wind;  // lowest band first; bands without a thermal are left out
  double circling_s = 0.0, circling_left_s = 0.0, circling_right_s = 0.0, gliding_s = 0.0, unknown_s = 0.0;
  double circling_share = 0.0;              // circling_s / duration_s
  double mean_thermal_climb_ms = kMissing;  // total gain / total time of the thermals (time-weighted)
  double distance_m = 0.0;                  // along the track over the ground
  double max_alt_m = kMissing, min_alt_m = kMissing;
  double best_climb_ms = kMissing;  // the best thermal's best_climb_ms
  // Best glide: the highest glide ratio among glides of at least FlightOptions::best_glide_min_m
  // that lost at least best_glide_min_loss_m (a straight run in lift has a huge or no ratio and
  // says nothing about the glider); longest glide: the greatest distance. Indexes into glides,
  // -1 when none.
  int best_glide = -1;
  int longest_glide = -1;
};

struct FlightAnalysis {
  std::vector<Flight> flights;  // in time order; empty when nothing was found
  std::size_t points = 0;       // points of the track
  std::size_t points_used = 0;  // with a time, a valid position and a time after the previous one
  bool has_altitude = false;    // some point had an elevation (climbs and glide ratios need it)
};

// Never throws on any track. A track without times (points_used == 0) or without any elevation
// (has_altitude false: take-off needs the climb) gives no flights.
FlightAnalysis analyse_flights(const Track& track, const FlightOptions& options = {});

// The phase of every point of `track` (counted as Place::point), for colouring: Ground outside
// the flights; points the analysis skipped take the phase of the point before them.
std::vector<Phase> phase_per_point(const Track& track, const FlightAnalysis& analysis);

}  // namespace trailray::track::flight
