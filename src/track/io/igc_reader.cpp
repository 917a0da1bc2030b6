// IGC flight recorder reader (FAI IGC technical specification, appendix A): one Track with
// one Segment of B-record fixes in file order, the H-record headers as metadata fields.
//
// Records read: A (recorder -> metadata.creator), H (headers, HFDTE flight date), I (B-record
// extensions; LAD/LOD extra coordinate digits are applied, the others are checked but not
// kept: the model has no channel for them and TAS/GSP units differ between recorders), B
// (fixes). Every other record type (C, D, E, F, G, J, K, L, ...) is ignored.
//
// Elevation rule (ReadOptions::igc_altitude), decided per file after reading every fix:
//   A channel whose value is 0 on every kept fix is "absent": XCTrack and other phone apps
//   write pressure altitude 00000 when there is no barometer, some recorders write GNSS
//   altitude 00000. A single 0 in a channel that is present elsewhere is kept as 0 (sea level
//   is real; dropouts are left to cleaning).
//   Auto:     GNSS altitude on 'A' (3D) fixes when the GNSS channel is present; otherwise
//             (a 'V' fix, or no GNSS channel) pressure altitude when that channel is present;
//             otherwise no elevation. Note that a file mixing 'A' and 'V' fixes with both
//             channels present then switches channel (GNSS is ellipsoid/geoid based, pressure
//             is ISA based: they can differ by tens of metres).
//   Gnss:     GNSS altitude on every fix, except 'V' fixes whose GNSS altitude is 0 (no 3D
//             solution); no elevation at all, with a warning, when the channel is absent.
//   Pressure: pressure altitude on every fix; no elevation, with a warning, when absent.
//
// Time rule: B times are UTC time of day on the HFDTE flight date. A time more than 12 hours
// earlier than the previous fix's is a UTC midnight rollover (next day); smaller backward
// steps are kept as recorded (cleaning deals with them). Without a readable HFDTE record the
// times are kept as time of day on 1970-01-01, with the warning "no HFDTE date record".

#include <algorithm>
#include <array>
#include <cstdint>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"

