// box_tree3.h -- a bounding volume hierarchy over axis-aligned boxes of R^3, searched best
// first: the spatial index of exact point location (point_location.h).
//
// Computes: a binary tree over n items with boxes (interval triples), each node's box the
// hull of its items' boxes; items split at the median of their box centres along the
// longest axis of the node's box, leaves of at most kLeafSize items. best_first visits the
// leaves in increasing order of a caller's lower bound on the node box (a priority queue)
// and stops when that bound exceeds the caller's current bound, which the visits may lower:
// the search of a nearest item under certified bounds.
// Why it is exact: the tree only orders and prunes; the caller's bounds are certified
// (interval lower bounds on box distances against certified upper bounds), so no item that
// can hold the answer is skipped.
// Contract: boxes with finite or infinite bounds (never NaN). Complexity: construction
// O(n log n); a search visits O(log n + k) nodes for k leaves within the bound.
// Section: docs/design.md 3 (filters prune, exact arithmetic decides).
#pragma once

#include <array>
#include <cstdint>
#include <queue>
#include <utility>
#include <vector>

#include "number/interval.h"

namespace grassfire {

class BoxTree3 {
 public:
  using Box = std::array<Interval, 3>;
  static constexpr std::uint32_t kLeafSize = 4;

  explicit BoxTree3(const std::vector<Box>& boxes);

  // Calls visit(item) for every item of every leaf whose node_lower(box) <= bound(), the
  // leaves in increasing order of node_lower; node_lower(box) must not exceed the bound of
  // any item inside box for the search to find the nearest.
  template <class NodeLower, class Visit, class Bound>
  void best_first(NodeLower&& node_lower, Visit&& visit, Bound&& bound) const {
    if (nodes_.empty()) return;
    using Entry = std::pair<double, std::uint32_t>;  // (lower bound, node)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    queue.emplace(node_lower(nodes_[0].box), 0);
    while (!queue.empty()) {
      const auto [lower, n] = queue.top();
      queue.pop();
      if (lower > bound()) break;
      const Node& node = nodes_[n];
      if (node.left == kLeaf) {
        for (std::uint32_t i = node.begin; i < node.end; ++i) visit(items_[i]);
        continue;
      }
      for (std::uint32_t child : {node.left, node.left + 1}) {
        const double l = node_lower(nodes_[child].box);
        if (l <= bound()) queue.emplace(l, child);
      }
    }
  }

 private:
  static constexpr std::uint32_t kLeaf = 0xffffffffu;
  struct Node {
    Box box;
    std::uint32_t begin = 0, end = 0;  // items_[begin, end)
    std::uint32_t left = kLeaf;        // children left and left + 1
  };
  void split(std::uint32_t node, const std::vector<Box>& boxes);
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> items_;
};

}  // namespace grassfire
