#include "track/scoring/fixes.hpp"

#include "track/io/load.hpp"
#include "track/io/parse_util.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

namespace trailray::track::scoring {
namespace {

bool digits(const std::string& s, std::size_t pos, std::size_t n, long& out) {
  if (pos + n > s.size()) return false;
  long v = 0;
  for (std::size_t i = pos; i < pos + n; ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    v = v * 10 + (s[i] - '0');
  }
  out = v;
  return true;
}

bool signed_altitude(const std::string& s, std::size_t pos, int& out) {
  if (pos + 5 > s.size()) return false;
  long v = 0;
  if (s[pos] == '-') {
    if (!digits(s, pos + 1, 4, v)) return false;
    out = -static_cast<int>(v);
    return true;
  }
  if (!digits(s, pos, 5, v)) return false;
  out = static_cast<int>(v);
  return true;
}

}  // namespace

FixList parse_scoring_fixes(const std::string& text, const std::string& name) {
  FixList out;
  std::istringstream in(text);
  std::string line;
  std::size_t line_no = 0;
  double day0 = 0.0;  // seconds of the HFDTE date at 00:00 UTC
  double prev_time = -1e300;
  bool have_prev = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("HFDTE", 0) == 0) {
      // "HFDTE150619" or "HFDTEDATE:150619,01"
      const std::size_t colon = line.find(':');
      const std::size_t pos = colon == std::string::npos ? 5 : colon + 1;
      long dd = 0, mm = 0, yy = 0;
      if (digits(line, pos, 2, dd) && digits(line, pos + 2, 2, mm) && digits(line, pos + 4, 2, yy) && mm >= 1 &&
          mm <= 12 && dd >= 1 && dd <= 31)
        day0 = 86400.0 * static_cast<double>(days_from_civil(yy < 80 ? 2000 + yy : 1900 + yy,
                                                             static_cast<unsigned>(mm), static_cast<unsigned>(dd)));
      continue;
    }
    if (line.empty() || line[0] != 'B') continue;
    ++out.b_records;
    long hh = 0, mi = 0, ss = 0, lat_d = 0, lat_m = 0, lon_d = 0, lon_m = 0;
    int p_alt = 0, g_alt = 0;
    if (line.size() < 35 || !digits(line, 1, 2, hh) || !digits(line, 3, 2, mi) || !digits(line, 5, 2, ss) ||
        !digits(line, 7, 2, lat_d) || !digits(line, 9, 5, lat_m) || !digits(line, 15, 3, lon_d) ||
        !digits(line, 18, 5, lon_m) || (line[14] != 'N' && line[14] != 'S') || (line[23] != 'E' && line[23] != 'W') ||
        !signed_altitude(line, 25, p_alt) || !signed_altitude(line, 30, g_alt)) {
      out.error = name + ":" + std::to_string(line_no) + ": malformed B record";
      return out;
    }
    double t = day0 + static_cast<double>(hh * 3600 + mi * 60 + ss);
    // As igc-parser: a time more than an hour before the previous one belongs to the next day.
    while (have_prev && t < prev_time - 3600.0) t += 86400.0;
    prev_time = t;
    have_prev = true;
    if (line[24] != 'A') continue;  // 'V': no 3D fix, not a scoring fix
    double lat = static_cast<double>(lat_d) + static_cast<double>(lat_m) / 60000.0;
    double lon = static_cast<double>(lon_d) + static_cast<double>(lon_m) / 60000.0;
    if (line[14] == 'S') lat = -lat;
    if (line[23] == 'W') lon = -lon;
    if (lat > 90.0 || lon > 180.0) {
      out.error = name + ":" + std::to_string(line_no) + ": B record position out of range";
      return out;
    }
    if (!out.fixes.empty() && out.fixes.back().time == t) continue;  // same second as the last kept fix
    out.fixes.push_back(Fix{lat, lon, t, g_alt, p_alt});
  }
  if (out.b_records == 0) out.error = name + ": no B records (not an IGC flight log?)";
  return out;
}

FixList read_scoring_fixes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    FixList out;
    out.error = path + ": cannot open file";
    return out;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  return parse_scoring_fixes(ss.str(), path);
}

FixList fixes_of_track(const Track& track) {
  FixList list;
  const auto metres = [](double v) { return std::isfinite(v) ? static_cast<int>(std::lround(v)) : 0; };
  for (const Segment& s : track.segments)
    for (const TrackPoint& p : s.points) {
      if (!p.has_time() || !std::isfinite(p.lat) || !std::isfinite(p.lon)) continue;
      ++list.b_records;
      if (!list.fixes.empty() && list.fixes.back().time >= p.time) continue;
      const double gnss = p.has_gnss_altitude() ? static_cast<double>(p.gnss_altitude) : p.ele;
      list.fixes.push_back(Fix{p.lat, p.lon, p.time, metres(gnss), metres(static_cast<double>(p.pressure_altitude))});
    }
  return list;
}

FixList read_any_scoring_fixes(const std::string& path) {
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower.ends_with(".igc")) return read_scoring_fixes(path);
  const ReadResult r = load_track_file(path);
  FixList best;
  if (r.error) {
    best.error = r.error->to_string();
    return best;
  }
  for (const Track& t : r.file.tracks) {
    FixList list = fixes_of_track(t);
    if (list.fixes.size() > best.fixes.size()) best = std::move(list);
  }
  return best;
}

}  // namespace trailray::track::scoring
