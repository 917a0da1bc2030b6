#pragma once
// Builds the track model from decoded FIT messages (fit_decoder.hpp):
//
//   record         -> TrackPoint: position (semicircles -> degrees), enhanced_altitude or
//                     altitude (scale 5, offset 500), enhanced_speed or speed (or the speed of
//                     compressed_speed_distance), heart_rate, cadence, power, temperature,
//                     timestamp. A record without a position (sensor-only samples, samples
//                     before the GPS fix) cannot be placed: it is dropped and counted in the
//                     metadata field "records_without_position" (routine, so not a warning).
//   session        -> one Track per session (multisport files have several): sport -> type;
//                     records go to the session whose start_time they follow.
//   timer stop, then start -> the next record starts a new Segment: the device recorded
//                     nothing while stopped, so nothing may be measured across the pause (the
//                     session's own distance leaves it out too). Laps do NOT split segments:
//                     a lap boundary is a button press in a continuous recording, and a
//                     segment boundary would drop the distance between the laps from
//                     `trailray stats`. Laps are counted in the metadata field "laps".
//   chained FIT files -> each starts a new Segment (separate recordings).
//   course / course_point -> the course name names the track; course points become
//                     Waypoints (name, type -> symbol, time).
//   file_id, sport -> metadata: creator (product name, or manufacturer and product),
//                     time_created -> time, file type, manufacturer, product, serial number;
//                     the first session's (or sport message's) sport -> activity_type.
//
// Times: FIT date_time is seconds since 1989-12-31T00:00:00Z. Values below 0x10000000 are
// seconds since the device powered on (VIRB cameras, old Garmins). They are made UTC with the
// offset of a timestamp_correlation message (timestamp - system_timestamp) when the file has
// one, else with device_settings' utc_offset (what gpsbabel does); without either they are
// kept as read (dates in 1990) with a warning that they are not UTC.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "track/diagnostics.hpp"
#include "track/io/fit_decoder.hpp"
#include "track/model.hpp"

namespace trailray::track::fit {

class TrackBuilder {
 public:
  TrackBuilder(TrackFile& file, WarningCollector& warnings) : file_(file), warnings_(warnings) {}

  void add(const Message& m);
  // Fills the model; call once after the last message.
  void finish(const DecodeStats& stats);

  std::size_t complete_points() const { return points_.size(); }

 private:
  struct Point {
    TrackPoint point;
    std::optional<std::uint32_t> fit_time;
    bool starts_segment = false;
  };
  struct Session {
    std::optional<std::uint32_t> start_time;
    std::string sport;
  };

  void add_record(const Message& m);
  std::optional<Waypoint> waypoint_at(const Message& m, std::uint8_t lat_field, std::uint8_t lon_field,
                                      const std::string& what);
  void add_course_point(const Message& m);
  void add_location(const Message& m);
  void add_file_id(const Message& m);
  void add_event(const Message& m);
  // FIT time -> seconds since the Unix epoch, with the device-relative offset applied.
  double unix_time(std::uint32_t fit_time) const;
  std::optional<std::int64_t> relative_time_offset() const;
  void build_tracks();

  TrackFile& file_;
  WarningCollector& warnings_;
  std::vector<Point> points_;
  std::vector<Session> sessions_;
  std::vector<std::pair<Waypoint, std::optional<std::uint32_t>>> course_points_;
  std::vector<Waypoint> locations_;  // saved places: waypoints after the course points
  std::string course_name_, sport_from_sport_message_;
  std::optional<std::uint32_t> time_created_;
  std::optional<std::int64_t> correlation_offset_, utc_offset_;
  bool break_pending_ = false;
  bool timer_stopped_ = false;
  int current_file_ = 0;
  bool saw_relative_time_ = false;
  std::size_t records_without_position_ = 0;
  std::size_t laps_ = 0;
};

}  // namespace trailray::track::fit
