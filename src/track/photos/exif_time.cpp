#include "track/photos/exif_time.hpp"

#include <cstdlib>

#include "track/io/parse_util.hpp"

namespace trailray::track {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string_view trimmed(std::string_view s) {
  auto blank = [](char c) { return c == ' ' || c == '\0' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// `count` digits at s[pos] as a number; -1 when they are not all digits.
int digits_at(std::string_view s, std::size_t pos, std::size_t count) {
  if (pos + count > s.size()) return -1;
  int v = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (!is_digit(s[pos + i])) return -1;
    v = v * 10 + (s[pos + i] - '0');
  }
  return v;
}

constexpr int kMaxOffsetS = 14 * 3600;

}  // namespace

std::optional<int> parse_utc_offset(std::string_view text) {
  const std::string_view s = trimmed(text);
  if (s == "Z" || s == "z") return 0;
  if (s.size() < 3 || (s[0] != '+' && s[0] != '-')) return std::nullopt;
  const int sign = s[0] == '-' ? -1 : 1;
  const int hours = digits_at(s, 1, 2);
  int minutes = 0;
  if (s.size() == 3) {
    minutes = 0;
  } else if (s.size() == 6 && s[3] == ':') {
    minutes = digits_at(s, 4, 2);
  } else if (s.size() == 5) {
    minutes = digits_at(s, 3, 2);
  } else {
    return std::nullopt;
  }
  if (hours < 0 || minutes < 0 || minutes >= 60) return std::nullopt;
  const int offset = sign * (hours * 3600 + minutes * 60);
  if (offset > kMaxOffsetS || offset < -kMaxOffsetS) return std::nullopt;
  return offset;
}

std::string format_utc_offset(int offset_s) {
  const int minutes = (offset_s >= 0 ? offset_s + 30 : offset_s - 30) / 60;
  const int a = std::abs(minutes);
  std::string out(1, minutes < 0 ? '-' : '+');
  out += static_cast<char>('0' + a / 600 % 10);
  out += static_cast<char>('0' + a / 60 % 10);
  out += ':';
  out += static_cast<char>('0' + a % 60 / 10);
  out += static_cast<char>('0' + a % 10);
  return out;
}

std::optional<double> parse_exif_subseconds(std::string_view text) {
  const std::string_view s = trimmed(text);
  if (s.empty() || s.size() > 9) return std::nullopt;
  double v = 0, scale = 0.1;
  for (char c : s) {
    if (!is_digit(c)) return std::nullopt;
    v += (c - '0') * scale;
    scale *= 0.1;
  }
  return v;
}

std::optional<ExifDateTime> parse_exif_datetime(std::string_view text) {
  const std::string_view s = trimmed(text);
  // "YYYY:MM:DD HH:MM:SS" is 19 characters.
  if (s.size() < 19) return std::nullopt;
  const int year = digits_at(s, 0, 4), month = digits_at(s, 5, 2), day = digits_at(s, 8, 2);
  const int hour = digits_at(s, 11, 2), minute = digits_at(s, 14, 2), second = digits_at(s, 17, 2);
  const bool date_seps = (s[4] == ':' || s[4] == '-') && s[7] == s[4];
  const bool time_seps = (s[10] == ' ' || s[10] == 'T') && s[13] == ':' && s[16] == ':';
  if (!date_seps || !time_seps || year < 0 || month < 0 || day < 0 || hour < 0 || minute < 0 || second < 0)
    return std::nullopt;
  // "0000:00:00 00:00:00" is what some cameras write for "not set".
  if (year == 0 || month < 1 || month > 12 || day < 1 || day > 31 || hour > 23 || minute > 59 || second > 60)
    return std::nullopt;
  static constexpr int kDaysInMonth[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  if (day > kDaysInMonth[month - 1] || (month == 2 && day == 29 && !leap)) return std::nullopt;
  ExifDateTime out;
  out.local_s = static_cast<double>(days_from_civil(year, static_cast<unsigned>(month), static_cast<unsigned>(day))) *
                    86400.0 +
                hour * 3600.0 + minute * 60.0 + second;
  std::string_view rest = s.substr(19);
  if (!rest.empty() && (rest.front() == '.' || rest.front() == ',')) {
    std::size_t n = 1;
    while (n < rest.size() && is_digit(rest[n])) ++n;
    const std::optional<double> fraction = parse_exif_subseconds(rest.substr(1, n - 1));
    if (!fraction) return std::nullopt;
    out.local_s += *fraction;
    out.has_fraction = true;
    rest.remove_prefix(n);
  }
  rest = trimmed(rest);
  if (!rest.empty()) {
    out.offset_s = parse_utc_offset(rest);
    if (!out.offset_s) return std::nullopt;
  }
  return out;
}

}  // namespace trailray::track
