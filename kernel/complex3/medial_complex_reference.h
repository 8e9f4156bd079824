// medial_complex_reference.h -- the all-rational definition of the MedialComplex's
// predicate-dependent decisions, for tests and bench_complex_build to compare with.
//
// Computes, from a MedialComplex (its vertices, edges and triangles): every edge's triangles
// in angular order by the rational EdgeAngularOrder of exact_predicates3.h (projections
// formed as rationals, the triangles sorted from the first one, as the construction before
// the filtered predicates did), and every sheet's planarity by rational orientation against
// the plane of its first triangle. No interval filter, no shortcut: the slow reference the
// filtered construction (filtered_predicates3.h) must agree with.
// Contract: a constructed MedialComplex. Complexity: O(sum over edges of k log k) rational
// predicates for k triangles on an edge, plus O(corners) orientations.
// Section: docs/design.md 3 (every fast algorithm has a slow definition-level reference), 5.
#pragma once

#include <cstdint>
#include <vector>

#include "complex3/medial_complex.h"

namespace grassfire {

struct ReferenceDecisions {
  std::vector<std::vector<std::uint32_t>> edge_triangles;  // per edge, in angular order
  std::vector<bool> sheet_planar;                          // per sheet
};

ReferenceDecisions reference_decisions(const MedialComplex& mc);

// How many edges and sheets the construction decided differently from the reference.
std::size_t reference_mismatches(const MedialComplex& mc, const ReferenceDecisions& ref);

}  // namespace grassfire
