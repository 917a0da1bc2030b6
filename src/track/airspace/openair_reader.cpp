#include "track/airspace/openair_reader.hpp"

#include <cctype>
#include <cmath>
#include <memory>
#include <string>

#include "geo/longitude.hpp"
#include "geo/utf8.hpp"
#include "track/airspace/arc_geometry.hpp"
#include "track/airspace/openair_values.hpp"
#include "track/io/byte_source.hpp"
#include "track/io/parse_util.hpp"

namespace trailray::track::airspace {
namespace {

// Radii beyond this (about 1080 NM) are not airspace but a broken file; refusing them keeps the
// arc step finite.
constexpr double kMaxRadiusM = 2'000'000.0;
// Boundary points in one file: a whole continent's file has well under a million; beyond this a
// file of nothing but huge circles would fill memory.
constexpr std::size_t kMaxPointsPerFile = 5'000'000;

// The file as UTF-8: the BOM dropped; Latin-1 bytes converted when the file is not UTF-8.
std::string as_utf8(std::string_view bytes, bool& converted) {
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  converted = !geo::is_valid_utf8(bytes);
  if (!converted) return std::string(bytes);
  std::string out;
  out.reserve(bytes.size() + bytes.size() / 8);
  for (char c : bytes) geo::append_utf8(out, static_cast<unsigned char>(c));
  return out;
}

std::string upper_ascii(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// A TNP file: TITLE=/POINT=/CIRCLE/INCLUDE= records and no OpenAir AC record.
bool is_tnp(std::string_view text) {
  bool tnp = false;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = trim(text.substr(begin, end - begin));
    const std::string head = upper_ascii(line.substr(0, 8));
    if (head.rfind("AC ", 0) == 0 || head.rfind("AC\t", 0) == 0) return false;
    if (head.rfind("TITLE=", 0) == 0 || head.rfind("POINT=", 0) == 0 || head.rfind("CIRCLE ", 0) == 0 ||
        head.rfind("INCLUDE=", 0) == 0)
      tnp = true;
    begin = end + 1;
  }
  return tnp;
}

class Parser {
 public:
  Parser(std::string name, const ReadOptions& options) : name_(std::move(name)), warnings_(name_), options_(options) {}

  // One line of the file, OpenAir or TNP (`tnp`): the bound on points, comments and blank lines
  // are the two formats' alike.
  void line(std::string_view text, std::int64_t number, bool tnp) {
    line_ = number;
    if (points_ + (current_ ? current_->boundary.size() : 0) > kMaxPointsPerFile)
      return fail_file("more than 5 million boundary points: not an airspace file");
    text = trim(text);
    if (text.empty() || text.front() == '*' || text.front() == '#') return;
    if (tnp)
      tnp_record(text, number);
    else
      openair_record(text, number);
  }

  void openair_record(std::string_view text, std::int64_t number) {
    std::size_t split = 0;
    while (split < text.size() && text[split] != ' ' && text[split] != '\t') ++split;
    const std::string keyword = upper_ascii(text.substr(0, split));
    const std::string_view value = trim(text.substr(split));
    if (keyword == "AC") {
      finish_airspace();
      current_ = std::make_unique<Airspace>();
      current_->airspace_class = std::string(value);
      current_->line = number;
      centre_.reset();
      clockwise_ = true;
      airway_.clear();
      airway_width_nm_ = 0.0;
      return;
    }
    // The rest of an airspace that cannot be used is passed over up to the next AC.
    if (current_ && broken_) return;
    if (keyword == "AR" || keyword == "AF" || keyword == "AY" || keyword == "AG" || keyword == "AT" ||
        keyword == "AI" || keyword == "SP" || keyword == "SB" || keyword == "AX" || keyword == "AA")
      return;  // radio, type, ground station, label positions, pens: nothing a check or a drawing uses
    if (keyword == "V") return variable(value);
    if (!current_) {
      if (keyword == "AN" || keyword == "AL" || keyword == "AH" || keyword == "DP" || keyword == "DA" ||
          keyword == "DB" || keyword == "DC")
        warnings_.add("outside", here(), keyword + " record before any AC record: ignored");
      else
        unknown(keyword);
      return;
    }
    if (keyword == "AN") {
      current_->name = std::string(value);
    } else if (keyword == "AL" || keyword == "AH") {
      auto limit = parse_openair_altitude(value);
      if (!limit) return fail(keyword + ": cannot read the height '" + std::string(value) + "'");
      std::optional<AltitudeLimit>& slot = keyword == "AL" ? floor_ : ceiling_;
      // Given twice (files merged by hand, or feet then metres): the later wins, as XCSoar reads it.
      if (slot)
        warnings_.add("twice:" + keyword, here(),
                      keyword + " given twice in airspace " + (current_->name.empty() ? "(no name)" : current_->name) +
                          ": the later ('" + std::string(value) + "') is used");
      slot = *limit;
    } else if (keyword == "DP") {
      auto p = parse_openair_coordinate(value);
      if (!p) return fail("DP: cannot read the coordinate '" + std::string(value) + "'");
      current_->boundary.push_back(*p);
    } else if (keyword == "DY") {
      auto p = parse_openair_coordinate(value);
      if (!p) return fail("DY: cannot read the coordinate '" + std::string(value) + "'");
      airway_.push_back(*p);
    } else if (keyword == "DC") {
      const auto r = parse_double(value);
      if (!r || !(*r > 0.0) || *r * kMetresPerNauticalMile > kMaxRadiusM)
        return fail("DC: the radius must be a positive number of nautical miles, not '" + std::string(value) + "'");
      if (!need_centre("DC")) return;
      auto circle = circle_points(*centre_, *r * kMetresPerNauticalMile);
      current_->boundary.insert(current_->boundary.end(), circle.begin(), circle.end());
    } else if (keyword == "DA") {
      arc_by_angles(value);
    } else if (keyword == "DB") {
      arc_between(value);
    } else {
      unknown(keyword);
    }
  }

