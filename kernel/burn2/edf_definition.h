// edf_definition.h -- the EDF and EMA straight from their definitions (the oracle).
//
// Computes, without any burning: for x in the graph and each branch b at x (the part of
// the graph reached from x through one incident edge), reach(b) = max over leaves y in b
// of d(x, y) + R(y), infinite when b leads into the 2-core. EDF(x) = R(x) at a leaf,
// the second largest reach elsewhere, infinite on the 2-core (Definition 3 with Lemma 3;
// docs/design.md 4). Along an edge {i, j} of length w the EDF at distance s from i is
// min(s + A_i, w - s + A_j), A_i the largest reach at i away from the edge; the EMA of
// a tree component is the unique point where the EDF is largest (Prop 3), found by
// exact comparison of node values and of the edge maxima (A_i + A_j + w) / 2.
// It is the slow, definition-level reference that extended_grassfire is tested against.
// Contract: a validated MedialGraph.
// Complexity: O(n^2) interval work per graph (one traversal per node), plus exact
// comparisons only where intervals overlap.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "burn2/graph_sum.h"
#include "medial2/medial_graph.h"

namespace grassfire {

struct DefinitionalEma {
  bool cycles = false;
  // For a point: a node (at_node) or the point at exact distance `offset` from `from`.
  bool at_node = true;
  std::uint32_t node = 0;
  std::uint32_t edge = 0;
  std::uint32_t from = 0;
  GraphSum offset;
  GraphSum edf;
  std::uint32_t maxima = 0;  // how many points attain the maximum (1 by Prop 3)
  std::vector<std::uint32_t> core_nodes;
};

// reach(b) of the branch at a node through `edge`; nullopt where it leads into the 2-core.
struct BranchReach {
  std::uint32_t edge = 0;
  std::optional<GraphSum> reach;
};

struct DefinitionalEdf {
  std::vector<std::optional<GraphSum>> edf;  // per node; nullopt where infinite
  // Per node outside the 2-core, one per incident edge (empty in the core): from them the
  // EDF along an edge {i, j} at distance s from i is min(s + A_i, w - s + A_j), A_i the
  // largest reach at i over the other branches (R(i) at a leaf), and the branches at x
  // split by Prop. 2 into reach > EDF(x) (gradient +1), = EDF(x) (-1, continuous) and
  // < EDF(x) (-1, a jump).
  std::vector<std::vector<BranchReach>> branches;
  std::vector<DefinitionalEma> ema;          // per component, ids as component_of_nodes()
  NumberStats stats;
};

DefinitionalEdf edf_by_definition(const MedialGraph& g);

}  // namespace grassfire
