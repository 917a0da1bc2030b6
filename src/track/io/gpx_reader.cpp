// GPX 1.0 and 1.1 reader: streaming, namespace-agnostic (default, prefixed or missing
// namespaces read alike), with the recorded channels of the common extensions:
// Garmin TrackPointExtension v1/v2 and GpxExtensions v3, Cluetrust gpxdata, and the plain
// hr/cad/temp/power/speed elements of Strava, Komoot, OsmAnd, Suunto and Wahoo exports.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <thread>

#include "geo/threads.hpp"

#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"
#include "track/io/xml_encoding.hpp"
#include "track/io/xml_stream.hpp"

namespace trailray::track {
namespace {

enum class Channel { None, HeartRate, Cadence, Temperature, Power, Speed };

// Extension element (any depth inside a point) -> recorded channel. Case-insensitive.
Channel extension_channel(std::string_view name) {
  char buf[24];
  // Known names are 2 to 12 letters; containers like TrackPointExtension are longer.
  if (name.size() < 2 || name.size() > 12) return Channel::None;
  for (std::size_t i = 0; i < name.size(); ++i)
    buf[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(name[i])));
  std::string_view n(buf, name.size());
  if (n == "hr" || n == "heartrate" || n == "heart_rate" || n == "heartratebpm") return Channel::HeartRate;
  if (n == "cad" || n == "cadence" || n == "runcadence") return Channel::Cadence;
  if (n == "atemp" || n == "temp" || n == "temperature") return Channel::Temperature;
  if (n == "power" || n == "watts" || n == "powerinwatts") return Channel::Power;
  if (n == "speed") return Channel::Speed;
  return Channel::None;
}

class GpxHandler final : public XmlHandler {
 public:
  GpxHandler(TrackFile& file, WarningCollector& warnings) : file_(file), warnings_(warnings) {}

  std::size_t complete_points() const { return complete_points_; }

  // For the second half of a file split at a <trkpt>: starts inside gpx/trk/trkseg, in a track
  // and segment of its own that the joining appends to the first half's.
  void continue_in_segment() {
    depth_ = 3;
    track_depth_ = 2;
    segment_depth_ = 3;
    file_.tracks.emplace_back().segments.emplace_back();
  }
  // True when the parse stands between two points of a segment, as the split requires.
  bool between_points() const { return depth_ == 3 && track_depth_ == 2 && segment_depth_ == 3 && point_depth_ < 0; }

  void start_element(std::string_view name, const char** attrs) override {
    ++depth_;
    if (depth_ == 1) {
      if (name != "gpx") {
        fail("root element is <" + std::string(name) + ">, expected <gpx>: not a GPX file");
        return;
      }
      if (const char* c = xml_attribute(attrs, "creator")) file_.metadata.creator = c;
      if (const char* v = xml_attribute(attrs, "version")) file_.metadata.fields.emplace_back("version", v);
      return;
    }
    if (point_depth_ > 0) return;  // children of a point are read at their end
    if (depth_ == 2) {
      if (name == "metadata") {
        metadata_depth_ = depth_;
      } else if (name == "trk") {
        file_.tracks.emplace_back();
        track_depth_ = depth_;
      } else if (name == "rte") {
        file_.routes.emplace_back();
        route_depth_ = depth_;
      } else if (name == "wpt") {
        begin_point(PointKind::Waypoint, attrs);
      }
      return;
    }
    if (track_depth_ > 0) {
      if (name == "trkseg" && depth_ == track_depth_ + 1) {
        file_.tracks.back().segments.emplace_back();
        segment_depth_ = depth_;
      } else if (name == "trkpt" && (depth_ == segment_depth_ + 1 || depth_ == track_depth_ + 1)) {
        // A trkpt directly under trk (seen in hand-written files) gets a segment of its own.
        if (segment_depth_ < 0 && (file_.tracks.back().segments.empty() || !implicit_segment_)) {
          file_.tracks.back().segments.emplace_back();
          implicit_segment_ = true;
        }
        begin_point(PointKind::TrackPoint, attrs);
      }
    } else if (route_depth_ > 0 && name == "rtept" && depth_ == route_depth_ + 1) {
      begin_point(PointKind::RoutePoint, attrs);
    }
  }

  void end_element(std::string_view name, std::string_view text) override {
    if (point_depth_ > 0) {
      if (depth_ == point_depth_) {
        end_point();
      } else {
        point_child(name, text);
      }
    } else if (track_depth_ > 0 && depth_ == track_depth_ + 1) {
      Track& t = file_.tracks.back();
      if (name == "name")
        t.name = std::string(trim(text));
      else if (name == "desc")
        t.description = std::string(trim(text));
      else if (name == "type")
        t.type = std::string(trim(text));
      else if (name == "trkseg")
        segment_depth_ = -1;
    } else if (route_depth_ > 0 && depth_ == route_depth_ + 1) {
      if (name == "name") file_.routes.back().name = std::string(trim(text));
    } else if ((metadata_depth_ > 0 && depth_ == metadata_depth_ + 1) || depth_ == 2) {
      // GPX 1.1 <metadata><name>, GPX 1.0 <gpx><name>.
      if (name == "name")
        file_.metadata.name = std::string(trim(text));
      else if (name == "desc")
        file_.metadata.description = std::string(trim(text));
      else if (name == "time") {
        if (auto t = parse_iso8601(text)) file_.metadata.time = *t;
      }
    }
    if (depth_ == track_depth_) track_depth_ = segment_depth_ = -1, implicit_segment_ = false;
    if (depth_ == route_depth_) route_depth_ = -1;
    if (depth_ == metadata_depth_) metadata_depth_ = -1;
    --depth_;
  }

