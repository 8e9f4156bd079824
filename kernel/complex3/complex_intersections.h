// complex_intersections.h -- is a 2-complex embedded? Exact search for improper
// intersections between its cells.
//
// Computes: a pair of cells (triangles, dangling segments) that meet outside
// their common faces, or nothing. Broad phase: CGAL box_intersection_d on bounding boxes
// of the exact coordinates (rounded outwards). Narrow phase, exact: cells without a common
// vertex must not intersect at all (first a separation certificate: a strict separating
// plane, or for coplanar triangles a separating edge line; a segment strictly on one side
// of a triangle's plane; two segments not coplanar; otherwise CGAL do_intersect with Epeck
// on the rational points); cells sharing exactly one vertex v meet beyond v iff their
// cones at v (the directions of their edges at v) overlap, since near v each flat cell is
// its cone and the set two convex cells share is convex; triangles sharing an edge meet
// beyond it only when coplanar on the same side, which MedialComplex's exact angular order
// already rejects. Every sign is taken first from interval enclosures
// (filtered_predicates3.h); when one is not certified, the whole pair is decided again in
// integer homogeneous coordinates (and CGAL), so the answer is the exact one.
// Contract: cells valid as RawComplex (indices, distinct vertices, no degenerate triangle).
// Complexity: O(n log^3 n + k) for k box overlaps (CGAL's box intersection), each O(1)
// filtered sign tests.
#pragma once

#include <optional>
#include <string>

#include "geometry3/filtered_predicates3.h"
#include "complex3/raw_complex.h"

namespace grassfire {

// The pair found first in the box scan (the message orders the pair deterministically).
std::optional<std::string> first_improper_intersection(const RawComplex& raw);
// The same with the enclosures of raw.vertices already computed.
std::optional<std::string> first_improper_intersection(const RawComplex& raw, const FilteredPoints& points);

}  // namespace grassfire
