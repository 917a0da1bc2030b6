// KML 2.1 / 2.2 / 2.3 reader: streaming and namespace-agnostic (default, prefixed such as
// "ns3:kml", or gx: extensions read alike; the scanner hands out local names).
//
//   Placemark            -> its geometries, with the placemark's name and description:
//     LineString         -> a segment of one Track (coordinates "lon,lat[,alt]", no times)
//     gx:Track           -> a segment with times and recorded channels (kml_gx_track.hpp)
//     gx:MultiTrack      -> a segment per gx:Track (its altitudeMode applies to those without one)
//     MultiGeometry      -> the geometries inside it, so one Track holds all the placemark's lines
//     Point              -> a Waypoint; the placemark's TimeStamp/when is its time
//     Polygon            -> an area, not a way travelled: skipped with a counted warning (as
//                           the GeoJSON reader does; gpsbabel reads its ring as a track)
//     Model, overlays    -> pictures, not tracks; ignored.
//   ExtendedData/Data name="type" of a placemark (Google My Tracks' activity) -> Track.type.
//   The first Document or Folder under <kml>: name and description -> the file's metadata.
//   Folders and Documents nest freely; NetworkLinks are not followed (a warning says so).
//
// altitudeMode (or gx:altitudeMode) decides what the altitudes mean; see apply_altitude_mode.
// Positions that are unreadable or out of range are dropped with a counted warning.

#include "track/io/kml_document.hpp"

#include <optional>
#include <string>
#include <vector>

#include "track/io/kml_coordinates.hpp"
#include "track/io/kml_gx_track.hpp"
#include "track/io/kml_values.hpp"
#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"

namespace trailray::track {
namespace {

constexpr std::size_t kShown = 40;  // characters of a bad value quoted in a warning

std::string quoted(std::string_view text) { return "'" + std::string(trim(text).substr(0, kShown)) + "'"; }

enum class Tag : unsigned char {
  Other,
  Kml,
  Document,
  Folder,
  Placemark,
  Name,
  Description,
  TimeStamp,
  When,
  Point,
  LineString,
  Track,  // gx:Track (KML 2.3: Track)
  MultiTrack,
  Coord,  // gx:coord
  Coordinates,
  AltitudeMode,
  SimpleArrayData,
  Value,  // gx:SimpleArrayData/gx:value and ExtendedData/Data/value
  Data,
  NetworkLink,
  Polygon
};

Tag tag_of(std::string_view n) {
  static constexpr std::pair<std::string_view, Tag> kTags[] = {
      {"kml", Tag::Kml},
      {"Document", Tag::Document},
      {"Folder", Tag::Folder},
      {"Placemark", Tag::Placemark},
      {"name", Tag::Name},
      {"description", Tag::Description},
      {"TimeStamp", Tag::TimeStamp},
      {"when", Tag::When},
      {"Point", Tag::Point},
      {"LineString", Tag::LineString},
      {"Track", Tag::Track},
      {"MultiTrack", Tag::MultiTrack},
      {"coord", Tag::Coord},
      {"coordinates", Tag::Coordinates},
      {"altitudeMode", Tag::AltitudeMode},
      {"SimpleArrayData", Tag::SimpleArrayData},
      {"value", Tag::Value},
      {"Data", Tag::Data},
      {"NetworkLink", Tag::NetworkLink},
      {"Polygon", Tag::Polygon},
  };
  for (const auto& [name, tag] : kTags)
    if (name == n) return tag;
  return Tag::Other;
}

// A geometry of the placemark being read, kept until the placemark ends: its altitudeMode may
// come after its coordinates, or from the gx:MultiTrack around it.
struct Piece {
  Tag kind = Tag::LineString;  // LineString, Track or Point
  std::vector<TrackPoint> points;
  std::optional<AltitudeMode> mode;
  SourcePosition mode_where;
};

struct PlacemarkState {
  int depth = -1;  // -1: not inside a placemark
  std::string name, description, type;
  double time = kMissing;
  std::vector<Piece> pieces;
};

class KmlHandler final : public XmlHandler {
 public:
  KmlHandler(TrackFile& file, WarningCollector& warnings)
      : file_(file),
        warnings_(warnings),
        on_tuple_([this](const KmlTuple& t, const SourcePosition& p) { add(t, p); }) {}

