// complex_checks.h -- the input contract of a RawComplex, checked exactly.
//
// Computes: the first violation of the contract that MedialComplex requires (see
// medial_complex.h), as a message naming the cell and the problem, or nothing. Checks:
// non-empty; R^2 per vertex and >= 0; indices in range; no repeated vertex in a cell;
// distinct vertex positions; no collinear triangle; no duplicate triangle or segment.
// Edge-level conditions (a segment that is a triangle edge, overlapping triangles on an
// edge, border rules) are checked while the edges are built.
// Every geometric decision goes through the filtered exact predicates
// (filtered_predicates3.h): the answers are those of the rational predicates.
// Complexity: O(n log n) filtered comparisons.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "geometry3/filtered_predicates3.h"
#include "complex3/raw_complex.h"

namespace grassfire {

std::optional<std::string> first_raw_violation(const RawComplex& raw);
// The same on the parts of a complex, without copying them: the vertices are `points`,
// radius_squared(v) for v < radius_count.
std::optional<std::string> first_raw_violation(const FilteredPoints& points,
                                               const std::function<const mpq_class&(std::size_t)>& radius_squared,
                                               std::size_t radius_count,
                                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                               const std::vector<std::array<std::uint32_t, 2>>& segments);

}  // namespace grassfire
