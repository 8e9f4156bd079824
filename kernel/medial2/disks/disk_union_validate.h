// disk_union_validate.h -- the definition-level check of the medial axis of a union of
// disks (2.1.1: a medial point has two or more closest boundary points; Prop 3's premise:
// the axis has the homotopy type of the shape).
//
// Checks, by brute force over every corner and every boundary arc of the union:
//  1. every node is at distance exactly R from each of its closest corners (exact zero
//     tests of |x - q|^2 - R^2 in the node's multiquadratic field);
//  2. every node has two or more closest boundary points: a Voronoi vertex three or more
//     corners, a disk centre the whole of its arcs;
//  3. no boundary point is closer than R: every other corner is strictly farther, and for
//     every arc whose interior contains the radial projection of x, | |x - c| - r | > R
//     (squared twice into an exact sign: no nested radical is evaluated);
//  4. the same at the midpoint of every edge, whose closest points must be the edge's two
//     generating corners;
//  5. degrees: a centre with k arcs has degree k, a Voronoi vertex degree >= 3;
//  6. the axis has the Betti numbers of the union, computed independently from the dual
//     complex (DiskUnionAxisReport: b0 = components, b1 = holes).
// Each decision: a double interval filter, then the exact sign (number/exact_sum.h).
// Contract: g was built by disk_union_axis with this report.
// Complexity: O((n + m) (c + a)) for n nodes, m edges, c corners and a arcs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "medial2/disks/disk_union_axis.h"
#include "medial2/medial_graph.h"

namespace grassfire {

struct DiskAxisValidation {
  std::uint64_t nodes_checked = 0, edges_checked = 0, feature_tests = 0;
  std::uint64_t exact_decisions = 0;  // tests the interval filter left to the exact sign
  std::vector<std::string> failures;  // empty when valid
  bool ok() const { return failures.empty(); }
};

DiskAxisValidation validate_disk_union_axis(const MedialGraph& g, const DiskUnionAxisReport& report);

}  // namespace grassfire
