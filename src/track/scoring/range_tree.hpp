#pragma once
// A binary tree over a window [lo, hi] of the fix list: every node is an index range with the
// Box (metric.hpp) that holds its fixes. The optimiser bounds whole ranges with it. Children
// always come after their parent in `nodes`.

#include <vector>

#include "track/scoring/metric.hpp"

namespace trailray::track::scoring {

struct RangeNode {
  int lo = 0, hi = 0;         // fix indexes, inclusive
  int left = -1, right = -1;  // children, -1 for a single fix
  Box box;
  int size() const { return hi - lo + 1; }
};

class RangeTree {
 public:
  RangeTree(const Metric& metric, int lo, int hi);
  const std::vector<RangeNode>& nodes() const { return nodes_; }
  const RangeNode& node(int i) const { return nodes_[static_cast<std::size_t>(i)]; }
  int root() const { return 0; }
  int lo() const { return lo_; }
  int hi() const { return hi_; }

 private:
  int build(const Metric& metric, int lo, int hi);
  std::vector<RangeNode> nodes_;
  int lo_, hi_;
};

}  // namespace trailray::track::scoring
