// Closed routes: triangles (TP1 -> TP2 -> TP3 -> TP1) and out-and-returns over two turnpoints
// (TP1 -> TP2 -> TP1), with the closing: the closest pair of a fix up to TP1 and a fix from the
// last turnpoint on, which must be within the type's limit and may cost a penalty.
//
// Best-first branch and bound over triples of index ranges (nodes of the range tree). For a
// triple (A, B, C) the bound is an upper bound of the score of every route with TP1 in A, TP2 in
// B, TP3 in C:
// - each leg <= round(upper(box, box)) (rounding is nondecreasing; upper() bounds the distance);
//   the distance <= final_round(their sum) (final rounding is nondecreasing too);
// - a side rule "each side >= s * distance" gives distance <= side / s for every side, so the
//   smallest side bound / s bounds the distance; if even the largest side cannot reach s times
//   the smallest possible distance (lower() bounds), no route of the triple qualifies;
//   "each side <= s * distance" likewise with the bounds swapped;
// - the closing of a route (a, c) is a minimum over fixes <= a and >= c: it can only grow when a
//   moves back or c forward, so the closing at (A.hi, C.lo) is a lower bound for every route of
//   the triple. The penalty is nondecreasing in the closing and the limit nondecreasing in the
//   distance, so a triple whose smallest closing exceeds the limit of its largest distance has no
//   valid route, and the penalty of the smallest closing bounds the penalty.
// The queue pops the triple with the highest bound; when that bound cannot beat the best route
// found, no route left can, and the search ends with the optimum.
#include <algorithm>
#include <queue>

#include "track/scoring/optimise.hpp"

