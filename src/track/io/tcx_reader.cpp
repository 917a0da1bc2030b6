// Garmin Training Center (TCX v2, and v1's plain <HeartRateBpm>) reader: streaming and
// namespace-agnostic, like the GPX reader.
//
//   Activities/Activity  -> one Track: Sport -> Track.type (and metadata.activity_type of the
//                           first activity), Id -> metadata.time (first parseable one), Notes ->
//                           Track.description. Each Lap becomes one Segment in file order; the
//                           Track elements of a Lap (Garmin starts one after each pause) are
//                           appended to that lap's segment. Activities nested in a
//                           MultiSportSession are read the same way.
//   Courses/Course       -> one Track: Name -> Track.name, Notes -> Track.description. Each
//                           Track element becomes one Segment (the course Lap is a summary with
//                           no points). CoursePoints become Waypoints (Name, Time, Position,
//                           AltitudeMeters, PointType -> symbol, Notes -> description).
//   Trackpoint           -> Time, Position/LatitudeDegrees + LongitudeDegrees, AltitudeMeters,
//                           HeartRateBpm/Value, Cadence, and in Extensions (ns3:TPX, ax:TPX, ...)
//                           Speed (m/s), Watts and RunCadence (as recorded: Garmin writes strides
//                           per minute; only used when there is no <Cadence>).
//   Creator/Name         -> metadata.creator (the device); the file's Author/Name when no
//                           activity or course names a Creator.
//
// A Trackpoint without <Position> (pause markers, HR-only samples: Garmin writes them
// routinely) is skipped silently. A Trackpoint whose Position is incomplete, unparseable or out
// of range is dropped with a counted warning. Segments left empty (a lap without positioned
// points) are not kept. Folders and Workouts are ignored.

#include <cfloat>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"
#include "track/io/xml_stream.hpp"

namespace trailray::track {
namespace {

constexpr std::size_t kShown = 40;  // characters of a bad value quoted in a warning

std::string quoted(std::string_view text) { return "'" + std::string(trim(text).substr(0, kShown)) + "'"; }

// A Trackpoint or CoursePoint being read.
struct PointBuilder {
  TrackPoint point;
  Waypoint waypoint;  // CoursePoint only
  SourcePosition where;
  int depth = -1;           // element depth of the point; -1 when not inside one
  int position_depth = -1;  // <Position>
  int hr_depth = -1;        // <HeartRateBpm>
  int ext_depth = -1;       // <Extensions>
  bool has_position = false;
  bool hr_value_seen = false;
  std::optional<std::string> lat_text, lon_text;
  float run_cadence = kMissingF;

  void reset(int d, SourcePosition w) {
    *this = PointBuilder{};
    depth = d;
    where = w;
  }
};

class TcxHandler final : public XmlHandler {
 public:
  TcxHandler(TrackFile& file, WarningCollector& warnings) : file_(file), warnings_(warnings) {}

  std::size_t complete_points() const { return complete_points_; }
  std::size_t skipped_without_position() const { return skipped_without_position_; }

  // After parsing (also after a cut or an error): creator fallback, empty segments removed.
  void finish() {
    file_.metadata.creator = !creator_.empty() ? creator_ : author_;
    for (Track& t : file_.tracks) std::erase_if(t.segments, [](const Segment& s) { return s.points.empty(); });
  }

  void start_element(std::string_view name, const char** attrs) override {
    ++depth_;
    if (depth_ == 1) {
      if (name != "TrainingCenterDatabase")
        fail("root element is <" + std::string(name).substr(0, 80) +
             ">, expected <TrainingCenterDatabase>: not a TCX file");
      return;
    }
    if (tp_.depth > 0 || cp_.depth > 0) {
      point_start(tp_.depth > 0 ? tp_ : cp_, name);
      return;
    }
    if (creator_depth_ > 0 || author_depth_ > 0) return;  // read at their ends
    if (depth_ == 2) {
      if (name == "Activities")
        section_ = Section::Activities, section_depth_ = depth_;
      else if (name == "Courses")
        section_ = Section::Courses, section_depth_ = depth_;
      else if (name == "Author")
        author_depth_ = depth_;
      return;
    }
    if (owner_depth_ < 0) {
      // Activity directly in Activities, or inside MultiSportSession/FirstSport|NextSport.
      if (section_ == Section::Activities && name == "Activity") {
        begin_owner(Owner::Activity);
        const char* sport = xml_attribute(attrs, "Sport");
        if (sport) {
          file_.tracks.back().type = sport;
          if (file_.metadata.activity_type.empty()) file_.metadata.activity_type = sport;
        }
      } else if (section_ == Section::Courses && name == "Course" && depth_ == section_depth_ + 1) {
        begin_owner(Owner::Course);
      }
      return;
    }
    Track& track = file_.tracks.back();
    if (depth_ == owner_depth_ + 1) {
      if (name == "Lap" && owner_ == Owner::Activity) {
        lap_depth_ = depth_;
        track.segments.emplace_back();
      } else if (name == "Track") {
        // A course's Track, or (not in the schema) a Track straight in an Activity.
        track_depth_ = depth_;
        track.segments.emplace_back();
      } else if (name == "Creator") {
        creator_depth_ = depth_;
      } else if (name == "CoursePoint" && owner_ == Owner::Course) {
        cp_.reset(depth_, position());
      }
      return;
    }
    if (lap_depth_ > 0 && depth_ == lap_depth_ + 1 && name == "Track") {
      track_depth_ = depth_;  // appended to the lap's segment
    } else if (track_depth_ > 0 && depth_ == track_depth_ + 1 && name == "Trackpoint") {
      tp_.reset(depth_, position());
    }
  }