 private:
  enum class PointKind { TrackPoint, RoutePoint, Waypoint };

  void begin_point(PointKind kind, const char** attrs) {
    point_kind_ = kind;
    point_depth_ = depth_;
    point_ = TrackPoint{};
    waypoint_ = Waypoint{};
    const char* lat = xml_attribute(attrs, "lat");
    const char* lon = xml_attribute(attrs, "lon");
    auto la = lat ? parse_double(lat) : std::nullopt;
    auto lo = lon ? parse_double(lon) : std::nullopt;
    point_valid_ = la && lo && valid_coordinates(*la, *lo);
    if (point_valid_) {
      point_.lat = *la;
      point_.lon = *lo;
    } else {
      warnings_.add("coords", position(),
                    "point with invalid coordinates dropped (lat=\"" +
                        std::string(lat ? lat : "<missing>").substr(0, 40) + "\" lon=\"" +
                        std::string(lon ? lon : "<missing>").substr(0, 40) + "\")");
    }
  }

  void point_child(std::string_view name, std::string_view text) {
    const bool direct = depth_ == point_depth_ + 1;
    if (direct && name == "ele") {
      set_number(point_.ele, text, "ele");
    } else if (direct && name == "time") {
      std::string_view t = trim(text);
      if (t.empty()) return;
      if (auto v = parse_iso8601(t))
        point_.time = *v;
      else
        warnings_.add("time", position(), "unreadable <time> '" + std::string(t.substr(0, 40)) + "' ignored");
    } else if (direct && point_kind_ == PointKind::Waypoint && (name == "name" || name == "desc" || name == "sym")) {
      std::string v(trim(text));
      if (name == "name")
        waypoint_.name = std::move(v);
      else if (name == "desc")
        waypoint_.description = std::move(v);
      else
        waypoint_.symbol = std::move(v);
    } else if (!direct || name == "speed") {
      // Extensions (any depth), and GPX 1.0's <speed> directly in the point.
      Channel c = extension_channel(name);
      switch (c) {
        case Channel::HeartRate:
          set_channel(point_.heart_rate, text, name);
          break;
        case Channel::Cadence:
          set_channel(point_.cadence, text, name);
          break;
        case Channel::Temperature:
          set_channel(point_.temperature, text, name);
          break;
        case Channel::Power:
          set_channel(point_.power, text, name);
          break;
        case Channel::Speed:
          set_channel(point_.speed, text, name);
          break;
        case Channel::None:
          break;
      }
    }
  }

  void set_number(double& out, std::string_view text, std::string_view what) {
    std::string_view t = trim(text);
    if (t.empty()) return;  // <ele/>: absent (OsmAnd writes these)
    if (auto v = parse_double(t))
      out = *v;
    else
      warnings_.add(std::string(what), position(),
                    "unreadable <" + std::string(what) + "> '" + std::string(t.substr(0, 40)) + "' ignored");
  }

  void set_channel(float& out, std::string_view text, std::string_view what) {
    double v = kMissing;
    set_number(v, text, what);
    if (std::isnan(v)) return;
    // Converting a double beyond float range is undefined behaviour: refuse such values.
    if (std::fabs(v) > 1e30) {
      warnings_.add(std::string(what), position(), "absurd <" + std::string(what) + "> value ignored");
      return;
    }
    out = static_cast<float>(v);
  }

  void end_point() {
    point_depth_ = -1;
    if (!point_valid_) return;
    ++complete_points_;
    switch (point_kind_) {
      case PointKind::TrackPoint:
        file_.tracks.back().segments.back().points.push_back(point_);
        break;
      case PointKind::RoutePoint:
        file_.routes.back().points.push_back(point_);
        break;
      case PointKind::Waypoint:
        waypoint_.point = point_;
        file_.waypoints.push_back(std::move(waypoint_));
        break;
    }
  }