namespace trailray::track::scoring {
namespace {

constexpr int kScanSize = 8;
constexpr int kClosingGrid = 32;

struct Triple {
  double bound;
  int a, b, c;
  bool operator<(const Triple& o) const { return bound < o.bound; }
};

}  // namespace

double ClosingFinder::closest(int a, int c, int* in, int* out) {
  if (c <= a) {
    if (in) *in = c;
    if (out) *out = c;
    return 0.0;
  }
  const long long key = static_cast<long long>(a) * 4294967296LL + c;
  auto it = memo_.find(key);
  if (it == memo_.end()) {
    Entry best{metric_.distance(a, c), a, c};
    // Recent answers: a pair (in, out) with in <= a and out >= c is a valid closing here, so it
    // bounds the search; if moreover the recent query's window held this one's (a <= its a,
    // c >= its c), the minimum here cannot be smaller than there, and that pair is the answer.
    for (const Recent& r : recent_) {
      if (r.entry.in > a || r.entry.out < c) continue;
      if (r.a >= a && r.c <= c) {
        best = r.entry;
        best.d = -best.d - 1;  // mark: exact, no search
        break;
      }
      if (r.entry.d < best.d) best = r.entry;
    }
    if (best.d < 0) {
      best.d = -best.d - 1;
      it = memo_.emplace(key, best).first;
      if (in) *in = best.in;
      if (out) *out = best.out;
      return best.d;
    }
    std::vector<std::pair<int, int>> stack{{tree_.root(), tree_.root()}};
    while (!stack.empty()) {
      const auto [xi, yi] = stack.back();
      stack.pop_back();
      const RangeNode& x = tree_.node(xi);
      const RangeNode& y = tree_.node(yi);
      if (x.lo > a || y.hi < c) continue;
      if (metric_.lower(x.box, y.box) >= best.d) continue;
      if (x.size() <= kScanSize && y.size() <= kScanSize) {
        const int xe = std::min(x.hi, a), ys = std::max(y.lo, c);
        for (int p = x.lo; p <= xe; ++p)
          for (int q = ys; q <= y.hi; ++q) {
            const double d = metric_.distance(p, q);
            if (d < best.d) best = Entry{d, p, q};
          }
        continue;
      }
      // Split the larger node; the nearer half is searched first (pushed last).
      int c1 = xi, c2 = xi, d1 = yi, d2 = yi;
      if (x.size() >= y.size() && x.left >= 0) {
        c1 = x.left, c2 = x.right;
      } else {
        d1 = y.left, d2 = y.right;
      }
      const double l1 = metric_.lower(tree_.node(c1).box, tree_.node(d1).box);
      const double l2 = metric_.lower(tree_.node(c2).box, tree_.node(d2).box);
      if (l1 <= l2) {
        stack.push_back({c2, d2});
        stack.push_back({c1, d1});
      } else {
        stack.push_back({c1, d1});
        stack.push_back({c2, d2});
      }
    }
    it = memo_.emplace(key, best).first;
    recent_[next_recent_] = Recent{a, c, best};
    next_recent_ = (next_recent_ + 1) % recent_.size();
  }
  if (in) *in = it->second.in;
  if (out) *out = it->second.out;
  return it->second.d;
}

TypeResult optimise_closed(const Metric& metric, const RangeTree& tree, ClosingFinder& closing, const FlightType& type,
                           double floor) {
  const bool oar = type.shape == Shape::OutAndReturn2;
  TypeResult best;
  best.type = type;
  double best_score = 0.0;

  // Routes must beat this to matter: the best of this type so far, or the caller's floor.
  auto threshold = [&] { return best.valid ? std::max(best_score, floor) : floor; };

  const bool exact_is_slow = metric.model() == DistanceModel::Geodesic;
  auto evaluate = [&](int a, int b, int c) {
    if (exact_is_slow) {
      // The exact geodesic is costly: first the cheap chord bound of the three legs.
      auto up = [&](int i, int j) { return round2(metric.upper(metric.point_box(i), metric.point_box(j))); };
      const double ub = oar ? 2 * up(a, c) : up(a, b) + up(b, c) + up(c, a);
      if (final_round(type, final_round(type, ub) * type.multiplier) <= threshold()) return;
    }
    std::vector<double> legs;
    if (oar) {
      const double leg = round2(metric.distance(a, c));
      legs = {leg, leg};
    } else {
      legs = {round2(metric.distance(a, b)), round2(metric.distance(b, c)), round2(metric.distance(c, a))};
    }
    double sum = 0;
    for (double l : legs) sum += l;
    const double distance = final_round(type, sum);
    if (distance < type.min_distance || distance <= 0) return;
    for (double l : legs) {
      if (type.min_side > 0 && l < type.min_side * distance) return;
      if (type.max_side > 0 && l > type.max_side * distance) return;
    }
    // Without its closing the route scores at most this: skip the closing search when that
    // cannot beat the best (the penalty is never negative).
    if (final_round(type, distance * type.multiplier) <= threshold()) return;
    int in = -1, out = -1;
    const double cd = round2(closing.closest(a, c, &in, &out));
    if (cd > closing_limit(type, distance)) return;
    const double penalty = closing_penalty(type, cd);
    const double score = final_round(type, (distance - penalty) * type.multiplier);
    if (score > best_score || !best.valid) {
      best_score = score;
      best.valid = true;
      best.score = score;
      best.distance = distance;
      best.closing = cd;
      best.penalty = penalty;
      best.legs = legs;
      best.points = oar ? std::vector<int>{a, c} : std::vector<int>{a, b, c};
      best.closing_in = in;
      best.closing_out = out;
    }
  };

  // Upper bound of the score of the triple; < 0 when no route of it can be valid.
  auto bound = [&](int ai, int bi, int ci) -> double {
    const RangeNode& A = tree.node(ai);
    const RangeNode& B = tree.node(bi);
    const RangeNode& C = tree.node(ci);
    if (A.lo > C.hi || (!oar && (A.lo > B.hi || B.lo > C.hi))) return -1;
    double u[3] = {0, 0, 0}, l[3] = {0, 0, 0};
    int sides = 3;
    double P = 0;
    if (oar) {
      u[0] = round2(metric.upper(A.box, C.box));
      P = final_round(type, 2 * u[0]);
      sides = 0;
    } else {
      u[0] = round2(metric.upper(A.box, B.box));
      u[1] = round2(metric.upper(B.box, C.box));
      u[2] = round2(metric.upper(C.box, A.box));
      P = final_round(type, u[0] + u[1] + u[2]);
    }
    if (P < type.min_distance || P <= 0) return -1;
    if (sides == 3 && (type.min_side > 0 || type.max_side > 0)) {
      l[0] = round2(metric.lower(A.box, B.box));
      l[1] = round2(metric.lower(B.box, C.box));
      l[2] = round2(metric.lower(C.box, A.box));
      const double pmin = final_round(type, l[0] + l[1] + l[2]);
      const double umin = std::min({u[0], u[1], u[2]});
      if (type.min_side > 0) {
        if (umin < type.min_side * pmin) return -1;
        P = std::min(P, final_round(type, umin / type.min_side));
      }
      if (type.max_side > 0 && std::max({l[0], l[1], l[2]}) > type.max_side * P) return -1;
    }
    const double open_bound = final_round(type, P * type.multiplier);
    if (open_bound <= threshold()) return open_bound;
    double cd = 0;
    // The closing only shrinks when a moves later or c earlier, so snapping A.hi up and C.lo
    // down to multiples of kClosingGrid still gives a lower bound, and far fewer distinct pairs
    // to compute (they are memoised).
    const int a_snap = std::min(tree.hi(), (A.hi + kClosingGrid - 1) / kClosingGrid * kClosingGrid);
    const int c_snap = std::max(tree.lo(), C.lo / kClosingGrid * kClosingGrid);
    if (a_snap < c_snap) cd = round2(closing.closest(a_snap, c_snap));
    if (cd > closing_limit(type, P)) return -1;
    return final_round(type, (P - closing_penalty(type, cd)) * type.multiplier);
  };

  std::priority_queue<Triple> queue;
  const int root = tree.root();
  const double b0 = bound(root, root, root);
  if (b0 >= 0 && b0 > floor) queue.push({b0, root, root, root});
  while (!queue.empty()) {
    const Triple t = queue.top();
    queue.pop();
    if (t.bound <= threshold()) break;
    const RangeNode& A = tree.node(t.a);
    const RangeNode& B = tree.node(t.b);
    const RangeNode& C = tree.node(t.c);
    const int sa = A.size(), sb = oar ? 0 : B.size(), sc = C.size();
    if (static_cast<long long>(sa) * std::max(sb, 1) * sc <= kScanSize) {
      for (int a = A.lo; a <= A.hi; ++a)
        for (int b = oar ? a : std::max(a, B.lo); b <= (oar ? a : B.hi); ++b)
          for (int c = std::max(oar ? a : b, C.lo); c <= C.hi; ++c) evaluate(a, b, c);
      continue;
    }
    auto push = [&](int a, int b, int c) {
      const double v = bound(a, b, c);
      if (v >= 0 && v > threshold()) queue.push({v, a, b, c});
    };
    if (sa >= sb && sa >= sc) {
      push(A.left, oar ? A.left : t.b, t.c);
      push(A.right, oar ? A.right : t.b, t.c);
    } else if (sb >= sc) {
      push(t.a, B.left, t.c);
      push(t.a, B.right, t.c);
    } else {
      push(t.a, oar ? t.a : t.b, C.left);
      push(t.a, oar ? t.a : t.b, C.right);
    }
  }
  best.exact = !best.valid ? floor < 0 : best_score >= floor;
  return best;
}

}  // namespace trailray::track::scoring
