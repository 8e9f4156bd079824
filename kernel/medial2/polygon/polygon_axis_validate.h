// polygon_axis_validate.h -- the definition-level check of an exact polygon axis
// (2.1.1: a medial point has two or more closest boundary points; docs/exactness.md).
//
// Checks, by brute force over every boundary segment of the polygon:
//  1. every node is equidistant to each of its defining sites: an exact zero when the
//     circle is a sum of square roots, else an Arb residual below 2^-200 (counted);
//  2. no boundary feature is closer to a node than R: for every closed boundary segment,
//     both endpoints and the interior projection are at distance >= R, decided by a
//     double interval, then Arb, then exactly where the circle has an exact form (ties
//     are expected only at the node's own sites, which are skipped as proved by 1);
//  3. every edge's two sites define both of its end nodes, and its mid point (the mid
//     parameter of the bisector) is equidistant to the two sites with no closer feature;
//  4. the leaves are exactly the convex polygon vertices, each an apex with R = 0.
// Contract: g was built by exact_polygon_axis.
// Complexity: O((n + m) s) for n nodes, m edges, s boundary segments.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "medial2/medial_graph.h"

namespace grassfire {

struct AxisValidation {
  std::uint64_t nodes_checked = 0, edges_checked = 0, boundary_tests = 0;
  std::uint64_t exact_decisions = 0;  // signs needing the exact form
  std::uint64_t ball_decisions = 0;   // signs needing Arb
  std::uint64_t residual_ties = 0;    // equidistance certified to 2^-200 only (nested radicals)
  std::vector<std::string> failures;  // empty when valid
  bool ok() const { return failures.empty(); }
};

AxisValidation validate_polygon_axis(const MedialGraph& g);

}  // namespace grassfire
