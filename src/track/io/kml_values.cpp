#include "track/io/kml_values.hpp"

#include <cctype>
#include <string>

#include "track/io/parse_util.hpp"
#include "track/model.hpp"

namespace trailray::track {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string lower(std::string_view s) {
  std::string l(s);
  for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return l;
}

}  // namespace

std::optional<AltitudeMode> parse_altitude_mode(std::string_view text) {
  std::string_view t = trim(text);
  if (t == "clampToGround") return AltitudeMode::ClampToGround;
  if (t == "relativeToGround") return AltitudeMode::RelativeToGround;
  if (t == "absolute") return AltitudeMode::Absolute;
  if (t == "clampToSeaFloor") return AltitudeMode::ClampToSeaFloor;
  if (t == "relativeToSeaFloor") return AltitudeMode::RelativeToSeaFloor;
  return std::nullopt;
}

void split_kml_tuples(std::string_view text, std::vector<KmlTuple>& out) {
  const std::size_t n = text.size();
  std::size_t i = 0;
  for (;;) {
    while (i < n && is_space(text[i])) ++i;
    if (i >= n) return;
    KmlTuple tuple;
    tuple.offset = i;
    double parts[3] = {0.0, 0.0, kMissing};
    int count = 0;
    bool readable = true;
    std::size_t end = i;
    for (;;) {
      // One component: up to whitespace or a comma.
      std::size_t start = i;
      while (i < n && !is_space(text[i]) && text[i] != ',') ++i;
      auto v = parse_double(text.substr(start, i - start));
      if (!v || count >= 3)
        readable = false;
      else
        parts[count] = *v;
      ++count;
      end = i;
      // A comma, possibly with whitespace around it, continues the tuple.
      std::size_t j = i;
      while (j < n && is_space(text[j])) ++j;
      if (j >= n || text[j] != ',') break;
      i = j + 1;
      while (i < n && is_space(text[i])) ++i;
      end = i;
    }
    tuple.text = text.substr(tuple.offset, end - tuple.offset);
    if (readable && count >= 2) tuple.value = KmlCoordinate{parts[0], parts[1], parts[2]};
    out.push_back(tuple);
  }
}

std::optional<KmlCoordinate> parse_gx_coord(std::string_view text) {
  double parts[3] = {0.0, 0.0, kMissing};
  int count = 0;
  std::size_t i = 0;
  const std::size_t n = text.size();
  for (;;) {
    while (i < n && (is_space(text[i]) || text[i] == ',')) ++i;
    if (i >= n) break;
    std::size_t start = i;
    while (i < n && !is_space(text[i]) && text[i] != ',') ++i;
    auto v = parse_double(text.substr(start, i - start));
    if (!v || count == 3) return std::nullopt;
    parts[count++] = *v;
  }
  if (count < 2) return std::nullopt;
  return KmlCoordinate{parts[0], parts[1], parts[2]};
}

ArrayChannel array_channel(std::string_view name) {
  if (name.size() > 32) return ArrayChannel::None;
  const std::string n = lower(trim(name));
  if (n == "heartrate" || n == "heart_rate" || n == "hr" || n == "heart rate") return ArrayChannel::HeartRate;
  if (n == "cadence" || n == "cad") return ArrayChannel::Cadence;
  if (n == "power" || n == "watts") return ArrayChannel::Power;
  if (n == "temperature" || n == "temp") return ArrayChannel::Temperature;
  return ArrayChannel::None;
}

}  // namespace trailray::track