  // TNP (Tim Newport-Peace, .sua; XCSoar reads it too): KEY=VALUE records. TITLE=, TYPE= and
  // CLASS= begin an airspace (once the one before has a shape), BASE= and TOPS= its limits (as
  // OpenAir writes them), POINT=, CIRCLE RADIUS= CENTRE= and CLOCKWISE / ANTI-CLOCKWISE RADIUS=
  // CENTRE= TO= its shape; INCLUDE=NO leaves out what follows up to INCLUDE=YES.
  void tnp_record(std::string_view text, std::int64_t number) {
    const std::string upper = upper_ascii(text);
    const auto starts = [&](std::string_view key) { return std::string_view(upper).substr(0, key.size()) == key; };
    const auto after = [&](std::string_view key) { return trim(text.substr(key.size())); };
    if (starts("INCLUDE=")) {
      const bool include = trim(std::string_view(upper).substr(8)) != "NO";
      if (!include) finish_airspace();
      tnp_include_ = include;
      return;
    }
    if (!tnp_include_) return;
    if (starts("TITLE=") || starts("TYPE=") || starts("CLASS=")) {
      if (!current_ || !current_->boundary.empty() || broken_) {
        finish_airspace();
        current_ = std::make_unique<Airspace>();
        current_->line = number;
        tnp_type_.clear();
        tnp_class_.clear();
      }
      if (starts("TITLE=")) current_->name = std::string(after("TITLE="));
      if (starts("TYPE=")) tnp_type_ = trim(std::string_view(upper).substr(5));
      if (starts("CLASS=")) tnp_class_ = trim(std::string_view(upper).substr(6));
      current_->airspace_class = tnp_class(tnp_type_, tnp_class_);
      return;
    }
    if (starts("RADIO=") || starts("ACTIVE=") || starts("END") || starts("WIDTH=")) return;  // nothing drawn or checked
    if (!current_) {
      unknown(std::string(upper.substr(0, upper.find_first_of(" =") + 1)));
      return;
    }
    if (broken_) return;
    if (starts("BASE=") || starts("TOPS=")) {
      const std::string_view value = after("BASE=");
      auto limit = parse_openair_altitude(value);
      const std::string key = starts("BASE=") ? "BASE" : "TOPS";
      if (!limit) return fail(key + ": cannot read the height '" + std::string(value) + "'");
      (key == "BASE" ? floor_ : ceiling_) = *limit;
    } else if (starts("POINT=")) {
      std::string_view rest;
      auto p = parse_tnp_coordinate(after("POINT="), &rest);
      if (!p || !rest.empty()) return fail("POINT: cannot read the coordinate '" + std::string(after("POINT=")) + "'");
      current_->boundary.push_back(*p);
    } else if (starts("CIRCLE") || starts("CLOCKWISE") || starts("ANTI-CLOCKWISE")) {
      tnp_shape(upper, text);
    } else {
      unknown(std::string(upper.substr(0, upper.find_first_of(" =") + 1)));
    }
  }