  void end_element(std::string_view name, std::string_view text) override {
    if (tp_.depth > 0) {
      if (depth_ == tp_.depth)
        end_trackpoint();
      else
        trackpoint_child(name, text);
    } else if (cp_.depth > 0) {
      if (depth_ == cp_.depth)
        end_course_point();
      else
        course_point_child(name, text);
    } else if (creator_depth_ > 0) {
      if (depth_ == creator_depth_ + 1 && name == "Name" && creator_.empty()) creator_ = std::string(trim(text));
    } else if (author_depth_ > 0) {
      if (depth_ == author_depth_ + 1 && name == "Name" && author_.empty()) author_ = std::string(trim(text));
    } else if (owner_depth_ > 0 && depth_ == owner_depth_ + 1) {
      Track& t = file_.tracks.back();
      if (name == "Id" && owner_ == Owner::Activity) {
        if (std::isnan(file_.metadata.time))
          if (auto v = parse_iso8601(trim(text))) file_.metadata.time = *v;
      } else if (name == "Name" && owner_ == Owner::Course) {
        t.name = std::string(trim(text));
      } else if (name == "Notes") {
        t.description = std::string(trim(text));
      }
    }
    if (depth_ == track_depth_) track_depth_ = -1;
    if (depth_ == lap_depth_) lap_depth_ = -1;
    if (depth_ == creator_depth_) creator_depth_ = -1;
    if (depth_ == author_depth_) author_depth_ = -1;
    if (depth_ == owner_depth_) owner_depth_ = track_depth_ = lap_depth_ = -1;
    if (depth_ == section_depth_) section_depth_ = -1, section_ = Section::None;
    --depth_;
  }

 private:
  enum class Section { None, Activities, Courses };
  enum class Owner { Activity, Course };

  void begin_owner(Owner o) {
    owner_ = o;
    owner_depth_ = depth_;
    file_.tracks.emplace_back();
  }

  // Children of a point are read at their end; starts only note where the containers are.
  void point_start(PointBuilder& b, std::string_view name) {
    if (depth_ != b.depth + 1) return;
    if (name == "Position") {
      b.position_depth = depth_;
      b.has_position = true;
    } else if (name == "HeartRateBpm") {
      b.hr_depth = depth_;
    } else if (name == "Extensions") {
      b.ext_depth = depth_;
    }
  }

  // Shared by Trackpoint and CoursePoint: Time, Position/*, AltitudeMeters.
  bool common_child(PointBuilder& b, std::string_view name, std::string_view text) {
    if (depth_ == b.depth + 1) {
      if (name == "Time") {
        std::string_view t = trim(text);
        if (t.empty()) return true;
        if (auto v = parse_iso8601(t))
          b.point.time = *v;
        else
          warnings_.add("time", position(), "unreadable <Time> " + quoted(t) + " ignored");
        return true;
      }
      if (name == "AltitudeMeters") {
        set_number(b.point.ele, text, name);
        return true;
      }
      return false;
    }
    if (b.position_depth > 0 && depth_ == b.position_depth + 1) {
      if (name == "LatitudeDegrees")
        b.lat_text = std::string(trim(text));
      else if (name == "LongitudeDegrees")
        b.lon_text = std::string(trim(text));
      return true;
    }
    return false;
  }

