#pragma once
// The tracks of a scene, one model for every front end: each track (or route) of the files
// opened, cleaned and measured once, with the per-point numbers the chart, tooltips and replay
// read, and what the renderer draws (its ECEF polylines with colour values and curtain heights,
// its colour, whether it is shown).
//
// A track has an id that stays the same while it is in its set (unique among the tracks of every
// set of the process, so one renderer can draw several sets), and a revision that changes
// whenever what is drawn of it changes (colour values, curtain, geometry): the renderer keeps one
// GPU buffer per (id, revision), so front ends never hold GPU objects.
//
// Points are numbered "flat": the points of a track's non-empty segments one after the other,
// the order the geometry stores them in, so a point index means the same thing to the chart, the
// 3D picking and the replay marker.

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/tracks/track_geometry.hpp"
#include "track/color_values.hpp"
#include "track/flight/flight_analysis.hpp"
#include "track/metrics.hpp"
#include "track/model.hpp"
#include "track/summary.hpp"

namespace trailray::scene {

using TrackId = std::uint64_t;

struct Track {
  TrackId id = 0;
  std::uint64_t revision = 0;  // bump_revision() after changing what is drawn
  std::string name;            // the track's (or route's) name, else the file's name and its number
  std::string source;          // the file it came from

  track::Track cleaned;         // after clean_track: what is drawn and measured
  // The options its metrics were computed with: the metrics themselves (seven numbers a point)
  // are not kept but worked out again from `cleaned` when a colouring needs them, so that a
  // season of tracks fits in memory (the per-point numbers below hold what the panels read).
  track::MetricsOptions metrics_options;
  track::TrackSummary summary;  // raw and clean statistics, as `trailray stats` prints them
  // The flight analysis of the track as read (before cleaning, as `trailray flight` sees it);
  // nullptr where it was not asked for (TrackBuildOptions) or for a route. Shared: copies of a
  // track need not copy it.
  std::shared_ptr<const track::flight::FlightAnalysis> flights;

  // Per flat point (NaN where a point has no such value).
  std::vector<std::size_t> segment_first;   // flat index of each non-empty segment's first point
  std::vector<double> distance_m;           // cumulative 2D distance from the start (gaps add nothing)
  std::vector<double> time_unix_s;          // timestamp
  std::vector<double> altitude_m;           // recorded elevation (what the 3D track is drawn at)
  // The recorded channels below are empty when no point has the channel: read them through the
  // accessors (pressure_altitude(i), heart_rate(i), ...), which answer NaN then.
  std::vector<double> pressure_altitude_m;  // IGC pressure altitude (against 1013.25 hPa)
  std::vector<double> gnss_altitude_m;      // IGC GNSS altitude
  std::vector<double> ground_m;             // terrain height below (NaN: no terrain, or not sampled yet)
  std::vector<double> speed_kmh;            // windowed horizontal speed
  std::vector<double> vspeed_ms;            // windowed vertical speed, positive climbing
  std::vector<double> heart_rate_bpm;       // recorded
  std::vector<double> cadence_rpm;          // recorded (revolutions or steps per minute)
  std::vector<double> power_w;              // recorded
  // With a surface model (TrackBuildOptions::surface): each point's track::Cover (0 open, 1
  // covered, 2 below the ground; kNoCover where a model has no height there); empty without.
  std::vector<std::uint8_t> cover;
  static constexpr std::uint8_t kNoCover = 255;
  std::vector<std::uint32_t> timed_points;  // the flat indices of the points with a time, in order
  double time_origin_s = track::kMissing;    // the first timestamp in file order (NaN: none)
  bool times_rise = true;                   // their times never go back (cleaned tracks' do not)

  // What is drawn: one polyline per non-empty segment, points in ECEF (points without an
  // elevation on the ground), the colour values of the style's metric, curtain heights.
  TrackGeometry geometry;
  bool visible = true;
  glm::vec3 color_srgb{1.0f, 0.0f, 0.0f};
  bool by_value = true;  // coloured by the style's metric (when it is not solid), else color_srgb
  // A planned route (GPX rte), not a recorded track: drawn thinner and dashed in the style's
  // route colour, never by value; its geometry's values are metres along it (for the dashes).
  bool is_route = false;

  std::size_t point_count() const { return distance_m.size(); }
  // Where flat point `point` is drawn (ECEF).
  const glm::dvec3& ecef(std::size_t point) const;
  // The segment holding a flat point index.
  std::size_t segment_of(std::size_t point) const;
  // Seconds since the track's first timestamp (NaN: the point has no time).
  double elapsed(std::size_t point) const { return time_unix_s[point] - time_origin_s; }
  // The first and last timestamp (nullopt: no timed point).
  std::optional<double> start_time() const;
  std::optional<double> end_time() const;
  // The lowest recorded altitude (NaN: no point has one).
  double lowest_altitude() const;
  // A point's pressure altitude (NaN: none, or no such array).
  double pressure_altitude(std::size_t point) const {
    return point < pressure_altitude_m.size() ? pressure_altitude_m[point] : track::kMissing;
  }
  // A point's GNSS altitude (NaN: none, or no such array).
  double gnss_altitude(std::size_t point) const {
    return point < gnss_altitude_m.size() ? gnss_altitude_m[point] : track::kMissing;
  }
  // A point's recorded heart rate, cadence, power (NaN: none, or no such array).
  double heart_rate(std::size_t point) const { return value_or_nan(heart_rate_bpm, point); }
  double cadence(std::size_t point) const { return value_or_nan(cadence_rpm, point); }
  double power(std::size_t point) const { return value_or_nan(power_w, point); }
  static double value_or_nan(const std::vector<double>& v, std::size_t point) {
    return point < v.size() ? v[point] : track::kMissing;
  }
  // Some point has a pressure altitude (an IGC file with a barometer).
  bool has_pressure_altitude() const;
  // Some point has a GNSS altitude (an IGC file whose GNSS channel is recorded).
  bool has_gnss_altitude() const;
  // Which IGC altitude the drawn one (altitude_m) is: `--igc-altitude` put it into `ele`, and
  // cleaning smooths all three alike, so it equals that one (to well under 1 cm). In auto mode a
  // 'V' fix takes the pressure altitude: the one it equals at most points. None: not an IGC
  // flight, or no drawn altitude.
  enum class AltitudeSource { none, gnss, pressure };
  AltitudeSource altitude_source() const;
  // Points with a colour value.
  std::size_t points_with_value() const;
  void bump_revision() { ++revision; }
};

class TrackSet {
 public:
  // Adds a track and gives it a new id (returned), never given to another track of any set.
  TrackId add(Track track);
  // nullptr when no track has that id.
  const Track* find(TrackId id) const;
  Track* find(TrackId id);

  std::vector<Track>& tracks() { return tracks_; }
  const std::vector<Track>& tracks() const { return tracks_; }
  std::size_t size() const { return tracks_.size(); }
  bool empty() const { return tracks_.empty(); }
  Track& operator[](std::size_t i) { return tracks_[i]; }
  const Track& operator[](std::size_t i) const { return tracks_[i]; }
  Track& at(std::size_t i) { return tracks_.at(i); }
  const Track& at(std::size_t i) const { return tracks_.at(i); }

 private:
  std::vector<Track> tracks_;
};

}  // namespace trailray::scene
