#pragma once
// The scoring rule sets (league rules as igc-xc-score 1.8.0 reads them; see
// shared/data/igc/scoring/RULES.md): per flight type its multiplier, closing limit, penalty and
// rounding.

#include <optional>
#include <string>
#include <vector>

namespace trailray::track::scoring {

enum class Shape { FreeDistance, Triangle, OutAndReturn1, OutAndReturn2 };

struct FlightType {
  std::string name;  // the rule set's own name for it
  std::string code;  // od, tri, fai, oar
  Shape shape = Shape::FreeDistance;
  double multiplier = 1.0;
  double min_side = 0.0;           // each side >= min_side * distance (0: none)
  double max_side = 0.0;           // each side <= max_side * distance (0: none)
  double min_distance = 0.0;       // km; below it the type scores 0
  double closing_fixed = 0.0;      // km always allowed
  double closing_relative = 0.0;   // fraction of the distance allowed
  double closing_free = -1.0;      // km of closing without penalty (< 0: every closing is penalised)
  bool final_rounding_01 = false;  // distance and score rounded to 0.1 (else 0.01)
  double cylinders = 0.0;          // km: FAI cylinder radius around turnpoints (0: none)
};

struct RuleSet {
  std::string name;
  std::vector<FlightType> types;
};

// xcontest, ffvl, fai, fai-oar, fai-cylinders, xcleague; nullopt for an unknown name.
std::optional<RuleSet> rule_set(const std::string& name);
std::vector<std::string> rule_set_names();

// Rounding to 0.01 km as the reference scorer does (toFixed(2)); to 0.1 for final rounding.
inline double round2(double v) {
  return static_cast<double>(static_cast<long long>(v * 100.0 + (v >= 0 ? 0.5 : -0.5))) / 100.0;
}
inline double round1(double v) {
  return static_cast<double>(static_cast<long long>(v * 10.0 + (v >= 0 ? 0.5 : -0.5))) / 10.0;
}
inline double final_round(const FlightType& t, double v) { return t.final_rounding_01 ? round1(v) : round2(v); }

// The largest closing distance allowed for a route of `distance` km.
inline double closing_limit(const FlightType& t, double distance) {
  const double rel = distance * t.closing_relative;
  return round2(rel > t.closing_fixed ? rel : t.closing_fixed);
}
// The penalty for a closing distance (nondecreasing in it).
inline double closing_penalty(const FlightType& t, double closing) {
  return round2(closing > t.closing_free ? closing : 0.0);
}

}  // namespace trailray::track::scoring
