#pragma once
// Text shared by the writers (GPX, GeoJSON, CSV, KML): numbers that read back exactly, UTC
// times, and escaping for XML, JSON and CSV.

#include <string>
#include <string_view>

namespace trailray::track {

// The shortest text that reads back as the same double (46.7, not 46.700000000000003): 1e-7
// degree and better survive a round trip, as does every recorded value.
std::string format_number(double v);
// The same for a recorded channel kept as float (23.1f is "23.1", not "23.100000381469727").
std::string format_number(float v);

// ISO 8601 UTC ("2024-06-01T10:00:00Z"), with milliseconds only when the time has a fraction
// ("...:00.250Z"); rounded to the millisecond.
std::string format_iso_time(double seconds_since_epoch);

// `s` with every byte sequence that is not UTF-8 replaced by U+FFFD (JSON and XML must be
// UTF-8; names from old files may be Latin-1 bytes).
std::string valid_utf8(std::string_view s);

std::string xml_escape(std::string_view s);
// A JSON string literal, quotes included.
std::string json_string(std::string_view s);
// A CSV field (RFC 4180): quoted when it holds a comma, quote or line end.
std::string csv_field(std::string_view s);

}  // namespace trailray::track
