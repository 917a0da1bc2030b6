#include "track/io/fit_track_builder.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "track/io/fit_profile.hpp"
#include "track/io/readers.hpp"

namespace trailray::track::fit {
namespace {

SourcePosition at(std::int64_t offset) { return SourcePosition{0, 0, offset}; }

float channel(std::optional<double> v) {
  if (!v || std::fabs(*v) > static_cast<double>(FLT_MAX)) return kMissingF;
  return static_cast<float>(*v);
}

std::optional<double> scaled(const Message& m, std::uint8_t field, double scale, double offset = 0.0) {
  auto v = m.number(field);
  if (!v) return std::nullopt;
  return *v / scale - offset;
}

std::optional<std::uint32_t> time_field(const Message& m, std::uint8_t field) {
  auto v = m.integer(field);
  if (!v || *v < 0 || *v > 0xFFFFFFFF) return std::nullopt;
  return static_cast<std::uint32_t>(*v);
}

// The speed in compressed_speed_distance (byte[3]): its low 12 bits, in 1/100 m/s.
std::optional<double> compressed_speed(const Message& m) {
  const Field* f = m.find(record::kCompressedSpeedDistance);
  if (!f || f->bytes.size() != 3) return std::nullopt;
  const auto b0 = static_cast<std::uint8_t>(f->bytes[0]), b1 = static_cast<std::uint8_t>(f->bytes[1]);
  if (b0 == 0xFF && b1 == 0xFF) return std::nullopt;
  return static_cast<double>(b0 | (b1 & 0x0F) << 8) / 100.0;
}

}  // namespace

void TrackBuilder::add(const Message& m) {
  if (m.file != current_file_) {
    current_file_ = m.file;
    break_pending_ = true;
  }
  switch (m.global) {
    case msg::kRecord:
      add_record(m);
      break;
    case msg::kEvent:
      add_event(m);
      break;
    case msg::kLap:
      ++laps_;
      break;
    case msg::kSession: {
      Session s;
      s.start_time = time_field(m, session::kStartTime);
      if (auto sport = m.integer(session::kSport)) s.sport = sport_name(static_cast<std::uint64_t>(*sport));
      sessions_.push_back(std::move(s));
      break;
    }
    case msg::kSport:
      if (auto sport = m.integer(sport::kSport); sport && sport_from_sport_message_.empty())
        sport_from_sport_message_ = sport_name(static_cast<std::uint64_t>(*sport));
      break;
    case msg::kCourse:
      if (course_name_.empty()) course_name_ = m.text(course::kName);
      if (auto sport = m.integer(course::kSport); sport && sport_from_sport_message_.empty())
        sport_from_sport_message_ = sport_name(static_cast<std::uint64_t>(*sport));
      break;
    case msg::kCoursePoint:
      add_course_point(m);
      break;
    case msg::kLocation:
      add_location(m);
      break;
    case msg::kFileId:
      add_file_id(m);
      break;
    case msg::kDeviceSettings:
      if (auto v = m.integer(device_settings::kUtcOffset); v && !utc_offset_) utc_offset_ = *v;
      break;
    case msg::kTimestampCorrelation: {
      auto system = time_field(m, timestamp_correlation::kSystemTimestamp);
      auto utc = time_field(m, kFieldTimestamp);
      if (system && utc && *utc >= kMinAbsoluteTime && !correlation_offset_)
        correlation_offset_ = static_cast<std::int64_t>(*utc) - static_cast<std::int64_t>(*system);
      break;
    }
    default:
      break;
  }
}

void TrackBuilder::add_record(const Message& m) {
  auto lat = m.integer(record::kPositionLat), lon = m.integer(record::kPositionLong);
  if (!lat || !lon) {
    ++records_without_position_;
    return;
  }
  Point p;
  p.point.lat = static_cast<double>(*lat) * kDegreesPerSemicircle;
  p.point.lon = static_cast<double>(*lon) * kDegreesPerSemicircle;
  if (!valid_coordinates(p.point.lat, p.point.lon)) {
    warnings_.add("fit-coords", at(m.offset),
                  "record with a position out of range (" + std::to_string(*lat) + ", " + std::to_string(*lon) +
                      " semicircles) dropped");
    return;
  }
  auto ele = scaled(m, record::kEnhancedAltitude, record::kAltitudeScale, record::kAltitudeOffset);
  if (!ele) ele = scaled(m, record::kAltitude, record::kAltitudeScale, record::kAltitudeOffset);
  if (ele) p.point.ele = *ele;
  auto speed = scaled(m, record::kEnhancedSpeed, record::kSpeedScale);
  if (!speed) speed = scaled(m, record::kSpeed, record::kSpeedScale);
  if (!speed) speed = compressed_speed(m);
  p.point.speed = channel(speed);
  p.point.heart_rate = channel(m.number(record::kHeartRate));
  p.point.cadence = channel(m.number(record::kCadence));
  p.point.power = channel(m.number(record::kPower));
  p.point.temperature = channel(m.number(record::kTemperature));
  p.fit_time = m.timestamp;
  if (p.fit_time && *p.fit_time < kMinAbsoluteTime) saw_relative_time_ = true;
  p.starts_segment = break_pending_;
  break_pending_ = false;
  points_.push_back(p);
}

void TrackBuilder::add_event(const Message& m) {
  auto event = m.integer(event::kEvent), type = m.integer(event::kEventType);
  if (!event || !type || *event != event::kEventTimer) return;
  // The segment breaks at the restart, not at the stop: devices often write one more record
  // after the stop event, which belongs to the stretch before the pause (gpsbabel agrees).
  if (*type == event::kTypeStop || *type == event::kTypeStopAll) {
    timer_stopped_ = true;
  } else if (*type == event::kTypeStart && timer_stopped_) {
    timer_stopped_ = false;
    break_pending_ = true;
  }
}

// A waypoint at a message's position (semicircles in fields `lat_field`, `lon_field`); nullopt,
// with a warning naming `what`, when it has none or one out of range.
std::optional<Waypoint> TrackBuilder::waypoint_at(const Message& m, std::uint8_t lat_field, std::uint8_t lon_field,
                                                  const std::string& what) {
  auto lat = m.integer(lat_field), lon = m.integer(lon_field);
  if (!lat || !lon) {
    warnings_.add("fit-" + what, at(m.offset), what + " without a position dropped");
    return std::nullopt;
  }
  Waypoint w;
  w.point.lat = static_cast<double>(*lat) * kDegreesPerSemicircle;
  w.point.lon = static_cast<double>(*lon) * kDegreesPerSemicircle;
  if (!valid_coordinates(w.point.lat, w.point.lon)) {
    warnings_.add("fit-" + what, at(m.offset), what + " with a position out of range dropped");
    return std::nullopt;
  }
  return w;
}

void TrackBuilder::add_course_point(const Message& m) {
  std::optional<Waypoint> w = waypoint_at(m, course_point::kPositionLat, course_point::kPositionLong, "course point");
  if (!w) return;
  w->name = m.text(course_point::kName);
  if (auto type = m.integer(course_point::kType)) w->symbol = course_point_type_name(static_cast<std::uint64_t>(*type));
  auto time = time_field(m, course_point::kTimestamp);
  if (time && *time < kMinAbsoluteTime) saw_relative_time_ = true;
  course_points_.emplace_back(std::move(*w), time);
}

// A saved place of a Locations file: a waypoint with its name, description and altitude. Its
// timestamp is when it was saved, not when anyone was there: not kept (gpsbabel agrees).
void TrackBuilder::add_location(const Message& m) {
  std::optional<Waypoint> w = waypoint_at(m, location::kPositionLat, location::kPositionLong, "location");
  if (!w) return;
  if (auto ele = scaled(m, location::kAltitude, record::kAltitudeScale, record::kAltitudeOffset)) w->point.ele = *ele;
  w->name = m.text(location::kName);
  w->description = m.text(location::kDescription);
  locations_.push_back(std::move(*w));
}

void TrackBuilder::add_file_id(const Message& m) {
  if (!file_.metadata.fields.empty()) return;  // the first file of a chain describes the file
  auto& fields = file_.metadata.fields;
  if (auto type = m.integer(file_id::kType)) fields.emplace_back("file_type", file_type_name(*type));
  std::string manufacturer, product;
  if (auto v = m.integer(file_id::kManufacturer))
    fields.emplace_back("manufacturer", manufacturer = manufacturer_name(*v));
  if (auto v = m.integer(file_id::kProduct)) fields.emplace_back("product", product = std::to_string(*v));
  if (auto v = m.integer(file_id::kSerialNumber)) fields.emplace_back("serial_number", std::to_string(*v));
  const std::string name = m.text(file_id::kProductName);
  if (!name.empty())
    file_.metadata.creator = name;
  else if (!manufacturer.empty())
    file_.metadata.creator = product.empty() ? manufacturer : manufacturer + " " + product;
  time_created_ = time_field(m, file_id::kTimeCreated);
}

std::optional<std::int64_t> TrackBuilder::relative_time_offset() const {
  if (correlation_offset_) return correlation_offset_;
  return utc_offset_;
}

double TrackBuilder::unix_time(std::uint32_t fit_time) const {
  double t = static_cast<double>(fit_time);
  if (fit_time < kMinAbsoluteTime) {
    if (auto offset = relative_time_offset()) t += static_cast<double>(*offset);
  }
  return t + kFitEpochUnix;
}

void TrackBuilder::finish(const DecodeStats& stats) {
  if (saw_relative_time_ && !relative_time_offset())
    warnings_.add_single(at(-1),
                         "timestamps are relative to the device's power-on and the file gives no UTC offset: "
                         "times are kept as read and are not UTC");
  if (time_created_ && (*time_created_ >= kMinAbsoluteTime || relative_time_offset()))
    file_.metadata.time = unix_time(*time_created_);
  if (!sessions_.empty())
    file_.metadata.activity_type = sessions_.front().sport;
  else
    file_.metadata.activity_type = sport_from_sport_message_;
  build_tracks();
  for (auto& [w, time] : course_points_) {
    if (time) w.point.time = unix_time(*time);
    file_.waypoints.push_back(std::move(w));
  }
  for (Waypoint& w : locations_) file_.waypoints.push_back(std::move(w));
  auto& fields = file_.metadata.fields;
  fields.emplace_back("laps", std::to_string(laps_));
  fields.emplace_back("records_without_position", std::to_string(records_without_position_));
  if (stats.developer_fields > 0)
    fields.emplace_back("developer_fields_skipped", std::to_string(stats.developer_fields));
  if (stats.files > 1) fields.emplace_back("chained_fit_files", std::to_string(stats.files));
}

void TrackBuilder::build_tracks() {
  // Sessions in time order; with fewer than two, every point belongs to one track.
  std::vector<Session> sessions = sessions_;
  std::stable_sort(sessions.begin(), sessions.end(), [](const Session& a, const Session& b) {
    return a.start_time.value_or(0) < b.start_time.value_or(0);
  });
  if (sessions.empty()) sessions.push_back(Session{std::nullopt, sport_from_sport_message_});
  const bool by_time = sessions.size() > 1;
  std::vector<Track> tracks(sessions.size());
  for (std::size_t i = 0; i < sessions.size(); ++i) tracks[i].type = sessions[i].sport;
  if (!course_name_.empty()) tracks.front().name = course_name_;
  std::size_t current = 0;
  for (Point& p : points_) {
    std::size_t index = 0;
    if (by_time && p.fit_time) {
      for (std::size_t i = 0; i < sessions.size(); ++i)
        if (sessions[i].start_time && *sessions[i].start_time <= *p.fit_time) index = i;
    } else if (by_time) {
      index = current;  // no time: stays with the previous point's session
    }
    if (p.fit_time) p.point.time = unix_time(*p.fit_time);
    Track& t = tracks[index];
    if (t.segments.empty() || p.starts_segment || index != current) {
      if (t.segments.empty() || !t.segments.back().points.empty()) t.segments.emplace_back();
    }
    current = index;
    t.segments.back().points.push_back(p.point);
  }
  for (Track& t : tracks)
    if (!t.segments.empty()) file_.tracks.push_back(std::move(t));
}

}  // namespace trailray::track::fit
