// mesh_embedding.h -- does a closed manifold triangle mesh bound a solid without touching
// itself? Exact checks, run by require_closed_manifold (mesh_checks.h) after the
// combinatorial ones.
//
// Computes: the first of (1) a triangle of zero area (three distinct but collinear
// vertices), (2) two triangles on a common edge that fold onto each other (coplanar, on the
// same side of the edge), (3) two triangles that meet outside their common vertices and
// edges (CGAL box intersection, then CGAL's filtered predicates, exact on the double
// coordinates; the pair reported is the smallest by triangle index). Any of them means the mesh is not the boundary of a solid as the builders need
// it; none is repaired (dropping a zero-area triangle opens the mesh, moving a vertex
// changes the solid).
// Contract: the mesh passed the combinatorial checks of require_closed_manifold (every edge
// in two triangles, one fan per vertex, distinct vertices). Errors are
// std::invalid_argument "<source>: <problem>", naming the faces by their index in the file
// (TriangleMesh3::triangle_origin).
// Complexity: O(n log n + k) for n triangles and k overlapping bounding boxes; the
// zero-area and fold tests are filtered in doubles (Shewchuk's static bounds) and exact
// only when the filter cannot decide.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "geometry3/triangle_mesh.h"

namespace grassfire {

void require_embedded(const TriangleMesh3& mesh);

// Test (1) for triangle t: its three vertices are collinear (exact).
bool has_zero_area(const TriangleMesh3& mesh, std::uint32_t t);

// Test (3) alone: the smallest pair (s, t), s < t, of triangles without a common edge that
// meet outside their common vertex, if any. Needs only triangles of positive area.
std::optional<std::array<std::uint32_t, 2>> first_crossing(const TriangleMesh3& mesh);

// The number of pairs test (3) finds among the triangles t with positive_area[t] (the
// defect census of mesh_repair.h; pairs on a common edge are not counted), for any
// triangle soup: exact.
std::size_t count_crossings(const TriangleMesh3& mesh, const std::vector<bool>& positive_area);

}  // namespace grassfire
