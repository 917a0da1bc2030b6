// IGC field readers (igc_fields.hpp).

#include "track/io/igc_fields.hpp"

#include <array>
#include <utility>

#include "geo/utf8.hpp"
#include "track/io/parse_util.hpp"

namespace trailray::track::detail {

bool numeric_extension(std::string_view v) {
  std::size_t i = 0;
  while (i < v.size() && v[i] == ' ') ++i;
  if (i < v.size() && (v[i] == '-' || v[i] == '+')) ++i;
  if (i == v.size()) return false;
  for (; i < v.size(); ++i)
    if (!is_digit(v[i])) return false;
  return true;
}

std::string excerpt(std::string_view s) {
  std::string out(s.substr(0, 40));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  if (s.size() > 40) out += "...";
  return out;
}

std::string header_text(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  const bool utf8 = geo::is_valid_utf8(s);
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

}  // namespace trailray::track::detail
