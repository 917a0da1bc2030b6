// IGC record parsing: B (fixes), I (B-record extensions), A (recorder) and H (headers,
// HFDTE date) records, each line into the parser's track and metadata.

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

#include "track/io/igc_fields.hpp"
#include "track/io/igc_parser.hpp"
#include "track/io/parse_util.hpp"
#include "track/io/readers.hpp"

namespace trailray::track::detail {
namespace {

constexpr double kRolloverSeconds = 12 * 3600.0;

}  // namespace

// The line dispatch lives with the record parsers, so each B record's parsing is inlined into
// it (a B record per second of flight).
void IgcParser::line(std::string_view s, std::int64_t line_no, std::int64_t offset, bool last_unterminated) {
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

void IgcParser::b_record(std::string_view s) {
  if (s.size() < kBaseLength) {
    drop("b-short", 1,
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

void IgcParser::i_record(std::string_view s) {
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

void IgcParser::a_record(std::string_view s) {
  seen_a_ = true;
  if (const char* maker = manufacturer_name(s.substr(1, 3))) {
    const std::string id = header_text(s.substr(4));
    file_.metadata.creator = id.empty() ? std::string(maker) : std::string(maker) + " " + id;
  } else {
    file_.metadata.creator = header_text(s.substr(1));
  }
}

void IgcParser::h_record(std::string_view s) {
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

void IgcParser::date_record(std::string_view v) {
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

}  // namespace trailray::track::detail
