#include "app/serve/request_path.hpp"

namespace trailray::app::serve {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// One segment between slashes, decoded; an error message when it cannot stand for a name.
std::string decode_segment(std::string_view raw, std::string& out) {
  out.clear();
  for (std::size_t i = 0; i < raw.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(raw[i]);
    if (c == '%') {
      if (i + 2 >= raw.size()) return "truncated percent escape";
      const int hi = hex_value(raw[i + 1]), lo = hex_value(raw[i + 2]);
      if (hi < 0 || lo < 0) return "malformed percent escape";
      c = static_cast<unsigned char>(hi * 16 + lo);
      i += 2;
      if (c == '/') return "encoded slash in a path segment";
    }
    if (c == '\\') return "backslash in the path";
    if (c < 0x20 || c == 0x7f) return "control character in the path";
    out.push_back(static_cast<char>(c));
  }
  if (out == "." || out == "..") return "dot segment in the path";
  return {};
}

}  // namespace

ParsedTarget parse_request_target(std::string_view target) {
  ParsedTarget parsed;
  const std::size_t end = target.find_first_of("?#");
  const std::string_view path = target.substr(0, end);
  if (path.empty() || path.front() != '/') {
    parsed.error = "the target is not a path from the root";
    return parsed;
  }
  std::string segment;
  std::size_t start = 1;
  while (start <= path.size()) {
    const std::size_t slash = path.find('/', start);
    const std::string_view raw = path.substr(start, slash == std::string_view::npos ? path.npos : slash - start);
    const bool last = slash == std::string_view::npos;
    if (raw.empty()) {
      if (!last) {
        parsed.error = "empty segment in the path";
        return parsed;
      }
      parsed.path.trailing_slash = !parsed.path.segments.empty();
      break;
    }
    if (std::string error = decode_segment(raw, segment); !error.empty()) {
      parsed.error = std::move(error);
      return parsed;
    }
    parsed.path.segments.push_back(segment);
    if (last) break;
    start = slash + 1;
  }
  return parsed;
}

std::optional<std::uint32_t> parse_segment_number(std::string_view segment) {
  if (segment.empty() || segment.size() > 10 || (segment.size() > 1 && segment.front() == '0')) return std::nullopt;
  std::uint64_t value = 0;
  for (const char c : segment) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  if (value > 0xffffffffu) return std::nullopt;
  return static_cast<std::uint32_t>(value);
}

std::optional<PhotoRequest> parse_photo_path(const RequestPath& path, std::size_t count) {
  const auto& s = path.segments;
  if (path.trailing_slash || s.size() < 3 || s.size() > 4 || s[0] != "api" || s[1] != "photos") return std::nullopt;
  std::optional<std::uint32_t> index;
  bool large = false;
  if (s.size() == 3) {
    const std::string_view file = s[2];
    if (!file.ends_with(".jpg")) return std::nullopt;
    index = parse_segment_number(file.substr(0, file.size() - 4));
  } else {
    if (s[3] != "large.jpg") return std::nullopt;
    index = parse_segment_number(s[2]);
    large = true;
  }
  if (!index || *index >= count) return std::nullopt;
  return PhotoRequest{*index, large};
}

}  // namespace trailray::app::serve