namespace trailray::track {
namespace {

constexpr std::size_t kMaxLine = 4096;   // IGC lines are at most 76 characters (+ L comments)
constexpr std::size_t kBaseLength = 35;  // a B record without extensions
constexpr double kRolloverSeconds = 12 * 3600.0;

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_alnum(char c) { return is_digit(c) || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// Exactly `n` digits at s[pos..pos+n) as an unsigned number; false for anything else.
bool read_digits(std::string_view s, std::size_t pos, std::size_t n, std::int64_t& out) {
  if (pos > s.size() || n > s.size() - pos) return false;
  std::int64_t v = 0;
  for (std::size_t i = pos; i < pos + n; ++i) {
    if (!is_digit(s[i])) return false;
    v = v * 10 + (s[i] - '0');
  }
  out = v;
  return true;
}

// A 5-character altitude field: digits, or '-' then digits ("-0012").
bool read_altitude(std::string_view s, std::size_t pos, std::int64_t& out) {
  if (pos + 5 > s.size()) return false;
  if (s[pos] == '-') {
    std::int64_t v = 0;
    if (!read_digits(s, pos + 1, 4, v)) return false;
    out = -v;
    return true;
  }
  return read_digits(s, pos, 5, out);
}

// An extension value: optional leading spaces, an optional sign, then only digits.
bool numeric_extension(std::string_view v) {
  std::size_t i = 0;
  while (i < v.size() && v[i] == ' ') ++i;
  if (i < v.size() && (v[i] == '-' || v[i] == '+')) ++i;
  if (i == v.size()) return false;
  for (; i < v.size(); ++i)
    if (!is_digit(v[i])) return false;
  return true;
}

// Printable excerpt of a field for a message: at most 40 bytes, control bytes as '?'.
std::string excerpt(std::string_view s) {
  std::string out(s.substr(0, 40));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  if (s.size() > 40) out += "...";
  return out;
}

// Structurally valid UTF-8 (lead and continuation bytes; overlong 3/4-byte forms not checked).
bool valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    if (c < 0x80)
      n = 0;
    else if (c >= 0xc2 && c <= 0xdf)
      n = 1;
    else if (c >= 0xe0 && c <= 0xef)
      n = 2;
    else if (c >= 0xf0 && c <= 0xf4)
      n = 3;
    else
      return false;
    if (n > s.size() - i - 1) return false;
    for (std::size_t k = 1; k <= n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
    i += n + 1;
  }
  return true;
}

// Header text as UTF-8: kept when it is valid UTF-8, otherwise read as Latin-1 (older
// recorders); control characters become spaces.
std::string header_text(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  const bool utf8 = valid_utf8(s);
  for (char ch : s) {
    auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) {
      out.push_back(' ');
    } else if (c < 0x80 || utf8) {
      out.push_back(ch);
    } else {
      out.push_back(static_cast<char>(0xc0 | (c >> 6)));
      out.push_back(static_cast<char>(0x80 | (c & 0x3f)));
    }
  }
  return std::string(trim(out));
}

// H-record three-letter codes -> metadata field keys.
const char* header_key(std::string_view code) {
  static constexpr std::array<std::pair<std::string_view, const char*>, 22> kKeys{{
      {"PLT", "pilot"},
      {"CM2", "copilot"},
      {"GTY", "glider_type"},
      {"GID", "glider_id"},
      {"CID", "competition_id"},
      {"CCL", "competition_class"},
      {"SIT", "site"},
      {"RFW", "firmware"},
      {"RHW", "hardware"},
      {"FTY", "recorder"},
      {"DTM", "gps_datum"},
      {"ALP", "altitude_pressure"},
      {"ALG", "altitude_gps"},
      {"GPS", "gps_receiver"},
      {"PRS", "pressure_sensor"},
      {"TZN", "timezone"},
      {"TZO", "timezone"},
      {"FXA", "fix_accuracy"},
      {"FRS", "security"},
      {"CLB", "club"},
      {"UNT", "units"},
      {"MOP", "means_of_propulsion"},
  }};
  for (const auto& [c, key] : kKeys)
    if (c == code) return key;
  return nullptr;
}

// A-record manufacturer codes (three-letter, plus the common unofficial X codes).
const char* manufacturer_name(std::string_view code) {
  static constexpr std::array<std::pair<std::string_view, const char*>, 19> kNames{{
      {"ACT", "Aircotec"},  {"CAM", "Cambridge"},         {"CNI", "ClearNav"},
      {"DSX", "Data Swan"}, {"EWA", "EW Avionics"},       {"FIL", "Filser"},
      {"FLA", "FLARM"},     {"GCS", "Garrecht"},          {"IMI", "IMI Gliding"},
      {"LGS", "Logstream"}, {"LXN", "LX Navigation"},     {"LXV", "LXNAV"},
      {"NAV", "Naviter"},   {"NKL", "Nielsen Kellerman"}, {"PES", "Peschges"},
      {"XCS", "XCSoar"},    {"XCT", "XCTrack"},           {"XSX", "Skytraxx"},
      {"ZAN", "Zander"},
  }};
  for (const auto& [c, name] : kNames)
    if (c == code) return name;
  return nullptr;
}

struct Extension {
  char code[4] = {};
  std::size_t start = 0;  // 0-based index into the B record
  std::size_t end = 0;    // one past the last byte
  std::string_view name() const { return std::string_view(code, 3); }
};

struct RawAltitude {
  std::int32_t pressure = 0;
  std::int32_t gnss = 0;
  bool fix_3d = false;
};

class IgcParser {
 public:
  IgcParser(ReadResult& result, WarningCollector& warnings, const ReadOptions& options)
      : file_(result.file), warnings_(warnings), options_(options) {}

