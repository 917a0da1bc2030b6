// Free distance over three turnpoints: start -> TP1 -> TP2 -> TP3 -> finish, with start <= TP1
// <= TP2 <= TP3 <= finish in time. The score is a sum of rounded legs, so it is solved exactly by
// dynamic programming with max-plus passes, two from each end meeting at TP2 (f1 is the last):
//   forward  f0[j] = max over i <= j of round(d(i, j))            (best start leg to TP1 = j)
//            f1[j] = max over i <= j of f0[i] + round(d(i, j))    (best two legs to TP2 = j)
//   backward b0[j] = max over i >= j of round(d(j, i))            (best finish leg from TP3 = j)
//            b1[j] = max over i >= j of b0[i] + round(d(j, i))    (best two legs from TP2 = j)
//   optimum = max over j of f1[j] + b1[j].
// Each pass prunes with the range tree: for a node N, in[i] + round(d(i, j)) <= max(in over N) +
// round(upper(j, N)) for every i in N, because rounding is nondecreasing and upper() bounds the
// distance (metric.cpp). A node is skipped when that bound is below what j needs: the best found
// for j so far, and a floor L: the length of a route already known (f0[j] + b0[j], all turnpoints
// at j) or what a better type elsewhere already scores. f1[j] must reach L - b1[j]; b1[j] must
// reach L - (an upper bound of f1[j], see below). A j on a route of length >= L has f1[j] + b1[j]
// >= L, so the nodes holding its optimal predecessor are never skipped (the test is strict) and
// its values are exact; other fixes may keep smaller values, which only loses routes below L.
#include <algorithm>
#include <limits>
#include <thread>

#include "geo/threads.hpp"

#include "track/scoring/optimise.hpp"

namespace trailray::track::scoring {
namespace {

constexpr double kNone = -std::numeric_limits<double>::infinity();
constexpr int kScanSize = 8;        // nodes this small are scanned fix by fix
constexpr int kParallelMin = 4000;  // fixes: below this a second thread costs more than it gains

bool parallel_available() { return geo::kThreadsAvailable && std::thread::hardware_concurrency() > 1; }

// out[j] = max over i on the `forward` side of j (i <= j, or i >= j) of in[i] + round(d(i, j)).
// need[j] (optional): a value out[j] must exceed to matter (see above).
// The fixes j in [lo, hi] of one pass; node_max: the largest `in` under each node.
void max_plus_chunk(const Metric& metric, const RangeTree& tree, bool forward, const std::vector<double>& in,
                    const std::vector<double>& node_max, const std::vector<double>* need, int lo, int hi,
                    std::vector<double>& out, std::vector<int>& arg) {
  std::vector<int> stack;
  const bool exact_is_slow = metric.model() == DistanceModel::Geodesic;
  const int first = forward ? lo : hi;
  const int last = forward ? hi : lo;
  const int step = forward ? 1 : -1;
  for (int j = first;; j += step) {
    const auto uj = static_cast<std::size_t>(j);
    double best = in[uj];
    int best_i = j;
    // Warm start: the best predecessor of the previous fix is usually close to the best here.
    if (j != first) {
      const int c = arg[static_cast<std::size_t>(j - step)];
      const double v = in[static_cast<std::size_t>(c)] + round2(metric.distance(c, j));
      if (v > best) best = v, best_i = c;
    }
    double bar = best;
    bool strict = false;  // prune at bound <= bar (best so far) or, for `need`, only at bound < bar
    if (need && (*need)[uj] > bar) bar = (*need)[uj], strict = true;
    const Box& pj = metric.point_box(j);
    stack.clear();
    stack.push_back(tree.root());
    while (!stack.empty()) {
      const int id = stack.back();
      stack.pop_back();
      const RangeNode& n = tree.node(id);
      const double nmax = node_max[static_cast<std::size_t>(id)];
      if ((forward ? n.lo > j : n.hi < j) || nmax == kNone) continue;
      // round2(x) <= x + 0.005: a bound without the cost of rounding.
      const double b = nmax + metric.upper(pj, n.box) + 0.005;
      if (strict ? b < bar : b <= bar) continue;
      if (n.size() <= kScanSize) {
        const int from = forward ? n.lo : std::max(n.lo, j);
        const int to = forward ? std::min(n.hi, j) : n.hi;
        for (int i = from; i <= to; ++i) {
          const double base = in[static_cast<std::size_t>(i)];
          if (base == kNone) continue;
          // The exact geodesic is costly: skip pairs whose cheap chord bound cannot win.
          if (exact_is_slow && base + round2(metric.upper(metric.point_box(i), pj)) <= best) continue;
          const double v = base + round2(metric.distance(i, j));
          if (v > best) {
            best = v, best_i = i;
            if (best >= bar) bar = best, strict = false;
          }
        }
        continue;
      }
      // The far side first (popped first): the far end of a leg is usually the better one.
      stack.push_back(forward ? n.right : n.left);
      stack.push_back(forward ? n.left : n.right);
    }
    out[uj] = best;
    arg[uj] = best_i;
    if (j == last) break;
  }
}

void max_plus_pass(const Metric& metric, const RangeTree& tree, bool forward, const std::vector<double>& in,
                   const std::vector<double>* need, std::vector<double>& out, std::vector<int>& arg) {
  const auto& nodes = tree.nodes();
  std::vector<double> node_max(nodes.size(), kNone);
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const RangeNode& n = nodes[k];
    node_max[k] =
        n.left < 0 ? in[static_cast<std::size_t>(n.lo)]
                   : std::max(node_max[static_cast<std::size_t>(n.left)], node_max[static_cast<std::size_t>(n.right)]);
  }
  // Every j is independent of the others (the warm start is only a hint), so long flights are
  // split between two threads writing disjoint parts of out and arg.
  const int lo = tree.lo(), hi = tree.hi();
  if (hi - lo < kParallelMin || !parallel_available()) {
    max_plus_chunk(metric, tree, forward, in, node_max, need, lo, hi, out, arg);
    return;
  }
  const int mid = lo + (hi - lo) / 2;
  std::thread other([&] { max_plus_chunk(metric, tree, forward, in, node_max, need, mid + 1, hi, out, arg); });
  max_plus_chunk(metric, tree, forward, in, node_max, need, lo, mid, out, arg);
  other.join();
}

}  // namespace

