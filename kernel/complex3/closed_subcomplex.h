// closed_subcomplex.h -- the maximal closed subcomplex of a medial complex (Prop. 7).
//
// Computes: the largest subcomplex without boundary, by peeling: repeatedly remove a
// triangle that has an edge with no other remaining triangle and no remaining segment (a
// border edge of what remains), and a segment with an end vertex that has no other
// remaining cell. What survives is closed (every remaining edge has >= 2 remaining
// triangles, or is a segment whose ends continue), and it is maximal because a cell with
// a free face lies in no closed subcomplex, inductively. An isolated vertex is its own
// border (it ignites at R) and is not kept. Prop. 7: BT = infinity exactly there.
// Contract: a validated MedialComplex. Complexity: O(cells).
#pragma once

#include <vector>

#include "complex3/medial_complex.h"

namespace grassfire {

struct ClosedSubcomplex {
  std::vector<bool> triangle;  // per triangle: kept
  std::vector<bool> edge;      // per edge: has a kept triangle, or is a kept segment
  std::vector<bool> vertex;    // per vertex: lies on a kept cell
  std::size_t triangles = 0, edges = 0, vertices = 0;
};

ClosedSubcomplex maximal_closed_subcomplex(const MedialComplex& mc);

}  // namespace grassfire