  void line(std::string_view s, std::int64_t line_no, std::int64_t offset, bool last_unterminated) {
    line_no_ = line_no;
    offset_ = offset;
    if (line_no == 1 && s.starts_with("\xEF\xBB\xBF")) {
      s.remove_prefix(3);
      offset_ += 3;
    }
    if (s.empty()) return;
    switch (s[0]) {
      case 'B':
        ++b_lines_;
        if (last_unterminated && s.size() < expected_b_length()) {
          warnings_.add_single(at(s.size() + 1), "file ends inside a record (cut short?): incomplete B record of " +
                                                     std::to_string(s.size()) + " characters dropped; kept the " +
                                                     std::to_string(points().size()) + " complete points before it");
          return;
        }
        b_record(s);
        break;
      case 'H':
        h_record(s);
        break;
      case 'I':
        i_record(s);
        break;
      case 'A':
        if (!seen_a_ && s.size() >= 4 && is_alnum(s[1]) && is_alnum(s[2]) && is_alnum(s[3])) a_record(s);
        break;
      default:
        break;
    }
  }

  void long_line(std::int64_t line_no, std::int64_t offset) {
    warnings_.add("long-line", SourcePosition{line_no, 1, offset},
                  "line longer than " + std::to_string(kMaxLine) + " bytes ignored (not an IGC record)");
  }

  // After the last line: dates, elevations, the not-IGC check. False when it is not IGC.
  bool finish(ReadResult& result, const std::string& name) {
    if (!seen_a_ && !seen_h_ && points().empty()) {
      result.error = Diagnostic{name, SourcePosition{1, 1, 0},
                                "not an IGC file: no A record, no H records and no valid B records"};
      file_.tracks.clear();
      return false;
    }
    file_.metadata.activity_type = "flight";
    if (b_lines_ == 0) warnings_.add_single({}, "no B records: the file has no fixes");

    const double base = date_days_ ? static_cast<double>(*date_days_) * 86400.0 : 0.0;
    if (date_days_) {
      file_.metadata.time = base;
    } else if (!points().empty()) {
      warnings_.add_single({}, "no HFDTE date record: times have no date (kept as time of day on 1970-01-01)");
    }
    for (TrackPoint& p : points()) p.time += base;
    assign_elevation();
    return true;
  }

  std::vector<TrackPoint>& points() { return file_.tracks.front().segments.front().points; }

 private:
  SourcePosition at(std::size_t column) const {
    return SourcePosition{line_no_, static_cast<std::int64_t>(column), offset_ + static_cast<std::int64_t>(column) - 1};
  }

  std::size_t expected_b_length() const {
    std::size_t n = kBaseLength;
    for (const Extension& e : extensions_) n = std::max(n, e.end);
    return n;
  }

  void drop(const char* kind, std::size_t column, const std::string& why) {
    warnings_.add(kind, at(column), why + ": fix dropped");
  }

