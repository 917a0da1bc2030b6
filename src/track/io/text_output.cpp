#include "track/io/text_output.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>

#include <fmt/format.h>

#include "geo/utf8.hpp"

namespace trailray::track {

// fmt's shortest round-trip form (Dragonbox): exact, and an order of magnitude faster than
// trying printf precisions until one reads back.
std::string format_number(double v) {
  if (!std::isfinite(v)) return "0";  // callers write only finite values; never "nan" in a file
  return fmt::format("{}", v);
}

std::string format_number(float v) {
  if (!std::isfinite(v)) return "0";
  return fmt::format("{}", v);
}

std::string format_iso_time(double t) {
  const double ms_total = std::round(t * 1000.0);
  const double whole = std::floor(ms_total / 1000.0);
  const auto millis = static_cast<long>(ms_total - whole * 1000.0);
  const auto seconds = static_cast<std::time_t>(whole);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  std::string out = buf;
  if (millis > 0) {
    std::snprintf(buf, sizeof buf, ".%03ld", millis);
    out += buf;
  }
  return out + "Z";
}

// Each byte that does not start a valid sequence becomes one U+FFFD.
std::string valid_utf8(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  std::size_t i = 0;
  while (i < s.size()) {
    const geo::Utf8Step step = geo::next_utf8(s.substr(i));
    if (step.valid) {
      out.append(s.substr(i, step.length));
      i += step.length;
    } else {
      geo::append_utf8(out, geo::kReplacementCharacter);
      ++i;
    }
  }
  return out;
}

std::string xml_escape(std::string_view raw) {
  const std::string s = valid_utf8(raw);
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        // XML 1.0 has no way to write other control characters.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r')
          out += ' ';
        else
          out += c;
    }
  }
  return out;
}

std::string json_string(std::string_view raw) {
  const std::string s = valid_utf8(raw);
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string csv_field(std::string_view raw) {
  const std::string s = valid_utf8(raw);
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace trailray::track
