#pragma once
// Launch and landing detection as the rule sets' reference scorer does it (igc-xc-score's
// trim): 10 s moving averages of ground speed and of |vertical speed| (pressure altitude, GNSS
// where there is none); "flying" once both exceed 5 m/s and 0.9 m/s and then stay above 1.5 and
// 0.05 for more than 60 s; "on the ground" where both stay below 2.5 m/s and 0.1 m/s for more
// than 20 s. Each flying stretch extends back and forward to the nearest ground fix.

#include <vector>

#include "track/scoring/fixes.hpp"

namespace trailray::track::scoring {

struct FlightWindow {
  int launch = 0;   // fix index
  int landing = 0;  // fix index, inclusive
};

// Every flight found, in order; the whole log when none is.
std::vector<FlightWindow> detect_flights(const std::vector<Fix>& fixes);

// Every flight found, in order; empty when none is (a walk, a drive, a log of the ground).
// Flight analysis (track/flight/) uses this: it needs to tell "no flight" from "all flight".
std::vector<FlightWindow> find_flights(const std::vector<Fix>& fixes);

// The detection's 10 s centred moving averages per fix: ground speed and |vertical speed|, m/s.
struct MotionAverages {
  std::vector<double> ground_speed;
  std::vector<double> vertical_speed;
};
MotionAverages motion_averages(const std::vector<Fix>& fixes);

}  // namespace trailray::track::scoring
