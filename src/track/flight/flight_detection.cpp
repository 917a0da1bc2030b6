// Take-off and landing: the scoring layer's launch detection on the samples, then each flight
// trimmed to where the ground speed says the pilot is no longer walking.
#include <cmath>

#include "track/flight/flight_samples.hpp"
#include "track/scoring/launch_landing.hpp"

namespace trailray::track::flight::detail {
namespace {

// 10 s averages: above kFastSpeed the pilot is surely in the air (the detection's own start
// threshold); below kWalkSpeed (its ground threshold) a pilot on foot could be walking. The
// flight starts after the last walking-speed fix before the first fast one, and ends at the first
// walking-speed fix after the last fast one: a hike up or a walk to the car is not flight time.
constexpr double kFastSpeed = 5.0, kWalkSpeed = 2.5;

}  // namespace

std::vector<FlightRange> find_flight_ranges(const std::vector<Sample>& s) {
  std::vector<scoring::Fix> fixes;
  fixes.reserve(s.size());
  for (const Sample& x : s) {
    scoring::Fix f;
    f.lat = x.lat;
    f.lon = x.lon;
    f.time = x.time;
    f.gnss_alt = std::isfinite(x.alt) ? static_cast<int>(std::lround(x.alt)) : 0;
    f.pressure_alt = 0;  // the detection then uses gnss_alt, here the analysed altitude
    fixes.push_back(f);
  }
  const std::vector<scoring::FlightWindow> windows = scoring::find_flights(fixes);
  const scoring::MotionAverages ma = scoring::motion_averages(fixes);
  const std::vector<double>& speed = ma.ground_speed;
  std::vector<FlightRange> out;
  for (const scoring::FlightWindow& w : windows) {
    auto launch = static_cast<std::size_t>(w.launch), landing = static_cast<std::size_t>(w.landing);
    std::size_t first_fast = launch, last_fast = landing;
    while (first_fast < landing && speed[first_fast] <= kFastSpeed) ++first_fast;
    while (last_fast > first_fast && speed[last_fast] <= kFastSpeed) --last_fast;
    if (first_fast < last_fast) {
      std::size_t a = first_fast;
      while (a > launch && speed[a - 1] >= kWalkSpeed) --a;
      std::size_t b = last_fast;
      while (b < landing && speed[b + 1] >= kWalkSpeed) ++b;
      launch = a;
      landing = b;
    }
    if (landing > launch) out.push_back({launch, landing});
  }
  return out;
}

}  // namespace trailray::track::flight::detail
