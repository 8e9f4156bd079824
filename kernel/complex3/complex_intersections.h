// complex_intersections.h -- is a 2-complex embedded? Exact search for improper
// intersections between its cells.
//
// Computes: the first pair of cells (triangles, dangling segments) that meet outside
// their common faces, or nothing. Broad phase: CGAL box_intersection_d on bounding boxes
// of the exact coordinates (rounded outwards). Narrow phase, with CGAL's filtered exact
// predicates on the rational coordinates (Epeck): cells without a common vertex must not
// intersect at all (CGAL do_intersect); cells sharing exactly one vertex v meet beyond v
// iff their cones at v (the directions of their edges at v) overlap, since near v each flat
// cell is its cone and the set two convex cells share is convex: an exact rational test on
// direction vectors; triangles sharing an edge meet beyond it only when coplanar on the
// same side, which MedialComplex's exact angular order already rejects.
// Contract: cells valid as RawComplex (indices, distinct vertices, no degenerate triangle).
// Complexity: O(n log n + k) for k box overlaps, each an O(1) filtered predicate.
#pragma once

#include <optional>
#include <string>

#include "complex3/raw_complex.h"

namespace grassfire {

std::optional<std::string> first_improper_intersection(const RawComplex& raw);

}  // namespace grassfire
