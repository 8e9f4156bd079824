// complex_checks.h -- the input contract of a RawComplex, checked exactly.
//
// Computes: the first violation of the contract that MedialComplex requires (see
// medial_complex.h), as a message naming the cell and the problem, or nothing. Checks:
// non-empty; R^2 per vertex and >= 0; indices in range; no repeated vertex in a cell;
// distinct vertex positions; no collinear triangle; no duplicate triangle or segment.
// Edge-level conditions (a segment that is a triangle edge, overlapping triangles on an
// edge, border rules) are checked while the edges are built.
// Complexity: O(n log n) exact comparisons.
#pragma once

#include <optional>
#include <string>

#include "complex3/raw_complex.h"

namespace grassfire {

std::optional<std::string> first_raw_violation(const RawComplex& raw);

}  // namespace grassfire