  void b_record(std::string_view s) {
    if (s.size() < kBaseLength) {
      drop(
          "b-short", 1,
          "B record too short (" + std::to_string(s.size()) + " characters, need " + std::to_string(kBaseLength) + ")");
      return;
    }
    std::int64_t hh = 0, mi = 0, ss = 0;
    if (!read_digits(s, 1, 2, hh) || !read_digits(s, 3, 2, mi) || !read_digits(s, 5, 2, ss) || hh > 23 || mi > 59 ||
        ss > 60) {
      drop("b-time", 2, "B record time '" + excerpt(s.substr(1, 6)) + "' is not HHMMSS");
      return;
    }
    std::int64_t lat_deg = 0, lat_min = 0, lon_deg = 0, lon_min = 0;  // minutes in 1/1000
    const char ns = s[14], ew = s[23];
    if (!read_digits(s, 7, 2, lat_deg) || !read_digits(s, 9, 5, lat_min) ||
        (ns != 'N' && ns != 'S' && ns != 'n' && ns != 's') || lat_min >= 60000) {
      drop("b-coords", 8, "B record latitude '" + excerpt(s.substr(7, 8)) + "' is not DDMMmmmN/S");
      return;
    }
    if (!read_digits(s, 15, 3, lon_deg) || !read_digits(s, 18, 5, lon_min) ||
        (ew != 'E' && ew != 'W' && ew != 'e' && ew != 'w') || lon_min >= 60000) {
      drop("b-coords", 16, "B record longitude '" + excerpt(s.substr(15, 9)) + "' is not DDDMMmmmE/W");
      return;
    }
    const char validity = s[24];
    if (validity != 'A' && validity != 'V') {
      drop("b-validity", 25, "B record fix validity '" + excerpt(s.substr(24, 1)) + "' is not A or V");
      return;
    }
    std::int64_t pressure = 0, gnss = 0;
    if (!read_altitude(s, 25, pressure)) {
      drop("b-altitude", 26, "B record pressure altitude '" + excerpt(s.substr(25, 5)) + "' is not a number");
      return;
    }
    if (!read_altitude(s, 30, gnss)) {
      drop("b-altitude", 31, "B record GNSS altitude '" + excerpt(s.substr(30, 5)) + "' is not a number");
      return;
    }

    // Extensions: all are checked; LAD/LOD add further decimal digits of the minutes.
    std::int64_t lat_scale = 1000, lon_scale = 1000;
    bool missing = false;
    for (const Extension& e : extensions_) {
      if (e.end > s.size()) {
        missing = true;
        continue;
      }
      std::string_view v = s.substr(e.start, e.end - e.start);
      if (!numeric_extension(v)) {
        warnings_.add("b-extension", at(e.start + 1),
                      "B record extension " + std::string(e.name()) + " '" + excerpt(v) +
                          "' is not a number: value ignored, fix kept");
        continue;
      }
      const bool lad = e.name() == "LAD", lod = e.name() == "LOD";
      if ((lad || lod) && v.size() <= 6) {
        std::int64_t extra = 0;
        if (!read_digits(v, 0, v.size(), extra)) {
          warnings_.add("b-extension", at(e.start + 1),
                        "B record extension " + std::string(e.name()) + " '" + excerpt(v) +
                            "' is not digits: value ignored, fix kept");
          continue;
        }
        std::int64_t& minutes = lad ? lat_min : lon_min;
        std::int64_t& scale = lad ? lat_scale : lon_scale;
        for (std::size_t k = 0; k < v.size(); ++k) {
          minutes *= 10;
          scale *= 10;
        }
        minutes += extra;
      }
    }
    if (missing)
      warnings_.add("b-extension-short", at(s.size()),
                    "B record of " + std::to_string(s.size()) + " characters is shorter than its I record declares (" +
                        std::to_string(expected_b_length()) + "): missing extension values ignored, fix kept");

    TrackPoint p;
    p.lat = static_cast<double>(lat_deg) + static_cast<double>(lat_min) / (60.0 * static_cast<double>(lat_scale));
    p.lon = static_cast<double>(lon_deg) + static_cast<double>(lon_min) / (60.0 * static_cast<double>(lon_scale));
    if (ns == 'S' || ns == 's') p.lat = -p.lat;
    if (ew == 'W' || ew == 'w') p.lon = -p.lon;
    if (!valid_coordinates(p.lat, p.lon)) {
      drop("b-coords", 8, "B record position '" + excerpt(s.substr(7, 17)) + "' is out of range");
      return;
    }
    if (validity == 'V' && lat_min == 0 && lat_deg == 0 && lon_min == 0 && lon_deg == 0) {
      drop("b-nofix", 8, "B record without a position (0,0 with fix validity V)");
      return;
    }

    // Time of day relative to the flight date; the date is added in finish().
    const double tod = static_cast<double>(hh * 3600 + mi * 60 + ss);
    if (have_prev_ && tod < prev_tod_ - kRolloverSeconds) ++day_;
    have_prev_ = true;
    prev_tod_ = tod;
    p.time = static_cast<double>(day_) * 86400.0 + tod;

    points().push_back(p);
    altitudes_.push_back(
        RawAltitude{static_cast<std::int32_t>(pressure), static_cast<std::int32_t>(gnss), validity == 'A'});
    if (pressure != 0) pressure_present_ = true;
    if (gnss != 0) gnss_present_ = true;
  }

