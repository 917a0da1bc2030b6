#pragma once
// Exact optimisers for one flight type over the fixes [lo, hi] of a flight (branch and bound
// over index ranges; every bound is an upper bound of the score, see optimise_*.cpp).

#include <array>
#include <unordered_map>
#include <vector>

#include "track/scoring/metric.hpp"
#include "track/scoring/range_tree.hpp"
#include "track/scoring/rules.hpp"

namespace trailray::track::scoring {

struct TypeResult {
  FlightType type;
  bool valid = false;  // false: no route of this type found (e.g. it never closes)
  // true: `score` is this type's optimum. false: the search stopped at a floor (a better score of
  // another type), so this type's optimum is known only to be at most that floor.
  bool exact = true;
  double score = 0;          // points
  double distance = 0;       // km, the sum of the rounded legs (final-rounded)
  double closing = -1;       // km, -1 for a free distance
  double penalty = 0;        // km
  std::vector<double> legs;  // km, rounded, in route order
  std::vector<int> points;   // fix indexes in route order (od: start, TP1, TP2, TP3, finish); -1: not a fix
  std::vector<std::pair<double, double>> positions;  // lat, lon of each point (moved ones differ from the fix)
  int closing_in = -1, closing_out = -1;             // the closing pair (fix indexes), -1 for od
};

// Closest pair between the fixes [tree.lo(), a] and [c, tree.hi()] (exact, memoised).
class ClosingFinder {
 public:
  ClosingFinder(const Metric& metric, const RangeTree& tree) : metric_(metric), tree_(tree) {}
  // Unrounded distance in km and the pair.
  double closest(int a, int c, int* in = nullptr, int* out = nullptr);

 private:
  const Metric& metric_;
  const RangeTree& tree_;
  struct Entry {
    double d;
    int in, out;
  };
  std::unordered_map<long long, Entry> memo_;
  struct Recent {
    int a = 0, c = -1;  // the query (c < a: empty slot, never used)
    Entry entry{0, 1 << 30, -1};
  };
  std::array<Recent, 8> recent_{};
  std::size_t next_recent_ = 0;
};

// The cheap first passes of the free distance (best start and finish leg per fix) and the route
// they give with all three turnpoints at one fix: its score is a floor the other types can use.
struct FreeDistanceStart {
  std::vector<double> f0, b0;
  std::vector<int> af0, ab0;
  double known = 0;  // km, the known route's length
  int known_at = 0;
};
FreeDistanceStart prepare_free_distance(const Metric& metric, const RangeTree& tree);
double known_route_score(const FreeDistanceStart& start, const FlightType& type);
// `floor`: only routes scoring above it are searched for (< 0: all).
TypeResult optimise_free_distance(const Metric& metric, const RangeTree& tree, const FlightType& type,
                                  const FreeDistanceStart& start, double floor);
// FAI out-and-return around one turnpoint: the return point is the middle of the closing pair.
// `floor`: only routes scoring above it are searched for (< 0: all).
TypeResult optimise_out_and_return1(const Metric& metric, const RangeTree& tree, const FlightType& type, double floor);
// `floor`: only routes scoring above it are searched for (< 0: all).
TypeResult optimise_closed(const Metric& metric, const RangeTree& tree, ClosingFinder& closing, const FlightType& type,
                           double floor);

}  // namespace trailray::track::scoring