  std::size_t complete_points() const { return complete_points_; }

  // After a cut: what was complete before it is kept (a gx:Track's points so far, the tuples
  // before the last one of a cut <coordinates>, the placemark they belong to).
  void finish() {
    if (in_coordinates_) coordinates_.finish_cut(on_tuple_);
    in_coordinates_ = false;
    if (piece_) end_piece(false);
    if (multitrack_depth_ > 0) end_multitrack();
    if (placemark_.depth > 0) end_placemark();
  }

  void start_element(std::string_view name, const char** attrs) override {
    const Tag tag = tag_of(name);
    if (stack_.empty() && tag != Tag::Kml) {
      fail("root element is <" + std::string(name).substr(0, 80) + ">, expected <kml>: not a KML file");
      return;
    }
    stack_.push_back(tag);
    const int depth = static_cast<int>(stack_.size());
    switch (tag) {
      case Tag::Placemark:
        if (placemark_.depth < 0) placemark_.depth = depth;
        break;
      case Tag::Point:
      case Tag::LineString:
      case Tag::Track:
        if (placemark_.depth > 0 && !piece_) {
          piece_.emplace().kind = tag;
          piece_depth_ = depth;
          if (tag == Tag::Track) gx_ = GxTrackParts{position(), {}, {}, {}};
        }
        break;
      case Tag::MultiTrack:
        if (placemark_.depth > 0 && !piece_ && multitrack_depth_ < 0) {
          multitrack_depth_ = depth;
          multitrack_first_ = placemark_.pieces.size();
          multitrack_mode_.reset();
        }
        break;
      case Tag::Coordinates:
        if (piece_ && piece_->kind != Tag::Track && depth == piece_depth_ + 1 && !in_coordinates_) {
          in_coordinates_ = true;
          coordinates_.begin(position());
          stream_text();  // a long track's coordinates may be far longer than the scanner's values
        }
        break;
      case Tag::SimpleArrayData:
        array_index_ = -1;
        if (in_gx_track()) {
          const char* array_name = xml_attribute(attrs, "name");
          ArrayChannel channel = array_name ? array_channel(array_name) : ArrayChannel::None;
          if (channel != ArrayChannel::None) {
            gx_.arrays.emplace_back(channel, std::vector<double>{});
            array_index_ = static_cast<int>(gx_.arrays.size()) - 1;
          }
        }
        break;
      case Tag::Data: {
        const char* data_name = xml_attribute(attrs, "name");
        data_is_type_ = placemark_.depth > 0 && data_name && std::string_view(data_name) == "type";
        break;
      }
      case Tag::NetworkLink:
        warnings_.add("networklink", position(), "<NetworkLink> not followed: the files it links to are not read");
        break;
      case Tag::Polygon:
        warnings_.add("polygon", position(), "a <Polygon> skipped (lines and points are read; areas are not)");
        break;
      default:
        break;
    }
  }

  void text_piece(std::string_view piece) override {
    if (in_coordinates_) coordinates_.feed(piece, on_tuple_);
  }