  AirspaceReadResult finish() {
    if (!result_.error) finish_airspace();
    // Only a file with no usable airspace at all is an error: the first reason one was skipped,
    // else that there was none.
    if (!result_.error && result_.file.airspaces.empty())
      result_.error = first_skipped_ ? *first_skipped_
                                     : Diagnostic{name_, {}, "no airspace in it (no AC record with a boundary)"};
    result_.warnings = warnings_.diagnostics();
    if (options_.strict && !result_.error && !result_.warnings.empty()) {
      result_.error = result_.warnings.front();
      result_.warnings.erase(result_.warnings.begin());
    }
    return std::move(result_);
  }

  bool failed() const { return result_.error.has_value(); }
  void note(const std::string& message) { warnings_.add_single({}, message); }

 private:
  SourcePosition here() const { return {line_, 1, -1}; }
  // What makes the airspace being read unusable: it is skipped with a warning naming its line,
  // the others go on. Outside any airspace (a V record before the first AC), a warning.
  void fail(const std::string& message) {
    if (!current_) {
      warnings_.add("outside", here(), message + ": ignored (before any AC record)");
      return;
    }
    if (!broken_) broken_ = Diagnostic{name_, here(), message};
  }
  // What makes the whole file unreadable.
  void fail_file(const std::string& message) { result_.error = Diagnostic{name_, here(), message}; }
  void unknown(const std::string& keyword) {
    warnings_.add("unknown:" + keyword, here(), "unknown OpenAir record '" + keyword + "': ignored");
  }

  // The class a TNP airspace is drawn and checked as: CLASS= (A..G) when given, else its TYPE= in
  // OpenAir's words (C/CTA/CTR: CTR, D: danger Q, G: gliding W, "CLASS C": C).
  static std::string tnp_class(const std::string& type, const std::string& klass) {
    if (!klass.empty()) return klass;
    if (type == "C" || type == "CTA" || type == "CTR" || type == "CTA/CTR") return "CTR";
    if (type == "D") return "Q";
    if (type == "G") return "W";
    if (type.rfind("CLASS ", 0) == 0) return std::string(trim(std::string_view(type).substr(6)));
    return type;
  }

  // The value of KEY= in a TNP shape record ("RADIUS=5 CENTRE=N... E... TO=N... E..."); empty when absent.
  static std::string_view tnp_field(std::string_view upper, std::string_view text, std::string_view key) {
    const std::size_t at = upper.find(key);
    if (at == std::string_view::npos) return {};
    std::string_view v = text.substr(at + key.size());
    // Up to the next KEY= (a word followed by '=').
    for (std::size_t i = 0; i < v.size(); ++i)
      if (v[i] == ' ') {
        const std::size_t eq = v.find('=', i + 1), space = v.find(' ', i + 1);
        if (eq != std::string_view::npos && (space == std::string_view::npos || eq < space)) return trim(v.substr(0, i));
      }
    return trim(v);
  }

  void tnp_shape(const std::string& upper, std::string_view text) {
    const std::string_view u(upper);
    const bool circle = u.rfind("CIRCLE", 0) == 0, anticlockwise = u.rfind("ANTI-CLOCKWISE", 0) == 0;
    const auto r = parse_double(tnp_field(u, text, "RADIUS="));
    std::string_view rest;
    const auto centre = parse_tnp_coordinate(tnp_field(u, text, "CENTRE="), &rest);
    if (!centre) return fail("cannot read the CENTRE= of '" + std::string(text) + "'");
    if (circle) {
      if (!r || !(*r > 0.0) || *r * kMetresPerNauticalMile > kMaxRadiusM)
        return fail("CIRCLE: the RADIUS= must be a positive number of nautical miles in '" + std::string(text) + "'");
      const auto points = circle_points(*centre, *r * kMetresPerNauticalMile);
      current_->boundary.insert(current_->boundary.end(), points.begin(), points.end());
      return;
    }
    const auto to = parse_tnp_coordinate(tnp_field(u, text, "TO="), &rest);
    if (!to) return fail("cannot read the TO= of '" + std::string(text) + "'");
    if (current_->boundary.empty()) return fail("an arc with no point before it to start from");
    // From the last point to TO= around CENTRE= (the radius each end's own, as for DB).
    const geo::LatLon from = current_->boundary.back();
    double r1 = 0, a1 = 0, r2 = 0, a2 = 0;
    geodesic_inverse(*centre, from, r1, a1);
    geodesic_inverse(*centre, *to, r2, a2);
    if (!(r1 > 0.0) || !(r2 > 0.0) || r1 > kMaxRadiusM || r2 > kMaxRadiusM)
      return fail("the arc's ends must lie away from its centre, within 2000 km");
    append_arc(current_->boundary, *centre, r1, r2, a1, a2, !anticlockwise);
    current_->boundary.back() = *to;
  }

