// chain_fronts.h -- the fronts inside one chain of a medial graph (docs/design.md 4, 3.3).
//
// Computes: for a chain x_0, e_1, ..., e_k, x_k (medial2/medial_chains.h) whose ends sent
// fire into it at times s0 (from x_0) and / or s1 (from x_k), what the arrival-ordered
// simulation on the whole graph would give inside it: the burn time of every interior
// node (a degree-2 node burns at its first arrival and passes the fire on), the fire
// entering every edge, and, when both ends sent, the quench point. With
// A_i = s0 + d(x_0, x_i) and B_i = s1 + d(x_i, x_k), A_i - B_i increases with i, so the
// fronts meet at the first i with A_i >= B_i (a binary search of certified comparisons):
// at node x_i when A_i = B_i, otherwise inside e_i. Ties are broken as the event queue
// breaks them (time, then ignition before arrival, then node id, then edge id), so the
// result is the one of the node-by-node simulation.
// Records: the times along a chain are BurnTimes advances, one per edge, whose double
// enclosures come from a compensated prefix sum of the edge lengths
// (number/compensated_sum.h), so they stay as tight as the lengths however long the chain.
// Contract: `result` belongs to the graph of `chains`; every end sent at most once.
// Complexity: O(k) records per direction and O(log k) comparisons per chain.
#pragma once

#include <cstdint>
#include <vector>

#include "burn2/ema.h"
#include "burn2/extended_grassfire.h"
#include "medial2/medial_chains.h"

namespace grassfire {

// The position of an event in the queue's tie order: (ignition before arrival, node, edge).
struct EventRank {
  bool ignition = false;
  std::uint32_t node = 0, edge = 0;
  bool operator<(const EventRank& o) const {
    if (ignition != o.ignition) return ignition;
    if (node != o.node) return node < o.node;
    return edge < o.edge;
  }
};

class ChainFronts {
 public:
  ChainFronts(const MedialGraph& g, const MedialChains& chains, GrassfireResult& result);

  // The records of the front that chain end `end` sends at time t, one per edge; returns
  // the last one, the arrival at the other stop.
  TimeId run(std::uint32_t end, TimeId t);
  // After the event loop: burn times and fire inside chain c from what its ends sent
  // (kNoTime where an end never sent) and the ranks of the events that made them send;
  // appends the chain's quench, if any, to `quenches` and `events`.
  void resolve(std::uint32_t c, const TimeId sent[2], const EventRank rank[2], std::vector<QuenchRecord>& quenches,
               std::vector<BurnEvent>& events);

 private:
  // The time of x_i seen from end `end` (A_i for end 0, B_i for end 1), i in 0..k.
  TimeId time_at(std::uint32_t end, std::uint32_t i, const TimeId sent[2]) const;
  EventRank rank_at(std::uint32_t c, std::uint32_t end, std::uint32_t i, const EventRank rank[2]) const;
  void one_front(std::uint32_t c, std::uint32_t end, const TimeId sent[2]);
  void both_fronts(std::uint32_t c, const TimeId sent[2], const EventRank rank[2], std::vector<QuenchRecord>& quenches,
                   std::vector<BurnEvent>& events);
  TimeId& fire_from(std::uint32_t edge, std::uint32_t node);

  const MedialGraph& g_;
  const MedialChains& chains_;
  GrassfireResult& result_;
  std::vector<TimeId> run_first_;  // per chain end: the first record of its run, or kNoTime
};

}  // namespace grassfire