  void end_element(std::string_view /*name*/, std::string_view text) override {
    const Tag tag = stack_.back();
    const int depth = static_cast<int>(stack_.size());
    const Tag parent = depth >= 2 ? stack_[depth - 2] : Tag::Other;
    const Tag grandparent = depth >= 3 ? stack_[depth - 3] : Tag::Other;
    switch (tag) {
      case Tag::Name:
      case Tag::Description:
        container_text(tag, parent, depth, text);
        break;
      case Tag::When:
        if (in_gx_track() && depth == piece_depth_ + 1)
          gx_.times.push_back(read_time(text));
        else if (parent == Tag::TimeStamp && grandparent == Tag::Placemark && depth == placemark_.depth + 2)
          placemark_.time = read_time(text);
        break;
      case Tag::Coord:
        if (in_gx_track() && depth == piece_depth_ + 1) read_gx_coord(text);
        break;
      case Tag::Coordinates:
        if (in_coordinates_ && depth == piece_depth_ + 1) {
          coordinates_.finish(on_tuple_);
          in_coordinates_ = false;
        }
        break;
      case Tag::AltitudeMode:
        if (piece_ && depth == piece_depth_ + 1)
          read_altitude_mode(text, piece_->mode, piece_->mode_where);
        else if (!piece_ && depth == multitrack_depth_ + 1)
          read_altitude_mode(text, multitrack_mode_, multitrack_mode_where_);
        break;
      case Tag::Value:
        if (parent == Tag::SimpleArrayData && array_index_ >= 0)
          read_array_value(text);
        else if (parent == Tag::Data && data_is_type_ && placemark_.type.empty())
          placemark_.type = std::string(trim(text));
        break;
      case Tag::SimpleArrayData:
        array_index_ = -1;
        break;
      case Tag::Data:
        data_is_type_ = false;
        break;
      case Tag::Point:
      case Tag::LineString:
      case Tag::Track:
        if (depth == piece_depth_) end_piece(true);
        break;
      case Tag::MultiTrack:
        if (depth == multitrack_depth_) end_multitrack();
        break;
      case Tag::Placemark:
        if (depth == placemark_.depth) end_placemark();
        break;
      default:
        break;
    }
    stack_.pop_back();
  }

 private:
  bool in_gx_track() const { return piece_ && piece_->kind == Tag::Track; }

  // A placemark's name and description; those of the Document or Folder under <kml> are the
  // file's.
  void container_text(Tag tag, Tag parent, int depth, std::string_view text) {
    if (parent == Tag::Placemark && depth == placemark_.depth + 1) {
      (tag == Tag::Name ? placemark_.name : placemark_.description) = std::string(trim(text));
    } else if ((parent == Tag::Document || parent == Tag::Folder) && depth == 3) {
      std::string& field = tag == Tag::Name ? file_.metadata.name : file_.metadata.description;
      if (field.empty()) field = std::string(trim(text));
    }
  }

  double read_time(std::string_view text) {
    std::string_view t = trim(text);
    if (t.empty()) return kMissing;
    if (auto v = parse_iso8601(t)) return *v;
    warnings_.add("when", position(), "unreadable <when> " + quoted(t) + " ignored");
    return kMissing;
  }

  void read_gx_coord(std::string_view text) {
    auto c = parse_gx_coord(text);
    if (c && !valid_coordinates(c->lat, c->lon)) c.reset();
    if (!c)
      warnings_.add("coords", position(), "point with invalid coordinates dropped (gx:coord " + quoted(text) + ")");
    gx_.coords.push_back(c);
  }

  // One tuple of the <coordinates> being read.
  void add(const KmlTuple& t, const SourcePosition& where) {
    if (!t.value || !valid_coordinates(t.value->lat, t.value->lon)) {
      warnings_.add("coords", where, "point with invalid coordinates dropped (" + quoted(t.text) + ")");
      return;
    }
    if (piece_->kind == Tag::Point && !piece_->points.empty()) return;  // a Point has one position
    TrackPoint p;
    p.lon = t.value->lon;
    p.lat = t.value->lat;
    p.ele = t.value->alt;
    piece_->points.push_back(p);
  }

  void read_altitude_mode(std::string_view text, std::optional<AltitudeMode>& mode, SourcePosition& where) {
    where = position();
    mode = parse_altitude_mode(text);
    if (!mode)
      warnings_.add("altitude-mode", where,
                    "unknown altitudeMode " + quoted(text) + ": clampToGround (KML's default) assumed");
  }

  void read_array_value(std::string_view text) {
    double v = kMissing;
    std::string_view t = trim(text);
    if (!t.empty()) {
      if (auto parsed = parse_double(t))
        v = *parsed;
      else
        warnings_.add("gx:value", position(), "unreadable <gx:value> " + quoted(t) + " ignored");
    }
    gx_.arrays[static_cast<std::size_t>(array_index_)].second.push_back(v);
  }

  void end_piece(bool complete) {
    if (piece_->kind == Tag::Track) piece_->points = gx_.assemble(warnings_, complete);
    placemark_.pieces.push_back(std::move(*piece_));
    piece_.reset();
    piece_depth_ = -1;
    array_index_ = -1;
  }

