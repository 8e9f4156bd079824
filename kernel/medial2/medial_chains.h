// medial_chains.h -- the chains of a medial graph: maximal paths whose interior nodes
// have degree 2 (docs/design.md 4).
//
// Computes: every path x_0, e_1, x_1, ..., e_k, x_k with x_1 .. x_{k-1} of degree 2 and
// x_0, x_k of degree other than 2 (the stops: leaves, junctions, isolated nodes); x_0 =
// x_k for a loop through degree-2 nodes. Cycles made only of degree-2 nodes have no stop
// and belong to no chain. A sampled medial axis is almost all chains (10^6 samples of a
// real silhouette: 110 stops, 999,887 degree-2 nodes), so the burning engine runs its
// event queue over stops and treats each chain as one edge (burn2/extended_grassfire.h).
// End 0 of chain c is x_0 with edge e_1, end 1 is x_k with edge e_k; the end id is 2c + end.
// Contract: a validated MedialGraph (no loops). Complexity: O(n + m).
#pragma once

#include <cstdint>
#include <vector>

#include "medial2/medial_graph.h"

namespace grassfire {

struct MedialChains {
  static constexpr std::uint32_t kNone = 0xffffffffu;
  // Chain c: nodes[node_begin[c] .. node_begin[c + 1]) = x_0 .. x_k and
  // edges[edge_begin[c] .. edge_begin[c + 1]) = e_1 .. e_k.
  std::vector<std::uint32_t> node_begin, nodes, edge_begin, edges;
  std::vector<std::uint32_t> chain_of_edge;  // kNone for edges of stop-free cycles

  std::uint32_t count() const { return static_cast<std::uint32_t>(edge_begin.size()) - 1; }
  std::uint32_t length(std::uint32_t c) const { return edge_begin[c + 1] - edge_begin[c]; }  // k
  std::uint32_t node(std::uint32_t c, std::uint32_t i) const { return nodes[node_begin[c] + i]; }      // x_i
  std::uint32_t edge(std::uint32_t c, std::uint32_t i) const { return edges[edge_begin[c] + i - 1]; }  // e_i
  std::uint32_t stop(std::uint32_t end) const { return end & 1 ? node(end >> 1, length(end >> 1)) : node(end >> 1, 0); }
  // The chain end at stop `v` through its incident edge `e`.
  std::uint32_t end_at(std::uint32_t v, std::uint32_t e) const {
    const std::uint32_t c = chain_of_edge[e];
    return 2 * c + (edge(c, 1) == e && node(c, 0) == v ? 0u : 1u);
  }
};

MedialChains medial_chains(const MedialGraph& g);

}  // namespace grassfire
