// rate_pruning.h -- erosion thickness by Shaked and Bruckstein's rate pruning paradigm
// (1998; dissertation 3.4.1), an independent computation of ET that never reads the EDF.
//
// Computes: the time at which the pruning front reaches every node. Pruning fronts start
// at every leaf (end of the axis) at time 0 and move along the axis with speed
// 1 / (1 - dR/ds), s the arc length in the direction of travel. Discrete form: crossing an
// edge from i to j of length w takes  integral (1 - dR/ds) ds = w - (R(j) - R(i))  (the
// fundamental theorem of calculus: no assumption on R inside the edge; >= 0 because R is
// 1-Lipschitz along the axis). At a node the junction rule of the extended grassfire
// (3.3.1): a node is pruned by the arrival that leaves at most one incident edge unreached,
// and the front goes on into that edge; earlier arrivals end there. Two fronts on one edge,
// sent from i at P_i and from j at P_j, meet where P_i + s - R(x) + R(i) equals
// P_j + (w - s) - R(x) + R(j): at s = (w + P_j + R(j) - P_i - R(i)) / 2 from i, whatever R
// does inside the edge. What is never reached (the 2-core) has ET = infinity.
// Pruning times are exact: P(j) = R(z) - R(j) + the lengths along the front's path from its
// leaf z (telescoping), a sum of graph atoms; events are ordered by the interval filter and
// then exactly (burn2/graph_sum.h); ties are broken by (node, edge).
// 3.4.1's identity ET = EDF - R is checked against this in proofs-checks/check_measures2d.
// Contract: a validated MedialGraph with R 1-Lipschitz along edges (a front that would
// reach a leaf throws std::logic_error, as in the extended grassfire).
// Complexity: O((n + m) log(n + m)) comparisons.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "burn2/graph_sum.h"
#include "medial2/medial_graph.h"

namespace grassfire {

struct PruningQuench {
  std::uint32_t component = 0;
  bool at_node = true;
  std::uint32_t node = 0;                 // at_node
  std::uint32_t edge = 0, from = 0;       // otherwise: at `offset` from `from` along `edge`
  GraphSum offset;
  Interval offset_approx;
};

struct RatePruning {
  std::vector<std::optional<GraphSum>> time;  // per node: its pruning time (= ET); nullopt: never
  std::vector<Interval> approx;               // enclosures (infinite where never pruned)
  std::vector<PruningQuench> last_quench;     // per tree component: where the last fronts meet
  NumberStats stats;
  std::uint64_t events = 0;
};

RatePruning rate_pruning(const MedialGraph& g);

}  // namespace grassfire
