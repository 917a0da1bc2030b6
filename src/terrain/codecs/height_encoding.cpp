#include "terrain/codecs/height_encoding.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace trailray::terrain {

namespace {

// Names come from metadata files and command lines: compare without regard to case or
// surrounding blanks ("Terrarium", " mapbox\n").
std::string normalized(std::string_view name) {
  const auto blank = [](unsigned char c) { return std::isspace(c) != 0; };
  while (!name.empty() && blank(static_cast<unsigned char>(name.front()))) name.remove_prefix(1);
  while (!name.empty() && blank(static_cast<unsigned char>(name.back()))) name.remove_suffix(1);
  std::string out(name);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

std::optional<HeightEncoding> parse_height_encoding(std::string_view name) {
  const std::string n = normalized(name);
  if (n == "terrarium") return HeightEncoding::terrarium;
  if (n == "mapbox" || n == "terrain-rgb" || n == "mapbox-terrain-rgb") return HeightEncoding::mapbox;
  if (n == "alpinemaps") return HeightEncoding::alpinemaps;
  if (n == "float" || n == "float32") return HeightEncoding::float32;
  return std::nullopt;
}

std::string_view to_string(HeightEncoding encoding) {
  switch (encoding) {
    case HeightEncoding::terrarium:
      return "terrarium";
    case HeightEncoding::mapbox:
      return "mapbox";
    case HeightEncoding::alpinemaps:
      return "alpinemaps";
    case HeightEncoding::float32:
      return "float";
  }
  return "?";
}

}  // namespace trailray::terrain