  void trackpoint_child(std::string_view name, std::string_view text) {
    PointBuilder& b = tp_;
    if (common_child(b, name, text)) {
      // done
    } else if (depth_ == b.depth + 1) {
      if (name == "Cadence") {
        set_channel(b.point.cadence, text, name);
      } else if (name == "HeartRateBpm" && !b.hr_value_seen) {
        set_channel(b.point.heart_rate, text, name);  // TCX v1: the value itself
      }
    } else if (b.hr_depth > 0 && depth_ == b.hr_depth + 1 && name == "Value") {
      b.hr_value_seen = true;
      set_channel(b.point.heart_rate, text, "HeartRateBpm/Value");
    } else if (b.ext_depth > 0 && depth_ > b.ext_depth) {
      if (name == "Speed")
        set_channel(b.point.speed, text, name);
      else if (name == "Watts")
        set_channel(b.point.power, text, name);
      else if (name == "RunCadence")
        set_channel(b.run_cadence, text, name);
    }
    if (depth_ == b.position_depth) b.position_depth = -1;
    if (depth_ == b.hr_depth) b.hr_depth = -1;
    if (depth_ == b.ext_depth) b.ext_depth = -1;
  }

  void course_point_child(std::string_view name, std::string_view text) {
    PointBuilder& b = cp_;
    if (!common_child(b, name, text) && depth_ == b.depth + 1) {
      if (name == "Name")
        b.waypoint.name = std::string(trim(text));
      else if (name == "PointType")
        b.waypoint.symbol = std::string(trim(text));
      else if (name == "Notes")
        b.waypoint.description = std::string(trim(text));
    }
    if (depth_ == b.position_depth) b.position_depth = -1;
  }

  // Fills lat/lon; false (with a counted warning under `kind`) when they are not usable.
  bool resolve_coordinates(PointBuilder& b, const std::string& kind, const char* what) {
    auto la = b.lat_text ? parse_double(*b.lat_text) : std::nullopt;
    auto lo = b.lon_text ? parse_double(*b.lon_text) : std::nullopt;
    if (la && lo && valid_coordinates(*la, *lo)) {
      b.point.lat = *la;
      b.point.lon = *lo;
      return true;
    }
    auto show = [](const std::optional<std::string>& s) {
      return s ? "\"" + s->substr(0, kShown) + "\"" : std::string("<missing>");
    };
    warnings_.add(kind, b.where,
                  std::string(what) + " with invalid coordinates dropped (LatitudeDegrees=" + show(b.lat_text) +
                      " LongitudeDegrees=" + show(b.lon_text) + ")");
    return false;
  }

  void end_trackpoint() {
    PointBuilder& b = tp_;
    b.depth = -1;
    if (!b.has_position) {
      ++skipped_without_position_;  // pause marker or sensor-only sample: routine, not a warning
      return;
    }
    if (!resolve_coordinates(b, "coords", "trackpoint")) return;
    if (std::isnan(b.point.cadence)) b.point.cadence = b.run_cadence;
    Track& t = file_.tracks.back();
    if (t.segments.empty()) t.segments.emplace_back();  // defensive: Track always opens or has one
    t.segments.back().points.push_back(b.point);
    ++complete_points_;
  }

  void end_course_point() {
    PointBuilder& b = cp_;
    b.depth = -1;
    if (!resolve_coordinates(b, "coursepoint-coords", "course point")) return;
    b.waypoint.point = b.point;
    file_.waypoints.push_back(std::move(b.waypoint));
    ++complete_points_;
  }

  void set_number(double& out, std::string_view text, std::string_view what) {
    std::string_view t = trim(text);
    if (t.empty()) return;  // <AltitudeMeters/>: absent
    if (auto v = parse_double(t))
      out = *v;
    else
      warnings_.add(std::string(what), position(), "unreadable <" + std::string(what) + "> " + quoted(t) + " ignored");
  }

  void set_channel(float& out, std::string_view text, std::string_view what) {
    double v = kMissing;
    set_number(v, text, what);
    if (std::isnan(v)) return;
    if (std::fabs(v) > static_cast<double>(FLT_MAX)) {  // a float cast would be undefined
      warnings_.add(std::string(what), position(),
                    "out-of-range <" + std::string(what) + "> " + quoted(text) + " ignored");
      return;
    }
    out = static_cast<float>(v);
  }

  TrackFile& file_;
  WarningCollector& warnings_;
  int depth_ = 0;
  Section section_ = Section::None;
  int section_depth_ = -1;
  Owner owner_ = Owner::Activity;
  int owner_depth_ = -1, lap_depth_ = -1, track_depth_ = -1, creator_depth_ = -1, author_depth_ = -1;
  PointBuilder tp_, cp_;
  std::string creator_, author_;
  std::size_t complete_points_ = 0;
  std::size_t skipped_without_position_ = 0;
};

}  // namespace

ReadResult read_tcx(ByteSource& source, const ReadOptions& options) {
  ReadResult result;
  result.file.format = Format::Tcx;
  WarningCollector warnings(source.display_name());
  TcxHandler handler(result.file, warnings);
  XmlParseOutcome outcome = XmlStream::parse(source, handler);
  handler.finish();
  record_xml_outcome(outcome, handler.complete_points(), result, warnings);
  finish_read(result, warnings, options);
  return result;
}

}  // namespace trailray::track
