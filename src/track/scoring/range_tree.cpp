#include "track/scoring/range_tree.hpp"

namespace trailray::track::scoring {

RangeTree::RangeTree(const Metric& metric, int lo, int hi) : lo_(lo), hi_(hi) {
  nodes_.reserve(static_cast<std::size_t>(2 * (hi - lo + 1)));
  build(metric, lo, hi);
}

int RangeTree::build(const Metric& metric, int lo, int hi) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(RangeNode{lo, hi, -1, -1, metric.point_box(lo)});
  if (lo == hi) return id;
  const int mid = lo + (hi - lo) / 2;
  const int l = build(metric, lo, mid);
  const int r = build(metric, mid + 1, hi);
  RangeNode& n = nodes_[static_cast<std::size_t>(id)];
  n.left = l;
  n.right = r;
  n.box = Metric::merge(nodes_[static_cast<std::size_t>(l)].box, nodes_[static_cast<std::size_t>(r)].box);
  return id;
}

}  // namespace trailray::track::scoring
