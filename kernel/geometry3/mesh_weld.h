// mesh_weld.h -- meshes as people have them: exactly repeated vertices welded, degenerate
// and repeated faces dropped, each counted (TriangleMesh3::cleanup), before any check.
//
// Computes, on a mesh as a reader parsed it or a repair made it (vertices and triangles in
// order, every triangle tagged with its file face in triangle_origin):
//  1. weld: vertices at exactly the same point (equal doubles; -0 = +0) become one, the
//     first in order; STL, which repeats every vertex in every facet, needs this;
//  2. degenerate faces: triangles left with fewer than three distinct vertices are dropped
//     (safe: such a triangle covers no area and its edges cancel in pairs);
//  3. repeated faces: a triangle on the same three vertices as an earlier one (either
//     orientation) is dropped, the first is kept;
//  4. unused vertices: points on no remaining triangle are dropped;
// then renumbers the vertices in order and records the file index of each one
// (vertex_origin). Nothing else is repaired: zero-area triangles with three distinct
// vertices, open edges, non-manifold edges or vertices and self-intersections are refused
// by the solid checks (medial3/mesh/mesh_checks.h), which name the file's elements,
// since dropping or moving anything there would change the solid. The readers call it
// through io/mesh_input.h's finish_mesh_reading; the repair (medial3/mesh/mesh_repair.h)
// calls it first.
// Complexity: O(n log n) for n vertices and triangles; no floating-point arithmetic.
#pragma once

#include <string>

#include "geometry3/triangle_mesh.h"

namespace grassfire {

// Steps 1-4 above; adds to mesh.cleanup. triangle_origin must have one entry per triangle.
void weld_and_drop(TriangleMesh3& mesh);

// "welded 24 repeated vertices, dropped 2 degenerate faces", or "" when nothing was repaired.
std::string describe_cleanup(const MeshCleanup& c);

}  // namespace grassfire
