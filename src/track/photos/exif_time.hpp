#pragma once
// EXIF's time strings, parsed without exiv2 (the reader hands them over as text): DateTimeOriginal
// "YYYY:MM:DD HH:MM:SS", which some cameras write with fractions and a zone inside
// ("2019:04:30 15:56:18.605+00:00"), SubSecTimeOriginal ("606"), OffsetTimeOriginal ("+02:00"),
// and the `--photo-tz` option's "+HH:MM". Pure functions: the browser build compiles them too.

#include <optional>
#include <string>
#include <string_view>

namespace trailray::track {

struct ExifDateTime {
  double local_s = 0;            // the wall clock as seconds since 1970, read as if it were UTC
  bool has_fraction = false;     // the field carried its own fraction of a second
  std::optional<int> offset_s;   // a zone written inside the field ("Z", "+02:00", "-0500")
};

// "YYYY:MM:DD HH:MM:SS" ('-' also between the date's parts, 'T' also between date and time), then
// optionally ".fff" and a zone; surrounding spaces and NULs ignored. nullopt for an empty field,
// EXIF's "unknown" (spaces and colons only, "0000:00:00 00:00:00") or anything malformed
// (month 13, 25 o'clock, trailing text).
std::optional<ExifDateTime> parse_exif_datetime(std::string_view text);

// SubSecTime*: the digits of a decimal fraction ("606" -> 0.606, "41" -> 0.41); nullopt when
// empty or not digits (spaces around are allowed).
std::optional<double> parse_exif_subseconds(std::string_view text);

// OffsetTime* and --photo-tz: "+HH:MM", "-HH:MM", "+HHMM", "+HH", "Z" -> seconds east of UTC;
// nullopt when malformed or beyond +-14:00 (spaces around are allowed).
std::optional<int> parse_utc_offset(std::string_view text);

// "+02:00", "-05:30" for an offset in seconds (rounded to minutes).
std::string format_utc_offset(int offset_s);

}  // namespace trailray::track