  void end_multitrack() {
    for (std::size_t i = multitrack_first_; i < placemark_.pieces.size(); ++i) {
      Piece& piece = placemark_.pieces[i];
      if (!piece.mode && multitrack_mode_) {
        piece.mode = multitrack_mode_;
        piece.mode_where = multitrack_mode_where_;
      }
    }
    multitrack_depth_ = -1;
    multitrack_mode_.reset();
  }

  // What the altitudes mean. KML's default (no altitudeMode) is clampToGround, which the spec
  // says ignores the altitudes: the geometry lies on the terrain. That is followed here even
  // though many writers (Google My Tracks, cameras, exporters) put real GPS altitudes in files
  // without an altitudeMode, and those files then have no elevation (no elevation gain in
  // `stats`): a viewer that honoured them would draw what Google Earth does not, and a
  // clamped file often carries 0 as its altitude (furkot's stops do). The points get no
  // elevation, so the scene puts them on its terrain; clampToSeaFloor, which on land is the
  // ground, the same.
  //
  // relativeToGround (and relativeToSeaFloor, which is the same on land) gives heights above
  // the terrain, which this layer has none of. Read as heights above the sea they would be
  // wrong by the ground's height (hundreds to thousands of metres where flights happen: the
  // track would run inside the mountain), so they are dropped with a warning and the points
  // are placed on the terrain too. Only absolute keeps the altitudes.
  void apply_altitude_mode(Piece& piece) {
    const AltitudeMode mode = piece.mode.value_or(AltitudeMode::ClampToGround);
    if (mode == AltitudeMode::Absolute) return;
    bool had_altitude = false;
    for (TrackPoint& p : piece.points) {
      had_altitude = had_altitude || p.has_ele();
      p.ele = kMissing;
    }
    if (had_altitude && (mode == AltitudeMode::RelativeToGround || mode == AltitudeMode::RelativeToSeaFloor))
      warnings_.add("altitude-relative", piece.mode_where,
                    "altitudeMode relative to the ground: heights above the terrain cannot be placed without it, "
                    "so they are not used and the points lie on the terrain");
  }

  void end_placemark() {
    Track track;
    track.name = placemark_.name;
    track.description = placemark_.description;
    track.type = placemark_.type;
    for (Piece& piece : placemark_.pieces) {
      apply_altitude_mode(piece);
      if (piece.kind == Tag::Point) {
        for (const TrackPoint& p : piece.points) {
          Waypoint w;
          w.point = p;
          w.point.time = placemark_.time;
          w.name = placemark_.name;
          w.description = placemark_.description;
          file_.waypoints.push_back(std::move(w));
          ++complete_points_;
        }
      } else if (!piece.points.empty()) {
        complete_points_ += piece.points.size();
        track.segments.push_back(Segment{std::move(piece.points)});
      }
    }
    if (!track.segments.empty()) file_.tracks.push_back(std::move(track));
    placemark_ = PlacemarkState{};
  }

  TrackFile& file_;
  WarningCollector& warnings_;
  std::vector<Tag> stack_;  // the open elements, outermost first
  PlacemarkState placemark_;
  std::optional<Piece> piece_;
  int piece_depth_ = -1;
  GxTrackParts gx_;
  int array_index_ = -1;  // the gx:SimpleArrayData being read, in gx_.arrays
  int multitrack_depth_ = -1;
  std::size_t multitrack_first_ = 0;  // its first piece in placemark_.pieces
  std::optional<AltitudeMode> multitrack_mode_;
  SourcePosition multitrack_mode_where_;
  CoordinatesStream coordinates_;
  bool in_coordinates_ = false;
  CoordinatesStream::TupleHandler on_tuple_;
  bool data_is_type_ = false;
  std::size_t complete_points_ = 0;
};

}  // namespace

KmlDocumentRead read_kml_document(ByteSource& source, TrackFile& file, WarningCollector& warnings) {
  KmlHandler handler(file, warnings);
  KmlDocumentRead read;
  read.outcome = XmlStream::parse(source, handler);
  handler.finish();
  read.complete_points = handler.complete_points();
  return read;
}

}  // namespace trailray::track
