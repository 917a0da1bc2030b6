// Free distance over three turnpoints: start -> TP1 -> TP2 -> TP3 -> finish, with start <= TP1
// <= TP2 <= TP3 <= finish in time. The score is a sum of rounded legs, so it is solved exactly by
// dynamic programming in four max-plus passes
//   out[j] = max over i <= j of in[i] + round(d(i, j)),
// starting from in = 0 (the best start for each TP1). Each pass prunes with the range tree: for
// a node N, in[i] + round(d(i, j)) <= max(in over N) + round(upper(j, N)) for every i in N, because
// rounding is nondecreasing and upper() bounds the distance (metric.cpp). A node whose bound
// cannot beat the best found for j is skipped; the result is the same as the full O(n^2) scan.
#include <algorithm>
#include <limits>

#include "track/scoring/optimise.hpp"

namespace trailray::track::scoring {
namespace {

constexpr double kNone = -std::numeric_limits<double>::infinity();
constexpr int kScanSize = 8;  // nodes this small are scanned fix by fix

void max_plus_pass(const Metric& metric, const RangeTree& tree, const std::vector<double>& in, std::vector<double>& out,
                   std::vector<int>& arg) {
  const auto& nodes = tree.nodes();
  std::vector<double> node_max(nodes.size(), kNone);
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const RangeNode& n = nodes[k];
    if (n.left < 0) {
      node_max[k] = in[static_cast<std::size_t>(n.lo)];
    } else {
      node_max[k] = std::max(node_max[static_cast<std::size_t>(n.left)], node_max[static_cast<std::size_t>(n.right)]);
    }
  }
  std::vector<int> stack;
  for (int j = tree.lo(); j <= tree.hi(); ++j) {
    const auto uj = static_cast<std::size_t>(j);
    double best = in[uj];
    int best_i = j;
    // Warm start: the best predecessor of the previous fix is usually close to the best here.
    if (j > tree.lo()) {
      const int c = arg[uj - 1];
      const double v = in[static_cast<std::size_t>(c)] + round2(metric.distance(c, j));
      if (v > best) best = v, best_i = c;
    }
    const Box& pj = metric.point_box(j);
    stack.clear();
    stack.push_back(tree.root());
    while (!stack.empty()) {
      const RangeNode& n = tree.node(stack.back());
      const double nmax = node_max[static_cast<std::size_t>(stack.back())];
      stack.pop_back();
      if (n.lo > j || nmax == kNone) continue;
      if (nmax + round2(metric.upper(pj, n.box)) <= best) continue;
      if (n.size() <= kScanSize) {
        const int end = std::min(n.hi, j);
        for (int i = n.lo; i <= end; ++i) {
          const double base = in[static_cast<std::size_t>(i)];
          if (base == kNone) continue;
          const double v = base + round2(metric.distance(i, j));
          if (v > best) best = v, best_i = i;
        }
        continue;
      }
      // Later fixes first: near j the bound is weakest, so earlier ranges are tried last.
      stack.push_back(n.left);
      stack.push_back(n.right);
    }
    out[uj] = best;
    arg[uj] = best_i;
  }
}

}  // namespace

TypeResult optimise_free_distance(const Metric& metric, const RangeTree& tree, const FlightType& type) {
  const std::size_t n = static_cast<std::size_t>(tree.hi()) + 1;
  std::vector<double> a(n, kNone), b(n, kNone);
  for (int i = tree.lo(); i <= tree.hi(); ++i) a[static_cast<std::size_t>(i)] = 0.0;
  std::vector<std::vector<int>> args(4, std::vector<int>(n, 0));
  // Pass k gives, for each fix, the best route ending there with k + 1 legs.
  for (int k = 0; k < 4; ++k) {
    max_plus_pass(metric, tree, a, b, args[static_cast<std::size_t>(k)]);
    std::swap(a, b);
  }
  int finish = tree.lo();
  for (int i = tree.lo(); i <= tree.hi(); ++i)
    if (a[static_cast<std::size_t>(i)] > a[static_cast<std::size_t>(finish)]) finish = i;
  TypeResult r;
  r.type = type;
  r.points.assign(5, finish);
  for (int k = 3; k >= 0; --k)
    r.points[static_cast<std::size_t>(k)] =
        args[static_cast<std::size_t>(k)][static_cast<std::size_t>(r.points[static_cast<std::size_t>(k) + 1])];
  double sum = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    r.legs.push_back(round2(metric.distance(r.points[k], r.points[k + 1])));
    sum += r.legs.back();
  }
  r.distance = final_round(type, sum);
  r.valid = r.distance >= type.min_distance;
  r.score = r.valid ? final_round(type, r.distance * type.multiplier) : 0.0;
  return r;
}

}  // namespace trailray::track::scoring