  TrackFile& file_;
  WarningCollector& warnings_;
  int depth_ = 0;
  int metadata_depth_ = -1, track_depth_ = -1, segment_depth_ = -1, route_depth_ = -1, point_depth_ = -1;
  bool implicit_segment_ = false;
  PointKind point_kind_ = PointKind::TrackPoint;
  TrackPoint point_;
  Waypoint waypoint_;
  bool point_valid_ = false;
  std::size_t complete_points_ = 0;
};

// Appends the second half's content to the first's: its first segment continues the first
// half's last one, its first track the last track.
void join_halves(TrackFile& first, TrackFile& second) {
  Track& track = first.tracks.back();
  Track& rest = second.tracks.front();
  auto& points = track.segments.back().points;
  auto& more = rest.segments.front().points;
  points.insert(points.end(), more.begin(), more.end());
  for (std::size_t i = 1; i < rest.segments.size(); ++i) track.segments.push_back(std::move(rest.segments[i]));
  if (track.name.empty()) track.name = std::move(rest.name);
  if (track.description.empty()) track.description = std::move(rest.description);
  if (track.type.empty()) track.type = std::move(rest.type);
  for (std::size_t i = 1; i < second.tracks.size(); ++i) first.tracks.push_back(std::move(second.tracks[i]));
  for (auto& r : second.routes) first.routes.push_back(std::move(r));
  for (auto& w : second.waypoints) first.waypoints.push_back(std::move(w));
  if (first.metadata.name.empty()) first.metadata.name = second.metadata.name;
  if (first.metadata.description.empty()) first.metadata.description = second.metadata.description;
  if (std::isnan(first.metadata.time)) first.metadata.time = second.metadata.time;
}

}  // namespace

// A big plain GPX file is read in two halves at once (two cores): the second half starts at the
// first "<trkpt" after the middle, parsed as if inside gpx/trk/trkseg. When the first half does
// end exactly there, between two points of a segment, the halves are joined; otherwise (the
// split fell in a comment, names carry a prefix, an error) the caller reads it in one go.
std::optional<ReadResult> read_gpx_in_halves(ByteSource& source, const ReadOptions& options) {
  const std::int64_t size = source.size();
  if (size < 0 || size < options.two_part_min_bytes || size < 64) return std::nullopt;
  if (!is_utf8_document(source.peek(4096))) return std::nullopt;

  // The split: the first "<trkpt" followed by a space or '>' in the 1 MiB after the middle.
  auto probe = source.range(size / 2, std::min(size, size / 2 + (1 << 20)));
  if (!probe) return std::nullopt;
  std::string window(1 << 20, '\0');
  std::size_t got = 0;
  for (std::ptrdiff_t n; got < window.size() && (n = probe->read(window.data() + got, window.size() - got)) > 0;)
    got += static_cast<std::size_t>(n);
  window.resize(got);
  std::size_t at = window.find("<trkpt");
  while (at != std::string::npos && at + 6 < window.size() && window[at + 6] != ' ' && window[at + 6] != '>' &&
         window[at + 6] != '\n' && window[at + 6] != '\t' && window[at + 6] != '\r')
    at = window.find("<trkpt", at + 1);
  if (at == std::string::npos || at + 6 >= window.size()) return std::nullopt;
  const std::int64_t split = size / 2 + static_cast<std::int64_t>(at);

  auto first_part = source.range(0, split);
  auto second_part = source.range(split, size);
  if (!first_part || !second_part) return std::nullopt;

  const std::string& name = source.display_name();
  TrackFile second_file;
  WarningCollector second_warnings(name);
  GpxHandler second_handler(second_file, second_warnings);
  second_handler.continue_in_segment();
  XmlPartStart start;
  start.byte_offset = split;
  start.open_elements = {"gpx", "trk", "trkseg"};
  XmlParseOutcome second_outcome;
  const auto parse_second = [&] {
    second_outcome = XmlStream::parse_part(*second_part, second_handler, &start, nullptr);
  };
  // Without threads (the browser's build, where only tests ask for halves) one after the other.
  std::thread second_thread;
  if (geo::kThreadsAvailable) second_thread = std::thread(parse_second);

  ReadResult result;
  result.file.format = Format::Gpx;
  WarningCollector warnings(name);
  GpxHandler handler(result.file, warnings);
  XmlEndState end;
  const XmlParseOutcome first_outcome = XmlStream::parse_part(*first_part, handler, nullptr, &end);
  if (second_thread.joinable())
    second_thread.join();
  else
    parse_second();

  const bool joins = first_outcome.kind == XmlParseOutcome::Kind::Truncated && !end.inside_markup &&
                     end.open_elements == start.open_elements && handler.between_points();
  if (!joins) return std::nullopt;

  // The second half counted lines from its first byte: move them to where it starts.
  const SourcePosition at_split = end.end;
  auto shift = [at_split](SourcePosition p) {
    if (p.line <= 0) return p;
    if (p.line == 1) p.column += at_split.column - 1;
    p.line += at_split.line - 1;
    return p;
  };
  join_halves(result.file, second_file);
  warnings.merge(second_warnings, shift);
  second_outcome.position = shift(second_outcome.position);
  record_xml_outcome(second_outcome, handler.complete_points() + second_handler.complete_points(), result, warnings);
  finish_read(result, warnings, options);
  return result;
}

ReadResult read_gpx(ByteSource& source, const ReadOptions& options) {
  if (auto halves = read_gpx_in_halves(source, options)) return std::move(*halves);
  ReadResult result;
  result.file.format = Format::Gpx;
  WarningCollector warnings(source.display_name());
  GpxHandler handler(result.file, warnings);
  XmlParseOutcome outcome = XmlStream::parse(source, handler);
  record_xml_outcome(outcome, handler.complete_points(), result, warnings);
  finish_read(result, warnings, options);
  return result;
}

}  // namespace trailray::track
