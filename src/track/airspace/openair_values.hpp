#pragma once
// The values inside OpenAir records: coordinates and vertical limits. Each returns nullopt for
// text it cannot read (the reader turns that into an error naming the line).

#include <optional>
#include <string_view>

#include "geo/web_mercator.hpp"
#include "track/airspace/airspace.hpp"

namespace trailray::track::airspace {

// "43:38:59 N 008:01:50 E", "01:05.5 N 000:05.5 E", "47:30:00.5N 7:15:00E", "46.5 N 7.25 E":
// degrees, then minutes and seconds (D:M:S, seconds may have decimals) or decimal minutes (D:M.m),
// then N/S, the same for the longitude with E/W. `rest` gets what follows the coordinate.
std::optional<geo::LatLon> parse_openair_coordinate(std::string_view text, std::string_view* rest = nullptr);

// "GND", "SFC", "0", "1000 ft", "1000ft MSL", "2500FT AMSL", "100 Agl", "100m GND", "FL 65",
// "FL65", "5000 STD", "UNL", "UNLIM", "UNLIMITED". No unit means feet; no reference means MSL;
// "N GND"/"N SFC" mean N above the ground; "N STD" is a pressure altitude in feet (as FL N/100).
std::optional<AltitudeLimit> parse_openair_altitude(std::string_view text);

// A TNP (Tim Newport-Peace, .sua) coordinate pair: "N013030 W0013030" (hemisphere, then
// DDMMSS and DDDMMSS, seconds may have decimals; 60 carries over as in OpenAir). `rest` gets what
// follows.
std::optional<geo::LatLon> parse_tnp_coordinate(std::string_view text, std::string_view* rest = nullptr);

}  // namespace trailray::track::airspace
