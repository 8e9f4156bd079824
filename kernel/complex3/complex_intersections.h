// complex_intersections.h -- is a 2-complex embedded? Exact search for improper
// intersections between its cells.
//
// Computes: a pair of cells (triangles, dangling segments) that meet outside
// their common faces, or nothing. Broad phase: CGAL box_intersection_d on bounding boxes
// of the exact coordinates (rounded outwards). Narrow phase, exact, in integer
// homogeneous coordinates: cells without a common vertex must not intersect at all (first
// a separation certificate: a strict separating plane, or for coplanar triangles a
// separating edge line; otherwise CGAL do_intersect with Epeck on the rational points);
// cells sharing exactly one vertex v meet beyond v iff their cones at v (the directions of
// their edges at v) overlap, since near v each flat cell is its cone and the set two
// convex cells share is convex; triangles sharing an edge meet beyond it only when
// coplanar on the same side, which MedialComplex's exact angular order already rejects.
// Contract: cells valid as RawComplex (indices, distinct vertices, no degenerate triangle).
// Complexity: O(n log n + k) for k box overlaps, each O(1) integer sign tests.
#pragma once

#include <optional>
#include <string>

#include "complex3/raw_complex.h"

namespace grassfire {

// The pair found first in the box scan (the message orders the pair deterministically).
std::optional<std::string> first_improper_intersection(const RawComplex& raw);

}  // namespace grassfire