FreeDistanceStart prepare_free_distance(const Metric& metric, const RangeTree& tree) {
  const std::size_t n = static_cast<std::size_t>(tree.hi()) + 1;
  FreeDistanceStart p;
  std::vector<double> zero(n, kNone);
  for (int i = tree.lo(); i <= tree.hi(); ++i) zero[static_cast<std::size_t>(i)] = 0.0;
  p.f0.assign(n, kNone);
  p.b0.assign(n, kNone);
  p.af0.assign(n, 0);
  p.ab0.assign(n, 0);
  max_plus_pass(metric, tree, true, zero, nullptr, p.f0, p.af0);
  max_plus_pass(metric, tree, false, zero, nullptr, p.b0, p.ab0);
  // A route already known: all three turnpoints at one fix j, start and finish the furthest.
  p.known = kNone;
  for (int j = tree.lo(); j <= tree.hi(); ++j) {
    const auto u = static_cast<std::size_t>(j);
    if (p.f0[u] + p.b0[u] > p.known) p.known = p.f0[u] + p.b0[u], p.known_at = j;
  }
  return p;
}

double known_route_score(const FreeDistanceStart& p, const FlightType& type) {
  const double distance = final_round(type, p.known);
  return distance >= type.min_distance ? final_round(type, distance * type.multiplier) : 0.0;
}

TypeResult optimise_free_distance(const Metric& metric, const RangeTree& tree, const FlightType& type,
                                  const FreeDistanceStart& p, double floor) {
  const std::size_t n = static_cast<std::size_t>(tree.hi()) + 1;
  const std::vector<double>& f0 = p.f0;
  const std::vector<double>& b0 = p.b0;
  std::vector<double> f1(n, kNone), b1(n, kNone);
  std::vector<int> af1(n, 0), ab1(n, 0);
  // Only routes at least `floor_length` long can matter: the known route's length, or one whose
  // score could reach the caller's floor (0.1 km below, for both roundings).
  double floor_length = p.known;
  if (floor >= 0) floor_length = std::max(floor_length, floor / type.multiplier - 0.1);
  // f1[j] <= max(f0 over i <= j) + max(d(i, j) over i <= j) = prefix max of f0 + f0[j]: no
  // triangle inequality needed. So b1[j] matters only if it reaches floor_length minus that.
  std::vector<double> need(n, kNone);
  double prefix = kNone;
  for (int j = tree.lo(); j <= tree.hi(); ++j) {
    const auto u = static_cast<std::size_t>(j);
    prefix = std::max(prefix, f0[u]);
    need[u] = floor_length - (prefix + f0[u]);
  }
  max_plus_pass(metric, tree, false, b0, &need, b1, ab1);
  // b1[j] is always the length of a real route from j (where it was cut short, a shorter one), so
  // f0[j] + b1[j] is a known route too (TP1 = TP2 = j): it raises floor_length.
  for (int j = tree.lo(); j <= tree.hi(); ++j) {
    const auto u = static_cast<std::size_t>(j);
    floor_length = std::max(floor_length, f0[u] + b1[u]);
  }
  // Where b1 was cut short, f1 + b1 stays below floor_length whatever f1 is; elsewhere b1 is
  // exact and f1[j] must reach floor_length - b1[j].
  for (int j = tree.lo(); j <= tree.hi(); ++j)
    need[static_cast<std::size_t>(j)] = floor_length - b1[static_cast<std::size_t>(j)];
  max_plus_pass(metric, tree, true, f0, &need, f1, af1);
  const std::vector<int>& af0 = p.af0;
  const std::vector<int>& ab0 = p.ab0;

  int tp2 = tree.lo();
  for (int j = tree.lo(); j <= tree.hi(); ++j) {
    const auto u = static_cast<std::size_t>(j), ub = static_cast<std::size_t>(tp2);
    if (f1[u] + b1[u] > f1[ub] + b1[ub]) tp2 = j;
  }
  TypeResult r;
  r.type = type;
  const int tp1 = af1[static_cast<std::size_t>(tp2)];
  const int tp3 = ab1[static_cast<std::size_t>(tp2)];
  r.points = {af0[static_cast<std::size_t>(tp1)], tp1, tp2, tp3, ab0[static_cast<std::size_t>(tp3)]};
  double sum = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    r.legs.push_back(round2(metric.distance(r.points[k], r.points[k + 1])));
    sum += r.legs.back();
  }
  r.distance = final_round(type, sum);
  r.valid = r.distance >= type.min_distance;
  r.score = r.valid ? final_round(type, r.distance * type.multiplier) : 0.0;
  r.exact = floor < 0 || r.score > floor;
  return r;
}

}  // namespace trailray::track::scoring
