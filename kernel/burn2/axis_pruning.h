// axis_pruning.h -- pruning the medial axis with the EDF measures (3.5.1, Fig. 3.6, 3.7).
//
// Computes: the part of the medial graph whose points pass both thresholds,
// ET(x) = EDF(x) - R(x) >= T and ST(x) = 1 - R(x) / EDF(x) >= S (3.5.1 uses T = 0.05 of the
// shape's size and S = 1 - 1/sqrt(2)), and a topology-preserving variant.
//  - Along an edge of length w the EDF is piecewise linear (extended_grassfire.h: T_u + s
//    up to the quench point, T_v + w - s after it) and R is taken linear between its end
//    values (the piecewise-linear graph of 3.3.2), so on each linear piece both conditions
//    are affine inequalities in s: the kept part of a piece is an interval, cut exactly at
//    the threshold crossings (not at nodes). Points where the EDF is infinite (the 2-core)
//    have ET = infinity and ST = 1 and are kept for any S <= 1.
//  - Plain pruning keeps every passing point; the result may be disconnected (3.5.1).
//  - Topology-preserving pruning is the thinning of 3.3.2 stopped by the thresholds: leaves
//    that fail are peeled, an edge from a failing leaf is cut back to its first passing
//    point, and a node becomes a leaf when all but one of its branches are gone. The
//    result is the smallest subgraph that contains every passing point and has the
//    homotopy type of the axis; a tree component without passing points shrinks to its
//    EMA, the point where its last fronts met.
// Certification: decisions at nodes are exact signs of EDF - R - T and (1 - S) EDF - R;
// at quench points and crossings, exact signs of sums of products of exact values when
// these have no certified constants, Arb balls at doubling precision otherwise (an exact
// tie with constants is reported as uncertified and counts as failing). Positions of cut
// points are certified enclosures of the offset along the edge.
// Contract: `burning` (Exact variant) was computed on g; 0 <= S <= 1.
// Complexity: O(n + m) plus the exact work.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <vector>

#include "burn2/extended_grassfire.h"

namespace grassfire {

struct PruningThresholds {
  mpq_class erosion = 0;     // T, in the shape's units
  mpq_class tubularity = 0;  // S, in [0, 1]
  bool topology = false;     // the topology-preserving variant
};

constexpr std::uint32_t kCutPoint = 0xffffffffu;

struct PrunedNode {
  Point2 position;
  Interval radius, edf, erosion, tubularity;  // R, EDF, ET, ST (linear R at cut points)
  std::uint32_t source_node = kCutPoint;       // the original node, or kCutPoint
  std::uint32_t source_edge = 0;               // for a cut point: on this edge,
  Interval offset;                             //   at this distance from its end u
};

struct PrunedEdge {
  std::uint32_t u = 0, v = 0;      // indices into PrunedAxis::nodes
  std::uint32_t source_edge = 0;
  Interval from, to;                // the kept stretch, as distances from the source edge's u
  Interval length;
  EdgeKind kind = EdgeKind::Segment;
};

struct PrunedAxis {
  std::vector<PrunedNode> nodes;
  std::vector<PrunedEdge> edges;
  std::uint64_t passing_nodes = 0, cut_points = 0;
  std::uint64_t uncertified = 0;  // ties that no precision separated
};

PrunedAxis prune_axis(const MedialGraph& g, const GrassfireResult& burning, const PruningThresholds& t);

}  // namespace grassfire
