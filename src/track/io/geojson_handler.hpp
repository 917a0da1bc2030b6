#pragma once
// The GeoJSON reader's SAX handler (geojson_reader.cpp has the conventions): follows where in
// the document each value is (a frame per open object or array that matters, with its key or
// index for JSON paths), collects Features and geometries (geojson_parts.hpp), and hands each
// finished Feature to add_geojson_feature. Only geojson_reader.cpp includes it.

#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "track/io/geojson_parts.hpp"
#include "track/io/json_source.hpp"
#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"

namespace trailray::track::geojson {

using json = nlohmann::json;

enum class Role { Object, Features, Geometries, Coordinates, Properties, CoordProps, Series, Skip };
enum class Slot { Root, Feature, Geometry, Member };

constexpr int kMaxCoordinateLevel = 4;  // MultiPolygon: coordinates -> polygons -> rings -> positions
constexpr std::size_t kMaxFrames = 64;  // GeometryCollections nested deeper are skipped

struct Frame {
  Role role = Role::Skip;
  bool is_array = false;
  std::string key;                   // object frames: the current key
  std::size_t index = 0;             // array frames: elements begun so far
  GeoObject* object = nullptr;       // the object this frame belongs to
  std::unique_ptr<GeoObject> owned;  // Object frames own it until they end
  Slot slot = Slot::Root;
  GeoProperties* props = nullptr;
  GeoSeries* series = nullptr;
  GeoChannel channel = GeoChannel::Time;
  int level = 0;       // Coordinates / Series: 1 = the array under the key
  int skip_depth = 0;  // Skip: containers opened inside it
  // Coordinates: the numbers of the position being read, and what the array held.
  int numbers = 0;
  double value[3] = {0, 0, 0};
  bool not_number = false, has_arrays = false, had_position_child = false;
};

inline std::optional<GeoChannel> property_series(const std::string& k) {
  if (k == "coordTimes") return GeoChannel::Time;
  if (k == "heartRates") return GeoChannel::Heart;
  if (k == "cadences") return GeoChannel::Cadence;
  if (k == "watts") return GeoChannel::Power;
  if (k == "speeds") return GeoChannel::Speed;
  return std::nullopt;
}

inline std::optional<GeoChannel> coordinate_property_series(const std::string& k) {
  if (k == "times") return GeoChannel::Time;
  if (k == "heart" || k == "heartRates" || k == "hr") return GeoChannel::Heart;
  if (k == "cads" || k == "cadences" || k == "cadence") return GeoChannel::Cadence;
  if (k == "powers" || k == "power" || k == "watts") return GeoChannel::Power;
  if (k == "atemps" || k == "temperatures" || k == "temperature") return GeoChannel::Temperature;
  if (k == "speeds" || k == "speed") return GeoChannel::Speed;
  return std::nullopt;
}

class GeoJsonHandler {
 public:
  GeoJsonHandler(JsonSourceBuffer& input, TrackFile& file, WarningCollector& warnings)
      : in_(input), file_(file), warnings_(warnings) {}

  // --- nlohmann SAX interface ---
  bool null() { return scalar(Scalar::Null, 0.0, nullptr); }
  bool boolean(bool) { return scalar(Scalar::Other, 0.0, nullptr); }
  bool number_integer(json::number_integer_t v) { return scalar(Scalar::Number, static_cast<double>(v), nullptr); }
  bool number_unsigned(json::number_unsigned_t v) { return scalar(Scalar::Number, static_cast<double>(v), nullptr); }
  bool number_float(json::number_float_t v, const json::string_t&) { return scalar(Scalar::Number, v, nullptr); }
  bool string(json::string_t& s) { return scalar(Scalar::String, 0.0, &s); }
  bool binary(json::binary_t&) { return scalar(Scalar::Other, 0.0, nullptr); }
  bool key(json::string_t& k) {
    if (!frames_.empty() && frames_.back().role != Role::Skip) frames_.back().key = k;
    return true;
  }
  bool start_object(std::size_t) { return open(false); }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(true); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    error_offset_ = static_cast<std::int64_t>(position) - 1;
    syntax_error_ = ex.what();
    return false;
  }

