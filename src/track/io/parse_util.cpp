#include "track/io/parse_util.hpp"

#include <fast_float/fast_float.h>
#include <algorithm>

#include <charconv>
#include <cmath>
#include <cstdint>

namespace trailray::track {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Reads exactly `n` digits at s[pos]; advances pos.
bool digits(std::string_view s, std::size_t& pos, int n, int& out) {
  if (pos + static_cast<std::size_t>(n) > s.size()) return false;
  int v = 0;
  for (int i = 0; i < n; ++i) {
    char c = s[pos + static_cast<std::size_t>(i)];
    if (!is_digit(c)) return false;
    v = v * 10 + (c - '0');
  }
  pos += static_cast<std::size_t>(n);
  out = v;
  return true;
}

}  // namespace

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::optional<double> parse_double(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;

  double v = 0.0;
  // fast_float: correctly rounded like std::from_chars, several times faster on the long
  // decimals Garmin writes ("47.05000556074082851409912109375").
  auto [ptr, ec] = fast_float::from_chars(s.data(), s.data() + s.size(), v, fast_float::chars_format::general);
  if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

long long days_from_civil(long long y, unsigned m, unsigned d) {
  // Howard Hinnant's algorithm.
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

std::optional<double> parse_iso8601(std::string_view s) {
  s = trim(s);
  std::size_t p = 0;
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0;
  if (!digits(s, p, 4, year)) return std::nullopt;
  if (p >= s.size() || s[p++] != '-' || !digits(s, p, 2, month)) return std::nullopt;
  if (p >= s.size() || s[p++] != '-' || !digits(s, p, 2, day)) return std::nullopt;
  if (month < 1 || month > 12 || day < 1 || day > 31) return std::nullopt;
  double frac = 0.0;
  if (p < s.size() && (s[p] == 'T' || s[p] == 't' || s[p] == ' ')) {
    ++p;
    if (!digits(s, p, 2, hour)) return std::nullopt;
    if (p >= s.size() || s[p++] != ':' || !digits(s, p, 2, minute)) return std::nullopt;
    if (p < s.size() && s[p] == ':') {
      ++p;
      if (!digits(s, p, 2, second)) return std::nullopt;
      if (p < s.size() && (s[p] == '.' || s[p] == ',')) {
        ++p;
        double scale = 0.1;
        std::size_t start = p;
        while (p < s.size() && is_digit(s[p])) {
          frac += (s[p] - '0') * scale;
          scale *= 0.1;
          ++p;
        }
        if (p == start) return std::nullopt;
      }
    }
    // 24:00:00 is allowed by ISO 8601 as the end of the day; leap second 60 is clamped.
    if (hour > 24 || minute > 59 || second > 60) return std::nullopt;
  }
  int offset_s = 0;
  if (p < s.size()) {
    char z = s[p];
    if (z == 'Z' || z == 'z') {
      ++p;
    } else if (z == '+' || z == '-') {
      ++p;
      int oh = 0, om = 0;
      if (!digits(s, p, 2, oh)) return std::nullopt;
      if (p < s.size() && s[p] == ':') ++p;
      if (p < s.size() && !digits(s, p, 2, om)) return std::nullopt;
      if (oh > 23 || om > 59) return std::nullopt;
      offset_s = (oh * 3600 + om * 60) * (z == '+' ? 1 : -1);
    }
  }
  if (p != s.size()) return std::nullopt;
  long long days = days_from_civil(year, static_cast<unsigned>(month), static_cast<unsigned>(day));
  double t =
      static_cast<double>(days) * 86400.0 + hour * 3600.0 + minute * 60.0 + std::min(second, 59) + frac - offset_s;
  return t;
}

}  // namespace trailray::track
