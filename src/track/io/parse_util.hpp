#pragma once
// Small locale-independent parsers shared by the readers.

#include <optional>
#include <string_view>

namespace trailray::track {

// Trims ASCII whitespace at both ends.
std::string_view trim(std::string_view s);

// A finite decimal number ("12", "-3.5", "1e3", leading '+' allowed), surrounding
// whitespace ignored; nullopt for anything else, including NaN and infinities. Correctly
// rounded.
std::optional<double> parse_double(std::string_view s);

// ISO 8601 / XML Schema dateTime to seconds since the Unix epoch, UTC.
// Accepts "2023-05-06T09:45:34Z", fractional seconds, "+02:00"/"-0530" offsets,
// a space instead of 'T', and no zone (taken as UTC, as GPX requires).
std::optional<double> parse_iso8601(std::string_view s);

// Days since 1970-01-01 of a proleptic Gregorian date (no validation).
long long days_from_civil(long long y, unsigned m, unsigned d);

}  // namespace trailray::track
