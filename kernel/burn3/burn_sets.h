// burn_sets.h -- the burning sets B(t) of Definition 9 on the baseline's graph (4.2.3).
//
// Computes, from the burn times of a DiscreteBurning and its graph, for every graph point x
// and link element e the witness time W_e(x) = min over moves y -> x through e of
// BT(y) + |x - y| (the earliest time a non-crossing straight path from a burned point
// enters x through e), and from it the discrete burning set
//   x in B(t)  iff  (x is a border point and f(x) <= t)  or  link_burns({e : W_e(x) <= t}),
// which is Definition 9 with paths restricted to graph moves (every disk type of x, a
// cycle of its link, must contain an element with a witness). This is recomputed from the
// neighbours' times only, independently of the event loop, so the checks of Lemma 2
// (B(s) within B(t) for s <= t) and of Definition 10 (BT(x) = inf {t : x in B(t)}) test
// the baseline's output against the definition.
// Contract: `burning` was computed on `graph`. Complexity: O(moves) to build; membership
// O(link size); first_time O(link size^2).
#pragma once

#include <vector>

#include "burn3/discrete_burning.h"
#include "burn3/steiner_graph.h"

namespace grassfire {

class BurnSets {
 public:
  BurnSets(const SteinerGraph& graph, const DiscreteBurning& burning);
  bool contains(std::uint32_t node, double t) const;
  // inf {t : node in B(t)} over the candidate times f(x) and W_e(x); kInfinity if none.
  double first_time(std::uint32_t node) const;
  double burn_time(std::uint32_t node) const;  // the baseline's BT at the node

 private:
  bool link_condition(std::uint32_t node, double t) const;
  double ignition(std::uint32_t node) const;
  bool border(std::uint32_t node) const;
  const SteinerGraph& g_;
  const DiscreteBurning& d_;
  std::vector<double> witness_;  // per slot
};

}  // namespace grassfire
