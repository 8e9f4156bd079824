// refined_mesh.h -- closed test and benchmark meshes of 10^3 .. 10^5 faces (docs/exact-engine.md).
//
// Computes: `smoothing` steps of Laplacian smoothing of a closed triangle mesh (each
// vertex moves half way to the mean of its neighbours), then Loop subdivision (CGAL
// Subdivision_method_3), k levels (each splits every face in four: faces * 4^k). Loop's
// vertex rule is itself a smoothing (the limit surface is C^1), but it keeps a flat region
// flat where all its vertices and their neighbours are coplanar (the large faces of
// cross.off); the Laplacian steps first move every vertex of the coarse mesh off such
// planes, so that neighbouring faces of the refined mesh are not coplanar:
// coplanar_neighbour_pairs counts the pairs that still are, exactly. Coordinates are the
// doubles computed, which are exact rationals (mesh_as_complex reads them exactly).
// Deterministic: no randomness; elements are visited in their index order.
// Contract: a manifold triangle mesh (std::invalid_argument otherwise); levels, smoothing >= 0.
// Complexity: O(faces * 4^levels); coplanar_neighbour_pairs O(edges) exact predicates.
#pragma once

#include <cstddef>

#include "geometry3/triangle_mesh.h"

namespace grassfire {

TriangleMesh3 loop_subdivided(const TriangleMesh3& mesh, int levels, int smoothing = 0);
// The number of levels that brings faces * 4^levels closest to target (ratio in log).
int loop_levels_for(std::size_t faces, std::size_t target);
// Two smoothing steps, then loop_subdivided at loop_levels_for(faces, target).
TriangleMesh3 refined_mesh(const TriangleMesh3& mesh, std::size_t target_faces);
// Pairs of faces sharing an edge whose four vertices are coplanar (exact).
std::size_t coplanar_neighbour_pairs(const TriangleMesh3& mesh);

}  // namespace grassfire
