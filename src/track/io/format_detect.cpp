#include "track/io/format_detect.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

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
  if (p.ends_with(".fit")) return Format::Fit;
  if (p.ends_with(".kml")) return Format::Kml;
  if (p.ends_with(".kmz")) return Format::Kmz;
  if (p.ends_with(".geojson") || p.ends_with(".json")) return Format::GeoJson;
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

// FIT: a header of 12 or 14 bytes whose bytes 8..11 are ".FIT".
bool is_fit(std::string_view head) {
  return head.size() >= 12 && (head[0] == 12 || head[0] == 14) && head.substr(8, 4) == ".FIT";
}

// A zip archive (KMZ): a local file header first.
bool is_zip(std::string_view head) {
  return head.size() >= 4 && head.substr(0, 4) == std::string_view("PK\x03\x04", 4);
}

}  // namespace

std::optional<Format> detect_format(std::string_view head, const std::string& path) {
  if (is_fit(head)) return Format::Fit;
  if (is_zip(head)) return Format::Kmz;
  std::string s = ascii_view(head);
  std::size_t i = 0;
  // BOMs: UTF-8 EF BB BF, UTF-16 FF FE / FE FF.
  while (i < s.size() && (static_cast<unsigned char>(s[i]) >= 0xEF || std::isspace(static_cast<unsigned char>(s[i]))))
    ++i;
  if (i < s.size() && s[i] == '<') {
    // XML: the root element decides. Look past the declaration, comments and doctype.
    std::string l = lower(s.substr(i));
    // The root that appears first wins (a KML may mention "gpx" further down, or the reverse).
    std::optional<Format> root;
    std::size_t root_at = std::string::npos;
    for (auto [mark, format] :
         {std::pair{"<trainingcenterdatabase", Format::Tcx}, std::pair{"<gpx", Format::Gpx},
          std::pair{":gpx", Format::Gpx}, std::pair{"<kml", Format::Kml}, std::pair{":kml", Format::Kml}}) {
      const std::size_t at = l.find(mark);
      if (at < root_at) root_at = at, root = format;
    }
    if (root) return root;
    auto by_name = format_from_name(path);
    if (by_name && *by_name != Format::Igc) return by_name;
    return Format::Gpx;  // unknown XML: the GPX reader says what the root is
  }
  // JSON: GeoJSON is the only JSON format read (its reader says what else it is).
  if (i < s.size() && s[i] == '{') return Format::GeoJson;
  // IGC: records are lines starting with an upper-case letter; the A record comes first.
  if (i < s.size() && s[i] == 'A') {
    if (s.find("\nB") != std::string::npos || s.find("\nH") != std::string::npos || s.size() < 4096) return Format::Igc;
  }
  return format_from_name(path);
}

}  // namespace trailray::track
