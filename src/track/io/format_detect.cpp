#include "track/io/format_detect.hpp"

#include <algorithm>
#include <cctype>

namespace trailray::track {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The name's format extension, ignoring a trailing ".gz".
std::optional<Format> format_from_name(const std::string& path) {
  std::string p = lower(path);
  if (p.size() > 3 && p.ends_with(".gz")) p.resize(p.size() - 3);
  if (p.ends_with(".gpx")) return Format::Gpx;
  if (p.ends_with(".igc")) return Format::Igc;
  if (p.ends_with(".tcx")) return Format::Tcx;
  return std::nullopt;
}

// UTF-16 text: drop every NUL so that ASCII markup can be searched.
std::string ascii_view(std::string_view head) {
  std::string s;
  s.reserve(head.size());
  for (char c : head)
    if (c != '\0') s.push_back(c);
  return s;
}

}  // namespace

std::optional<Format> detect_format(std::string_view head, const std::string& path) {
  std::string s = ascii_view(head);
  std::size_t i = 0;
  // BOMs: UTF-8 EF BB BF, UTF-16 FF FE / FE FF.
  while (i < s.size() && (static_cast<unsigned char>(s[i]) >= 0xEF || std::isspace(static_cast<unsigned char>(s[i]))))
    ++i;
  if (i < s.size() && s[i] == '<') {
    // XML: the root element decides. Look past the declaration, comments and doctype.
    std::string l = lower(s.substr(i));
    if (l.find("<trainingcenterdatabase") != std::string::npos) return Format::Tcx;
    if (l.find("<gpx") != std::string::npos || l.find(":gpx") != std::string::npos) return Format::Gpx;
    auto by_name = format_from_name(path);
    if (by_name && *by_name != Format::Igc) return by_name;
    return Format::Gpx;  // unknown XML: the GPX reader says what the root is
  }
  // IGC: records are lines starting with an upper-case letter; the A record comes first.
  if (i < s.size() && s[i] == 'A') {
    if (s.find("\nB") != std::string::npos || s.find("\nH") != std::string::npos || s.size() < 4096) return Format::Igc;
  }
  return format_from_name(path);
}

}  // namespace trailray::track