  // After the parser stopped at the end of the input: the open features are kept as read.
  void close_after_cut() {
    cut_ = true;
    while (!frames_.empty()) close();
  }

  std::int64_t error_offset() const { return error_offset_; }
  const std::string& syntax_error() const { return syntax_error_; }
  const std::string& abort_message() const { return abort_message_; }
  std::unique_ptr<GeoObject>& root() { return root_; }
  bool cut() const { return cut_; }

 private:
  enum class Scalar { Null, Number, String, Other };

  // The JSON path of the value being read ("features[3].geometry.coordinates[17]").
  std::string path(std::size_t frames) const {
    std::string p;
    for (std::size_t i = 0; i < frames && i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.is_array)
        p += "[" + std::to_string(f.index == 0 ? 0 : f.index - 1) + "]";
      else if (f.role != Role::Skip || f.skip_depth == 0)
        p += (p.empty() ? "" : ".") + f.key;
    }
    return p;
  }
  std::string path() const { return path(frames_.size()); }

  // A warning of `kind`; the position (and the message) are worked out for the first one only.
  template <typename Message>
  void warn(const std::string& kind, Message message) {
    if (seen_.insert(kind).second)
      warnings_.add(kind, in_.here(), message());
    else
      warnings_.add(kind, {}, {});
  }

  // Every value starts here: the parent array counts it.
  void begin_value() {
    if (!frames_.empty() && frames_.back().is_array && frames_.back().role != Role::Skip) ++frames_.back().index;
  }

  bool scalar(Scalar kind, double number, json::string_t* text) {
    begin_value();
    if (frames_.empty()) return abort("not GeoJSON: the top-level value is not an object");
    Frame& f = frames_.back();
    switch (f.role) {
      case Role::Object:
        if (f.key == "type" && text) f.object->type = *text;
        if (f.slot == Slot::Root && text) root_text(f.key, *text);
        break;
      case Role::Properties:
        if (text) property_text(f, *text);
        break;
      case Role::Coordinates:
        if (kind == Scalar::Number) {
          if (f.numbers < 3) f.value[f.numbers] = number;
          ++f.numbers;
        } else {
          f.not_number = true;
        }
        break;
      case Role::Series:
        series_value(f, kind, number, text);
        break;
      default:
        break;
    }
    return true;
  }

  // A FeatureCollection's own name, description and time (foreign members; our writer's).
  void root_text(const std::string& k, const std::string& text) {
    Metadata& m = file_.metadata;
    if (k == "name")
      m.name = text;
    else if (k == "description")
      m.description = text;
    else if (k == "time")
      if (auto t = parse_iso8601(text)) m.time = *t;
  }

  void property_text(const Frame& f, const std::string& text) {
    GeoProperties& p = *f.props;
    const std::string& k = f.key;
    if (k == "name")
      p.name = text;
    else if (k == "desc" || (k == "description" && p.description.empty()))
      p.description = text;
    else if (k == "sym")
      p.symbol = text;
    else if (k == "type")
      p.type = text;
    else if (k == "_gpxType")
      p.gpx_type = text;
    else if (k == "time" || (k == "timestamp" && p.time.empty()))
      p.time = text;
  }

  void series_value(Frame& f, Scalar kind, double number, const json::string_t* text) {
    double v = kMissing;
    if (f.channel == GeoChannel::Time) {
      if (text) {
        if (auto t = parse_iso8601(*text))
          v = *t;
        else
          warn("geojson-time", [&] { return path() + ": unreadable time '" + text->substr(0, 40) + "' ignored"; });
      } else if (kind == Scalar::Number) {
        warn("geojson-time", [&] { return path() + ": a time that is a number (not ISO 8601) ignored"; });
      }
    } else if (kind == Scalar::Number) {
      v = number;
    } else if (text) {
      if (auto d = parse_double(*text)) v = *d;
    }
    f.series->values.push_back(v);
  }

  bool open(bool is_array) {
    begin_value();
    if (frames_.empty()) {
      if (is_array) return abort("not GeoJSON: the top-level value is an array, not an object");
      push_object(Slot::Root);
      return true;
    }
    Frame& parent = frames_.back();
    if (parent.role == Role::Skip) {
      ++parent.skip_depth;
      return true;
    }
    if (frames_.size() >= kMaxFrames) {
      warn("geojson-deep", [&] { return path() + ": nested too deep; skipped"; });
      return push_skip(is_array);
    }
    const std::string& k = parent.key;
    switch (parent.role) {
      case Role::Object:
        if (!is_array && k == "geometry" && (parent.slot == Slot::Root || parent.slot == Slot::Feature))
          push_object(Slot::Geometry);
        else if (!is_array && k == "properties" && (parent.slot == Slot::Root || parent.slot == Slot::Feature))
          push_properties(Role::Properties);
        else if (is_array && k == "features" && parent.slot == Slot::Root)
          push_array(Role::Features)->object->has_features = true;
        else if (is_array && k == "geometries")
          push_array(Role::Geometries);
        else if (is_array && k == "coordinates")
          push_coordinates(1)->object->has_coordinates = true;
        else
          push_skip(is_array);
        return true;
      case Role::Features:
      case Role::Geometries:
        if (is_array) {
          warn("geojson-not-object", [&] { return path() + ": an array where a GeoJSON object belongs; skipped"; });
          return push_skip(true);
        }
        push_object(parent.role == Role::Features ? Slot::Feature : Slot::Member);
        return true;
      case Role::Properties:
        if (!is_array && k == "coordinateProperties") return push_properties(Role::CoordProps), true;
        if (auto c = is_array ? property_series(k) : std::nullopt) return push_series(*c, 1), true;
        return push_skip(is_array);
      case Role::CoordProps:
        if (auto c = is_array ? coordinate_property_series(k) : std::nullopt) return push_series(*c, 1), true;
        return push_skip(is_array);
      case Role::Coordinates:
        if (!is_array || parent.level >= kMaxCoordinateLevel) {
          parent.not_number = true;
          return push_skip(is_array);
        }
        parent.has_arrays = true;
        push_coordinates(parent.level + 1);
        return true;
      case Role::Series:
        if (is_array && parent.level == 1) {
          parent.series->nested = true;
          push_series(parent.channel, 2);
          return true;
        }
        parent.series->values.push_back(kMissing);  // an object or a deeper array: no value
        return push_skip(is_array);
      case Role::Skip:
        break;
    }
    return push_skip(is_array);
  }

  Frame& push(Role role, bool is_array) {
    Frame f;
    f.role = role;
    f.is_array = is_array;
    if (!frames_.empty()) {
      f.object = frames_.back().object;
      f.props = frames_.back().props;
    }
    frames_.push_back(std::move(f));
    return frames_.back();
  }
  bool push_skip(bool is_array) { return push(Role::Skip, is_array), true; }
  Frame* push_array(Role role) { return &push(role, true); }
  void push_object(Slot slot) {
    auto object = std::make_unique<GeoObject>();
    object->path = path();
    object->where = in_.here();
    Frame& f = push(Role::Object, false);
    f.slot = slot;
    f.object = object.get();
    f.props = nullptr;
    f.owned = std::move(object);
  }
  void push_properties(Role role) {
    GeoObject* owner = frames_.back().object;
    if (role == Role::Properties && !owner->properties) owner->properties = std::make_unique<GeoProperties>();
    Frame& f = push(role, false);
    f.props = owner->properties.get();
  }
  void push_series(GeoChannel c, int level) {
    GeoSeries& s = frames_.back().props->of(c);
    if (level == 1) {
      s = GeoSeries{};
      s.present = true;
      s.path = path();
      s.where = in_.here();
    }
    Frame& f = push(Role::Series, true);
    f.series = &s;
    f.channel = c;
    f.level = level;
  }
  Frame* push_coordinates(int level) {
    Frame& f = push(Role::Coordinates, true);
    f.level = level;
    return &f;
  }

  bool close() {
    if (frames_.empty()) return true;
    Frame& f = frames_.back();
    if (f.role == Role::Skip && f.skip_depth > 0 && !cut_) {
      --f.skip_depth;
      return true;
    }
    if (f.role == Role::Coordinates) end_coordinates(f);
    if (f.role == Role::Series && f.level == 2) f.series->part_ends.push_back(f.series->values.size());
    if (f.role != Role::Object) {
      frames_.pop_back();
      return true;
    }
    std::unique_ptr<GeoObject> object = std::move(f.owned);
    const Slot slot = f.slot;
    frames_.pop_back();
    GeoObject* parent = frames_.empty() ? nullptr : frames_.back().object;
    switch (slot) {
      case Slot::Root:
        root_ = std::move(object);
        break;
      case Slot::Feature:
        add_geojson_feature(*object, cut_, file_, warnings_);
        break;
      case Slot::Geometry:
        if (parent) parent->geometry = std::move(object);
        break;
      case Slot::Member:
        if (parent) parent->geometries.push_back(std::move(object));
        break;
    }
    return true;
  }

  void end_coordinates(Frame& f) {
    GeoObject& g = *f.object;
    Frame* parent = frames_.size() >= 2 && frames_[frames_.size() - 2].role == Role::Coordinates
                        ? &frames_[frames_.size() - 2]
                        : nullptr;
    if (f.has_arrays) {
      if (f.numbers > 0 || f.not_number) g.mixed_levels = true;
      if (f.had_position_child) g.part_ends.push_back(g.points.size()), g.part_levels.push_back(f.level);
      return;
    }
    if (f.numbers == 0 && !f.not_number) {  // []: an empty line (or ring)
      g.part_ends.push_back(g.points.size()), g.part_levels.push_back(f.level);
      return;
    }
    if (cut_) return;  // a position cut short is not one
    TrackPoint p;
    if (f.not_number || f.numbers < 2) {
      p.lat = kMissing;
      const bool text = f.not_number;
      warn(text ? "geojson-coord-type" : "geojson-coord-short", [&] {
        return path(frames_.size() - 1) +
               (text ? ": a coordinate that is not a number" : ": a position with fewer than 2 numbers") +
               "; point dropped";
      });
    } else {
      p.lon = f.value[0];
      p.lat = f.value[1];
      if (f.numbers >= 3 && std::isfinite(f.value[2])) p.ele = f.value[2];  // 1e400 reads as infinity
      if (!valid_coordinates(p.lat, p.lon)) {
        warn("geojson-coord-range", [&] {
          return path(frames_.size() - 1) + ": a position out of range (lon " + std::to_string(f.value[0]) + ", lat " +
                 std::to_string(f.value[1]) + "); point dropped";
        });
        p.lat = kMissing;
      }
    }
    g.points.push_back(p);
    if (g.position_level == 0)
      g.position_level = f.level;
    else if (g.position_level != f.level)
      g.mixed_levels = true;
    if (parent) parent->had_position_child = true;
  }

  bool abort(std::string message) {
    abort_message_ = std::move(message);
    return false;
  }

  JsonSourceBuffer& in_;
  TrackFile& file_;
  WarningCollector& warnings_;
  std::vector<Frame> frames_;
  std::set<std::string> seen_;
  std::unique_ptr<GeoObject> root_;
  bool cut_ = false;
  std::int64_t error_offset_ = -1;
  std::string syntax_error_, abort_message_;
};

}  // namespace trailray::track::geojson
