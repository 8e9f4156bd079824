// mesh_checks.h -- is a triangle mesh the boundary of a solid? Exact checks.
//
// Computes: whether a TriangleMesh3 is a closed, consistently oriented, embedded 2-manifold
// without duplicate or unused vertices (mesh_embedding.h: no zero-area triangle, no fold,
// no self-intersection), and which way it is oriented; exact orientation of four double
// points. The medial-axis builders (convex polyhedron, mesh poles) require solids.
// Contract: coordinates finite, indices in range, three distinct indices per triangle
// (what the readers guarantee). Errors are std::invalid_argument "<source>: <problem>",
// naming the first offending vertex, edge or face by its index in the file and its point.
// Complexity: O(n log n) for n triangles; the orientation filter is Shewchuk's static
// bound for orient3d on doubles, with an exact rational fallback.
#pragma once

#include <array>

#include "complex3/raw_complex.h"
#include "geometry3/triangle_mesh.h"

namespace grassfire {

// Every edge in exactly two triangles, used once in each direction; every vertex used,
// with one fan of triangles around it; no two vertices at the same point; embedded
// (require_embedded).
void require_closed_manifold(const TriangleMesh3& mesh);

// +1 when the triangles are oriented outward (positive signed volume), -1 inward, 0 for
// zero volume; exact. The mesh must be closed.
int mesh_orientation(const TriangleMesh3& mesh);

// Sign of det[b - a, c - a, d - a], exactly.
int orient3d(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
             const std::array<double, 3>& d);

ExactPoint3 exact_point(const std::array<double, 3>& p);

}  // namespace grassfire
