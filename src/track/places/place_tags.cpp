#include "track/places/place_tags.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <system_error>

#include <fast_float/fast_float.h>

#include "track/io/text_output.hpp"

namespace trailray::track::places {

std::string_view kind_name(PlaceKind kind) {
  switch (kind) {
    case PlaceKind::Peak: return "peak";
    case PlaceKind::Volcano: return "volcano";
    case PlaceKind::Saddle: return "saddle";
    case PlaceKind::Pass: return "pass";
    case PlaceKind::AlpineHut: return "alpine_hut";
    case PlaceKind::WildernessHut: return "wilderness_hut";
    case PlaceKind::City: return "city";
    case PlaceKind::Town: return "town";
    case PlaceKind::Village: return "village";
    case PlaceKind::Hamlet: return "hamlet";
    case PlaceKind::Lake: return "lake";
  }
  return "place";
}

std::optional<PlaceKind> classify_place(const PlaceTags& t, bool area) {
  if (t.name.empty()) return std::nullopt;
  // A lake: natural=water that is not a river, canal or the like (those are areas of water too,
  // but "Rhein" is no lake label). Mapped as an area, or as a node where only its name is.
  if (t.natural == "water" &&
      (t.water.empty() || t.water == "lake" || t.water == "reservoir" || t.water == "pond" || t.water == "lagoon"))
    return PlaceKind::Lake;
  if (area) return std::nullopt;
  if (t.natural == "peak") return PlaceKind::Peak;
  if (t.natural == "volcano") return PlaceKind::Volcano;
  if (t.mountain_pass == "yes") return PlaceKind::Pass;
  if (t.natural == "saddle") return PlaceKind::Saddle;
  if (t.tourism == "alpine_hut") return PlaceKind::AlpineHut;
  if (t.tourism == "wilderness_hut") return PlaceKind::WildernessHut;
  if (t.place == "city") return PlaceKind::City;
  if (t.place == "town") return PlaceKind::Town;
  if (t.place == "village") return PlaceKind::Village;
  if (t.place == "hamlet") return PlaceKind::Hamlet;
  return std::nullopt;
}

std::string place_label(const Place& place) {
  std::string name = valid_utf8(place.name);
  const bool with_ele = is_summit(place.kind) || is_hut(place.kind) || place.kind == PlaceKind::Saddle ||
                        place.kind == PlaceKind::Pass;
  if (!with_ele || !std::isfinite(place.ele_m)) return name;
  return name + " " + std::to_string(static_cast<long long>(std::llround(place.ele_m))) + " m";
}

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool equals_lower(std::string_view s, std::string_view lower) {
  if (s.size() != lower.size()) return false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != lower[i]) return false;
  }
  return true;
}

}  // namespace

double parse_ele(std::string_view text) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::string_view s = trim(text);
  if (s.empty() || s.size() > 32) return nan;
  // The number: digits with one '.' or ',' as the decimal separator (49 of Andorra's peaks
  // write "3143,45"), an optional sign.
  std::string number;
  std::size_t i = 0;
  if (s[i] == '-' || s[i] == '+') number += s[i++];
  bool digits = false, separator = false;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (c >= '0' && c <= '9') {
      number += c;
      digits = true;
    } else if ((c == '.' || c == ',') && !separator) {
      number += '.';
      separator = true;
    } else {
      break;
    }
  }
  if (!digits) return nan;
  double value = nan;
  const auto parsed = fast_float::from_chars(number.data(), number.data() + number.size(), value);
  if (parsed.ec != std::errc() || parsed.ptr != number.data() + number.size()) return nan;
  // The unit: none or metres, or feet.
  const std::string_view unit = trim(s.substr(i));
  if (unit.empty() || equals_lower(unit, "m") || equals_lower(unit, "meters") || equals_lower(unit, "metres") ||
      equals_lower(unit, "msl") || equals_lower(unit, "m.s.l.")) {
  } else if (unit == "'" || equals_lower(unit, "ft") || equals_lower(unit, "feet") || equals_lower(unit, "foot")) {
    value *= 0.3048;
  } else {
    return nan;
  }
  // Below the Dead Sea's shore or above Everest by far: a typo, not an elevation.
  if (!std::isfinite(value) || std::fabs(value) > 12000.0) return nan;
  return value;
}

}  // namespace trailray::track::places