  bool need_centre(const char* keyword) {
    if (centre_) return true;
    fail(std::string(keyword) + ": no centre given (a 'V X=' record must come first)");
    return false;
  }

  void variable(std::string_view value) {
    if (value.size() < 2 || value[1] != '=') {
      warnings_.add("variable", here(), "V record without NAME=VALUE: ignored");
      return;
    }
    const char var = static_cast<char>(std::toupper(static_cast<unsigned char>(value[0])));
    const std::string_view v = trim(value.substr(2));
    if (var == 'X') {
      auto p = parse_openair_coordinate(v);
      if (!p) return fail("V X=: cannot read the centre '" + std::string(v) + "'");
      centre_ = *p;
    } else if (var == 'D') {
      if (v == "+")
        clockwise_ = true;
      else if (v == "-")
        clockwise_ = false;
      else
        fail("V D=: the direction must be + or -, not '" + std::string(v) + "'");
    } else if (var == 'W') {  // the width of an airway (DY records), nautical miles
      const auto w = parse_double(v);
      if (!w || !(*w > 0.0) || *w * kMetresPerNauticalMile > kMaxRadiusM)
        return fail("V W=: an airway's width must be a positive number of nautical miles, not '" + std::string(v) + "'");
      airway_width_nm_ = *w;
    } else if (var != 'Z' && var != 'T') {  // zoom, thickness: unused
      warnings_.add("variable", here(), std::string("unknown variable V ") + var + "=: ignored");
    }
  }

  // DA radius, start, end: radius in NM, angles in degrees clockwise from true north.
  void arc_by_angles(std::string_view value) {
    double numbers[3];
    for (int i = 0; i < 3; ++i) {
      const std::size_t comma = i < 2 ? value.find(',') : value.size();
      if (comma == std::string_view::npos) return fail("DA: expected 'radius, start angle, end angle'");
      const auto v = parse_double(value.substr(0, comma));
      if (!v) return fail("DA: cannot read the number '" + std::string(trim(value.substr(0, comma))) + "'");
      numbers[i] = *v;
      value = value.substr(std::min(comma + 1, value.size()));
    }
    const double r = numbers[0] * kMetresPerNauticalMile;
    if (!(r > 0.0) || r > kMaxRadiusM || std::abs(numbers[1]) > 3600 || std::abs(numbers[2]) > 3600)
      return fail("DA: the radius must be positive and the angles in degrees");
    if (!need_centre("DA")) return;
    append_arc(current_->boundary, *centre_, r, r, numbers[1], numbers[2], clockwise_);
  }

  // DB from, to: an arc around the centre between two points.
  void arc_between(std::string_view value) {
    std::string_view rest;
    auto from = parse_openair_coordinate(value, &rest);
    if (!from || rest.empty() || rest.front() != ',')
      return fail("DB: expected 'coordinate, coordinate', got '" + std::string(value) + "'");
    auto to = parse_openair_coordinate(rest.substr(1), &rest);
    if (!to || !rest.empty()) return fail("DB: cannot read the second coordinate in '" + std::string(value) + "'");
    if (!need_centre("DB")) return;
    double r1 = 0, a1 = 0, r2 = 0, a2 = 0;
    geodesic_inverse(*centre_, *from, r1, a1);
    geodesic_inverse(*centre_, *to, r2, a2);
    if (!(r1 > 0.0) || !(r2 > 0.0) || r1 > kMaxRadiusM || r2 > kMaxRadiusM)
      return fail("DB: the points must lie away from the centre, within 2000 km");
    if (std::abs(r1 - r2) > 0.05 * std::max(r1, r2))
      warnings_.add("db-radius", here(),
                    "DB: the two points are at different distances from the centre (" + std::to_string(int(r1)) +
                        " m and " + std::to_string(int(r2)) + " m); the radius goes linearly from one to the other");
    append_arc(current_->boundary, *centre_, r1, r2, a1, a2, clockwise_);
    // The given points themselves, not their geodesic reconstruction.
    current_->boundary[current_->boundary.size() - 1] = *to;
  }

