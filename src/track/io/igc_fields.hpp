#pragma once
// Field readers for IGC records, internal to the IGC reader: fixed-width digits and
// altitudes, extension values, header text, and the names behind H-record and A-record codes.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace trailray::track::detail {

// The readers of every fix's fields are inline: they run for each B record (tens of thousands a
// file), where a call into another translation unit costs more than the reading.
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

inline bool is_alnum(char c) { return is_digit(c) || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// Exactly `n` digits at s[pos..pos+n) as an unsigned number; false for anything else.
inline bool read_digits(std::string_view s, std::size_t pos, std::size_t n, std::int64_t& out) {
  if (pos > s.size() || n > s.size() - pos) return false;
  std::int64_t v = 0;
  for (std::size_t i = pos; i < pos + n; ++i) {
    if (!is_digit(s[i])) return false;
    v = v * 10 + (s[i] - '0');
  }
  out = v;
  return true;
}

// A 5-character altitude field: digits, or '-' then digits ("-0012").
inline bool read_altitude(std::string_view s, std::size_t pos, std::int64_t& out) {
  if (pos + 5 > s.size()) return false;
  if (s[pos] == '-') {
    std::int64_t v = 0;
    if (!read_digits(s, pos + 1, 4, v)) return false;
    out = -v;
    return true;
  }
  return read_digits(s, pos, 5, out);
}

// An extension value: optional leading spaces, an optional sign, then only digits.
bool numeric_extension(std::string_view v);

// Printable excerpt of a field for a message: at most 40 bytes, control bytes as '?'.
std::string excerpt(std::string_view s);

// Header text as UTF-8: kept when it is valid UTF-8, otherwise read as Latin-1 (older
// recorders); control characters become spaces.
std::string header_text(std::string_view s);

// H-record three-letter codes -> metadata field keys.
const char* header_key(std::string_view code);

// A-record manufacturer codes (three-letter, plus the common unofficial X codes).
const char* manufacturer_name(std::string_view code);

}  // namespace trailray::track::detail