  void i_record(std::string_view s) {
    extensions_.clear();
    std::int64_t n = 0;
    if (!read_digits(s, 1, 2, n)) {
      warnings_.add("i-record", at(2),
                    "I record count '" + excerpt(s.substr(1, 2)) + "' is not a number: B-record extensions ignored");
      return;
    }
    for (std::int64_t i = 0; i < n; ++i) {
      const std::size_t off = 3 + 7 * static_cast<std::size_t>(i);
      if (off + 7 > s.size()) {
        warnings_.add("i-record", at(std::min(off, s.size()) + 1),
                      "I record declares " + std::to_string(n) + " extensions but has " + std::to_string(i) +
                          ": the missing ones are ignored");
        return;
      }
      std::int64_t start = 0, end = 0;
      if (!read_digits(s, off, 2, start) || !read_digits(s, off + 2, 2, end) ||
          start < static_cast<std::int64_t>(kBaseLength) + 1 || end < start) {
        warnings_.add("i-record", at(off + 1),
                      "I record entry '" + excerpt(s.substr(off, 7)) + "' has an invalid byte range: ignored");
        continue;
      }
      Extension e;
      for (std::size_t k = 0; k < 3; ++k) e.code[k] = s[off + 4 + k];
      e.start = static_cast<std::size_t>(start) - 1;
      e.end = static_cast<std::size_t>(end);
      extensions_.push_back(e);
    }
  }

  void a_record(std::string_view s) {
    seen_a_ = true;
    if (const char* maker = manufacturer_name(s.substr(1, 3))) {
      const std::string id = header_text(s.substr(4));
      file_.metadata.creator = id.empty() ? std::string(maker) : std::string(maker) + " " + id;
    } else {
      file_.metadata.creator = header_text(s.substr(1));
    }
  }

  void h_record(std::string_view s) {
    if (s.size() < 5) return;
    if (!is_alnum(s[2]) || !is_alnum(s[3]) || !is_alnum(s[4])) return;
    seen_h_ = true;
    const std::string_view code = s.substr(2, 3);
    std::string_view raw = s.substr(5);
    if (auto colon = raw.find(':'); colon != std::string_view::npos) raw.remove_prefix(colon + 1);
    if (code == "DTE") {
      date_record(trim(raw));
      return;
    }
    std::string value = header_text(raw);
    if (value.empty()) return;
    const char* key = header_key(code);
    file_.metadata.fields.emplace_back(key ? std::string(key) : std::string(s.substr(0, 5)), std::move(value));
  }

  // "DDMMYY" or "DDMMYY,NN" (flight number), from HFDTE010123 or HFDTEDATE:010123,01.
  void date_record(std::string_view v) {
    if (date_days_) return;  // the first readable one counts
    std::int64_t d = 0, m = 0, y = 0;
    static constexpr int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool digits_ok = read_digits(v, 0, 2, d) && read_digits(v, 2, 2, m) && read_digits(v, 4, 2, y);
    // digits_ok implies v.size() >= 6; only then may v[6] be looked at.
    const bool tail_ok = digits_ok && (v.size() == 6 || v[6] == ',' || v[6] == ' ');
    if (digits_ok && tail_ok && m >= 1 && m <= 12 && d >= 1 && d <= kDays[m - 1]) {
      const long long year = y >= 80 ? 1900 + y : 2000 + y;
      const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
      if (!(m == 2 && d == 29 && !leap)) {
        date_days_ = days_from_civil(year, static_cast<unsigned>(m), static_cast<unsigned>(d));
        char iso[16];
        iso[0] = static_cast<char>('0' + year / 1000);
        iso[1] = static_cast<char>('0' + year / 100 % 10);
        iso[2] = static_cast<char>('0' + year / 10 % 10);
        iso[3] = static_cast<char>('0' + year % 10);
        iso[4] = '-';
        iso[5] = v[2];
        iso[6] = v[3];
        iso[7] = '-';
        iso[8] = v[0];
        iso[9] = v[1];
        file_.metadata.fields.emplace_back("date", std::string(iso, 10));
        if (v.size() > 7 && v[6] == ',') {
          std::string flight = header_text(v.substr(7));
          if (!flight.empty()) file_.metadata.fields.emplace_back("flight_number", std::move(flight));
        }
        return;
      }
    }
    warnings_.add("date", at(1), "unreadable HFDTE date '" + excerpt(v) + "' ignored (expected DDMMYY)");
  }