  void finish_airspace() {
    if (!current_) return;
    Airspace& a = *current_;
    if (!airway_.empty() && !broken_) {
      // An airway: its centreline and width become the boundary.
      if (!(airway_width_nm_ > 0.0)) {
        line_ = a.line;
        fail("DY: an airway without a width (V W=)");
      } else {
        const auto ring = airway_outline(airway_, airway_width_nm_ * kMetresPerNauticalMile / 2.0);
        a.boundary.insert(a.boundary.end(), ring.begin(), ring.end());
      }
      airway_.clear();
    }
    if (broken_) {
      const std::string label = a.name.empty() ? "(no name)" : a.name;
      warnings_.add("skipped:" + std::to_string(a.line), broken_->position,
                    broken_->message + ": airspace " + label + " (from line " + std::to_string(a.line) + ") skipped");
      if (!first_skipped_) first_skipped_ = broken_;
      ++result_.skipped;
      broken_.reset();
      current_.reset();
      floor_.reset();
      ceiling_.reset();
      return;
    }
    auto& ring = a.boundary;
    if (ring.size() > 1 && ring.front().lat == ring.back().lat && ring.front().lon == ring.back().lon) ring.pop_back();
    geo::unwrap_longitudes(ring);  // across the antimeridian: continuous (airspace.hpp)
    const SourcePosition at{a.line, 1, -1};
    const std::string label = a.name.empty() ? "(no name)" : a.name;
    if (!floor_ || !ceiling_)
      warnings_.add(
          "limits", at,
          "airspace " + label + " has no " + (!floor_ ? "AL floor (taken as GND)" : "AH ceiling (taken as UNL)"));
    a.floor = floor_.value_or(AltitudeLimit{AltitudeReference::Agl, 0.0, "GND"});
    a.ceiling = ceiling_.value_or(AltitudeLimit{AltitudeReference::Unlimited, 0.0, "UNL"});
    // Two points are a line: Skytraxx files mark cables that way (floor = ceiling). Kept for
    // drawing; a line has no inside, so no check ever finds a track in it.
    if (ring.size() < 2) {
      warnings_.add("shape", at, "airspace " + label + " has fewer than 2 boundary points: skipped");
      ++result_.skipped;
    } else {
      points_ += ring.size();
      result_.file.airspaces.push_back(std::move(a));
    }
    current_.reset();
    floor_.reset();
    ceiling_.reset();
  }

  std::string name_;
  WarningCollector warnings_;
  ReadOptions options_;
  AirspaceReadResult result_;
  std::unique_ptr<Airspace> current_;
  std::optional<AltitudeLimit> floor_, ceiling_;
  std::optional<geo::LatLon> centre_;
  std::vector<geo::LatLon> airway_;  // DY points
  double airway_width_nm_ = 0.0;     // V W=
  std::optional<Diagnostic> broken_;         // why the airspace being read cannot be used
  std::optional<Diagnostic> first_skipped_;  // the first such reason in the file
  bool clockwise_ = true;
  std::int64_t line_ = 0;
  std::size_t points_ = 0;  // in the airspaces kept so far
  bool tnp_include_ = true;    // TNP: INCLUDE=NO leaves out what follows
  std::string tnp_type_, tnp_class_;
};

}  // namespace

AirspaceReadResult read_openair(std::string_view bytes, const std::string& display_name, const ReadOptions& options) {
  bool latin1 = false;
  const std::string text = as_utf8(bytes, latin1);
  Parser parser(display_name, options);
  const bool tnp = is_tnp(text);
  std::size_t begin = 0;
  std::int64_t number = 0;
  while (begin < text.size() && !parser.failed()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    parser.line(line, ++number, tnp);
    begin = end + 1;
  }
  if (latin1) parser.note("not valid UTF-8: read as Latin-1 (ISO-8859-1), names converted to UTF-8");
  return parser.finish();
}

AirspaceReadResult load_openair_file(const std::string& path, const ReadOptions& options) {
  std::string error;
  auto source = ByteSource::open(path, error);
  const std::string name = path == "-" ? "<stdin>" : path;
  if (!source) {
    AirspaceReadResult r;
    r.error = Diagnostic{name, {}, error};
    return r;
  }
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const std::ptrdiff_t n = source->next(buffer, sizeof buffer);
    if (n < 0) {
      AirspaceReadResult r;
      r.error = Diagnostic{name, {}, "cannot read: " + source->error()};
      return r;
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
    if (bytes.size() > (std::size_t{256} << 20)) {
      AirspaceReadResult r;
      r.error = Diagnostic{name, {}, "more than 256 MiB: not an airspace file"};
      return r;
    }
  }
  return read_openair(bytes, name, options);
}

}  // namespace trailray::track::airspace
