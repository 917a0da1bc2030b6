#pragma once
// XC scoring of a flight under a rule set: every flight type of the set optimised exactly, the
// best-scoring one picked. The library entry point; `trailray score` prints its result, and the
// 3D drawing of scored legs can take the turnpoints from it.

#include <string>
#include <vector>

#include "track/scoring/fixes.hpp"
#include "track/scoring/launch_landing.hpp"
#include "track/scoring/optimise.hpp"
#include "track/scoring/rules.hpp"

namespace trailray::track::scoring {

struct ScoreOptions {
  DistanceModel model = DistanceModel::Fcc;
  bool trim = true;  // score only the detected flight (launch to landing); false: the whole log
  // true: every type's own optimum (by_type all exact; slower). false: a type stops once it cannot
  // beat the best score found so far; the best type is exact either way.
  bool all_types = false;
};

struct ScoreResult {
  std::string rules;
  DistanceModel model = DistanceModel::Fcc;
  FlightWindow flight;              // the scored flight (fix indexes)
  std::vector<TypeResult> by_type;  // one per flight type of the rule set, in its order
  int best = -1;                    // index into by_type; -1 when nothing scores
};

// `fixes` must have at least 5 fixes (otherwise the result has best == -1 and no types).
ScoreResult score_flight(const std::vector<Fix>& fixes, const RuleSet& rules, const ScoreOptions& options = {});

}  // namespace trailray::track::scoring