  void assign_elevation() {
    using Mode = ReadOptions::IgcAltitude;
    auto& pts = points();
    if (pts.empty()) return;
    const Mode mode = options_.igc_altitude;
    if (mode == Mode::Gnss && !gnss_present_)
      warnings_.add_single({}, "GNSS altitude is 0 on every fix (not recorded): points have no elevation");
    if (mode == Mode::Pressure && !pressure_present_)
      warnings_.add_single({}, "pressure altitude is 0 on every fix (no barometer): points have no elevation");
    if (mode == Mode::Auto && !gnss_present_ && !pressure_present_)
      warnings_.add_single({}, "GNSS and pressure altitude are 0 on every fix: points have no elevation");
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const RawAltitude& a = altitudes_[i];
      double ele = kMissing;
      switch (mode) {
        case Mode::Auto:
          if (a.fix_3d && gnss_present_)
            ele = a.gnss;
          else if (pressure_present_)
            ele = a.pressure;
          break;
        case Mode::Gnss:
          if (gnss_present_ && (a.fix_3d || a.gnss != 0)) ele = a.gnss;
          break;
        case Mode::Pressure:
          if (pressure_present_) ele = a.pressure;
          break;
      }
      pts[i].ele = ele;
    }
  }

  TrackFile& file_;
  WarningCollector& warnings_;
  const ReadOptions& options_;
  std::vector<Extension> extensions_;
  std::vector<RawAltitude> altitudes_;
  std::optional<long long> date_days_;
  std::int64_t line_no_ = 0;
  std::int64_t offset_ = 0;
  std::size_t b_lines_ = 0;
  long long day_ = 0;
  double prev_tod_ = 0.0;
  bool have_prev_ = false;
  bool seen_a_ = false;
  bool seen_h_ = false;
  bool pressure_present_ = false;
  bool gnss_present_ = false;
};

// "Flight 2024-07-14 from Amisbühl": the date and take-off site, never the pilot (IGC headers
// carry personal data), so tables and legends can tell flights apart.
void name_flight(TrackFile& file) {
  if (file.tracks.empty()) return;
  std::string date, site;
  for (const auto& [key, value] : file.metadata.fields) {
    if (key == "date" && date.empty()) date = value;
    if (key == "site" && site.empty()) site = value;
  }
  std::string name = "Flight";
  if (!date.empty()) name += " " + date;
  if (!site.empty()) name += " from " + site;
  file.tracks.front().name = name;
}

}  // namespace

ReadResult read_igc(ByteSource& source, const ReadOptions& options) {
  ReadResult result;
  result.file.format = Format::Igc;
  WarningCollector warnings(source.display_name());
  try {
    result.file.tracks.emplace_back();
    result.file.tracks.front().segments.emplace_back();
    IgcParser parser(result, warnings, options);
    LineReader reader(source, kMaxLine);
    std::string_view line;
    while (reader.next(line)) {
      if (reader.last_line_cut()) {
        parser.long_line(reader.line_number(), reader.line_offset());
        continue;
      }
      parser.line(line, reader.line_number(), reader.line_offset(), reader.last_line_unterminated());
    }
    if (reader.read_failed()) {
      warnings.add_single(SourcePosition{reader.line_number() + 1, 0, -1},
                          "read error: " + source.error() + "; kept the " + std::to_string(parser.points().size()) +
                              " complete points before it");
    }
    parser.finish(result, source.display_name());
    name_flight(result.file);
  } catch (const std::bad_alloc&) {
    result.file.tracks.clear();
    result.error = Diagnostic{source.display_name(), {}, "out of memory while reading the IGC file"};
  }
  finish_read(result, warnings, options);
  return result;
}

}  // namespace trailray::track
