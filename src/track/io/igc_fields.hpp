#pragma once
// Field readers for IGC records, internal to the IGC reader: fixed-width digits and
// altitudes, extension values, header text, and the names behind H-record and A-record codes.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace trailray::track::detail {

bool is_alnum(char c);

// Exactly `n` digits at s[pos..pos+n) as an unsigned number; false for anything else.
bool read_digits(std::string_view s, std::size_t pos, std::size_t n, std::int64_t& out);

// A 5-character altitude field: digits, or '-' then digits ("-0012").
bool read_altitude(std::string_view s, std::size_t pos, std::int64_t& out);

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
