// FAI out-and-return around one turnpoint: fixes p <= b <= q with the closing round(d(p, q))
// within the limit; the return point is the middle of p and q (in latitude and longitude, as the
// reference scorer takes it) and the distance is twice round(d(b, middle)).
//
// Best-first branch and bound over triples (P, B, Q) of index ranges. Bounds:
// - closing: d(p, q) >= lower(P, Q), and the closing is a single pair here (not a minimum), so
//   a triple whose lower bound already rounds above the limit has no valid route;
// - leg: for the FCC model the middles of P x Q lie in the latitude/longitude box of the averages
//   of P's and Q's extents, and upper() on latitude/longitude boxes bounds the FCC distance
//   (metric.cpp). For the geodesic model (a true metric) d(b, middle) <= d(b, p) + d(p, middle),
//   and with d(p, q) <= limit + 0.005 km the middle lies within half of that (plus far less than a
//   metre for the latitude/longitude middle against the geodesic one) of p: 0.41 km covers it
//   up to the 0.8 km limit of the FAI rules.
#include <algorithm>
#include <queue>

#include "track/scoring/optimise.hpp"

namespace trailray::track::scoring {
namespace {

struct Triple {
  double bound;
  int p, b, q;
  bool operator<(const Triple& o) const { return bound < o.bound; }
};

}  // namespace

TypeResult optimise_out_and_return1(const Metric& metric, const RangeTree& tree, const FlightType& type, double floor) {
  TypeResult best;
  best.type = type;
  double best_score = 0;
  auto threshold = [&] { return best.valid ? std::max(best_score, floor) : floor; };
  const double limit = closing_limit(type, 0.0);  // fixed limit (the FAI rules have no relative part)

  auto evaluate = [&](int p, int b, int q) {
    const double cd = round2(metric.distance(p, q));
    if (cd > limit) return;
    const auto& fp = metric.point_box(p);
    const auto& fq = metric.point_box(q);
    const auto& fb = metric.point_box(b);
    const double mlat = (fp.lat_min + fq.lat_min) / 2, mlon = (fp.lon_min + fq.lon_min) / 2;
    const double leg = round2(metric.distance(fb.lat_min, fb.lon_min, mlat, mlon));
    const double distance = final_round(type, 2 * leg);
    if (distance < type.min_distance || distance <= 0) return;
    const double penalty = closing_penalty(type, cd);
    const double score = final_round(type, (distance - penalty) * type.multiplier);
    if (!best.valid || score > best_score) {
      best_score = score;
      best.valid = true;
      best.score = score;
      best.distance = distance;
      best.closing = cd;
      best.penalty = penalty;
      best.legs = {leg, leg};
      best.points = {b, -1};
      best.positions = {{fb.lat_min, fb.lon_min}, {mlat, mlon}};
      best.closing_in = p;
      best.closing_out = q;
    }
  };

  auto bound = [&](int pi, int bi, int qi) -> double {
    const RangeNode& P = tree.node(pi);
    const RangeNode& B = tree.node(bi);
    const RangeNode& Q = tree.node(qi);
    if (P.lo > B.hi || B.lo > Q.hi) return -1;
    if (round2(metric.lower(P.box, Q.box)) > limit) return -1;
    double leg = 0;
    if (metric.model() == DistanceModel::Fcc) {
      Box mid;
      mid.lat_min = (P.box.lat_min + Q.box.lat_min) / 2;
      mid.lat_max = (P.box.lat_max + Q.box.lat_max) / 2;
      mid.lon_min = (P.box.lon_min + Q.box.lon_min) / 2;
      mid.lon_max = (P.box.lon_max + Q.box.lon_max) / 2;
      Metric::set_coefficients(mid);
      leg = metric.upper(B.box, mid);
    } else {
      leg = metric.upper(B.box, P.box) + 0.41;
    }
    const double distance = final_round(type, 2 * round2(leg));
    if (distance < type.min_distance) return -1;
    return final_round(type, distance * type.multiplier);
  };

  std::priority_queue<Triple> queue;
  const int root = tree.root();
  if (bound(root, root, root) > floor) queue.push({bound(root, root, root), root, root, root});
  while (!queue.empty()) {
    const Triple t = queue.top();
    queue.pop();
    if (t.bound <= threshold()) break;
    const RangeNode& P = tree.node(t.p);
    const RangeNode& B = tree.node(t.b);
    const RangeNode& Q = tree.node(t.q);
    if (static_cast<long long>(P.size()) * B.size() * Q.size() <= 8) {
      for (int p = P.lo; p <= P.hi; ++p)
        for (int b = std::max(p, B.lo); b <= B.hi; ++b)
          for (int q = std::max(b, Q.lo); q <= Q.hi; ++q) evaluate(p, b, q);
      continue;
    }
    auto push = [&](int p, int b, int q) {
      const double v = bound(p, b, q);
      if (v >= 0 && v > threshold()) queue.push({v, p, b, q});
    };
    if (P.size() >= B.size() && P.size() >= Q.size()) {
      push(P.left, t.b, t.q);
      push(P.right, t.b, t.q);
    } else if (B.size() >= Q.size()) {
      push(t.p, B.left, t.q);
      push(t.p, B.right, t.q);
    } else {
      push(t.p, t.b, Q.left);
      push(t.p, t.b, Q.right);
    }
  }
  best.exact = !best.valid ? floor < 0 : best_score >= floor;
  return best;
}

}  // namespace trailray::track::scoring
