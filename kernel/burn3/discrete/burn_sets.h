// burn_sets.h -- the burning sets B(t) of Definition 9 on the baseline's graph (4.2.3).
//
// Computes, from the burn times of a DiscreteBurning and its graph, for every graph point x
// and link element e the witness time W_e(x) = min over moves y -> x through e of
// BT(y) + |x - y| (the earliest time a non-crossing straight path from a burned point
// enters x through e), and from it the discrete burning set
//   x in B(t)  iff  (x is a border point and f(x) <= t)  or  link_burns({e : W_e(x) <= t}),
// which is Definition 9 with paths restricted to graph moves (every disk type of x, a
// cycle of its link, must contain an element with a witness): the discrete model, with
// the baseline's own moves, link rule and ignition. It is recomputed from the neighbours'
// times only, independently of the event loop, so Definition 10 on it (BT(x) = inf {t :
// x in B(t)}, the first_time below) certifies the event loop: with positive move lengths
// the discrete equations have exactly one solution, so a BT that satisfies them at every
// point is the discrete BT. It cannot detect an error in the moves, the rule or the
// ignition, which it shares with the baseline; those are compared with the continuous
// definition elsewhere (closed forms and brute force, burn3_reference.h). Lemma 2 (B(s)
// within B(t) for s <= t) holds here for any BT whatever, because the rule is monotone in
// the arrived set; a rule_override (discrete_burning.h) replaces the rule, which is how
// the proof checks show that their Lemma 2 row detects a non-monotone rule.
// Contract: `burning` was computed on `graph`. Complexity: O(moves) to build; membership
// O(link size); first_time O(link size^2).
#pragma once

#include <vector>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/discrete/steiner_graph.h"

namespace grassfire {

class BurnSets {
 public:
  BurnSets(const SteinerGraph& graph, const DiscreteBurning& burning, const BurnRuleOverride* rule_override = nullptr);
  bool contains(std::uint32_t node, double t) const;
  // inf {t : node in B(t)} over the candidate times f(x) and W_e(x); kInfinity if none.
  double first_time(std::uint32_t node) const;
  double burn_time(std::uint32_t node) const;  // the baseline's BT at the node
  // The distinct finite candidate times of the node (f(x) and the witnesses W_e(x)), sorted.
  std::vector<double> candidate_times(std::uint32_t node) const;

 private:
  bool link_condition(std::uint32_t node, double t) const;
  double ignition(std::uint32_t node) const;
  bool border(std::uint32_t node) const;
  const SteinerGraph& g_;
  const DiscreteBurning& d_;
  const BurnRuleOverride* override_;
  std::vector<double> witness_;  // per slot
};

}  // namespace grassfire
