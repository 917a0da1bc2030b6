#include "track/airspace/openair_values.hpp"

#include <cctype>
#include <cmath>
#include <string>

#include "track/io/parse_util.hpp"

namespace trailray::track::airspace {
namespace {

constexpr double kMetresPerFoot = 0.3048;

void skip_spaces(std::string_view& s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
}

// An unsigned decimal number (digits with an optional fraction), consumed from `s`.
std::optional<double> take_number(std::string_view& s) {
  std::size_t n = 0;
  bool digits = false, dot = false;
  while (n < s.size() && (std::isdigit(static_cast<unsigned char>(s[n])) || (s[n] == '.' && !dot))) {
    if (s[n] == '.')
      dot = true;
    else
      digits = true;
    ++n;
  }
  if (!digits || n > 24) return std::nullopt;
  const std::string text(s.substr(0, n));
  s.remove_prefix(n);
  return std::strtod(text.c_str(), nullptr);  // plain digits and one dot: locale-independent enough
}

// D[:M[:S]] or D:M.m then a hemisphere letter from `hemispheres` ("NS" or "EW").
std::optional<double> take_angle(std::string_view& s, const char* hemispheres, double max_deg) {
  skip_spaces(s);
  double parts[3] = {0, 0, 0};
  int count = 0;
  while (count < 3) {
    skip_spaces(s);
    auto v = take_number(s);
    if (!v) return std::nullopt;
    parts[count++] = *v;
    skip_spaces(s);
    if (s.empty() || s.front() != ':') break;
    s.remove_prefix(1);
  }
  skip_spaces(s);
  if (s.empty()) return std::nullopt;
  const char h = static_cast<char>(std::toupper(static_cast<unsigned char>(s.front())));
  if (h != hemispheres[0] && h != hemispheres[1]) return std::nullopt;
  s.remove_prefix(1);
  // 60 minutes or seconds is the next degree or minute: real exports write them (French files by
  // the thousand), and XCSoar reads them so.
  if (parts[1] > 60.0 || parts[2] > 60.0) return std::nullopt;
  const double deg = parts[0] + parts[1] / 60.0 + parts[2] / 3600.0;
  if (!(deg <= max_deg)) return std::nullopt;
  return h == hemispheres[0] ? deg : -deg;
}

std::string upper_words(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == ' ' || c == '\t') continue;  // "FL 65" == "FL65", "100 ft AGL" == "100FTAGL"
    out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}

}  // namespace

std::optional<geo::LatLon> parse_openair_coordinate(std::string_view text, std::string_view* rest) {
  std::string_view s = text;
  auto lat = take_angle(s, "NS", 90.0);
  if (!lat) return std::nullopt;
  skip_spaces(s);
  if (!s.empty() && s.front() == ',') s.remove_prefix(1);  // "lat, lon" in some files
  auto lon = take_angle(s, "EW", 180.0);
  if (!lon) return std::nullopt;
  skip_spaces(s);
  if (rest) *rest = s;
  return geo::LatLon{*lat, *lon};
}

namespace {

// [NS]DDMMSS[.s] or [EW]DDDMMSS[.s].
std::optional<double> take_tnp_angle(std::string_view& s, const char* hemispheres, std::size_t degree_digits,
                                     double max_deg) {
  skip_spaces(s);
  if (s.empty()) return std::nullopt;
  const char h = static_cast<char>(std::toupper(static_cast<unsigned char>(s.front())));
  if (h != hemispheres[0] && h != hemispheres[1]) return std::nullopt;
  s.remove_prefix(1);
  std::size_t n = 0;
  while (n < s.size() && std::isdigit(static_cast<unsigned char>(s[n]))) ++n;
  if (n != degree_digits + 4) return std::nullopt;
  const auto number = [&](std::size_t from, std::size_t count) {
    double v = 0;
    for (std::size_t i = from; i < from + count; ++i) v = v * 10 + (s[i] - '0');
    return v;
  };
  const double deg = number(0, degree_digits), min = number(degree_digits, 2);
  double sec = number(degree_digits + 2, 2);
  s.remove_prefix(n);
  if (!s.empty() && s.front() == '.') {  // decimals of the seconds
    s.remove_prefix(1);
    double scale = 0.1;
    while (!s.empty() && std::isdigit(static_cast<unsigned char>(s.front()))) {
      sec += (s.front() - '0') * scale;
      scale /= 10;
      s.remove_prefix(1);
    }
  }
  if (min > 60.0 || sec > 60.0) return std::nullopt;
  const double v = deg + min / 60.0 + sec / 3600.0;
  if (!(v <= max_deg)) return std::nullopt;
  return h == hemispheres[0] ? v : -v;
}

}  // namespace

std::optional<geo::LatLon> parse_tnp_coordinate(std::string_view text, std::string_view* rest) {
  std::string_view s = text;
  const auto lat = take_tnp_angle(s, "NS", 2, 90.0);
  if (!lat) return std::nullopt;
  const auto lon = take_tnp_angle(s, "EW", 3, 180.0);
  if (!lon) return std::nullopt;
  skip_spaces(s);
  if (rest) *rest = s;
  return geo::LatLon{*lat, *lon};
}

std::optional<AltitudeLimit> parse_openair_altitude(std::string_view text) {
  AltitudeLimit limit;
  limit.text = std::string(trim(text));
  std::string s = upper_words(text);
  if (s == "UNL" || s == "UNLIM" || s == "UNLIMITED") {
    limit.reference = AltitudeReference::Unlimited;
    return limit;
  }
  if (s == "GND" || s == "SFC" || s == "ASFC" || s == "AGL") {
    limit.reference = AltitudeReference::Agl;
    return limit;
  }
  bool flight_level = false;
  if (s.rfind("FL", 0) == 0) {
    flight_level = true;
    s.erase(0, 2);
  }
  std::string_view v = s;
  auto number = take_number(v);
  if (!number) return std::nullopt;
  if (flight_level) {
    if (!v.empty()) return std::nullopt;
    limit.reference = AltitudeReference::Std;
    limit.metres = *number * 100.0 * kMetresPerFoot;
    return limit;
  }
  double unit = kMetresPerFoot;  // OpenAir's default unit
  auto eat = [&v](std::string_view word) {
    if (v.substr(0, word.size()) != word) return false;
    v.remove_prefix(word.size());
    return true;
  };
  if (eat("FT")) {
    unit = kMetresPerFoot;
  } else if (v.substr(0, 3) != "MSL" && eat("M")) {
    unit = 1.0;
  }
  limit.metres = *number * unit;
  if (v.empty() || v == "MSL" || v == "AMSL" || v == "ALT") {
    limit.reference = AltitudeReference::Msl;
  } else if (v == "AGL" || v == "GND" || v == "SFC" || v == "ASFC" || v == "AAL") {
    limit.reference = AltitudeReference::Agl;
  } else if (v == "STD") {
    limit.reference = AltitudeReference::Std;
  } else {
    return std::nullopt;
  }
  return limit;
}

}  // namespace trailray::track::airspace
