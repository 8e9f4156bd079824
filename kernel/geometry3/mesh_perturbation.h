// mesh_perturbation.h -- seeded random perturbations of a closed triangle mesh's surface,
// for the stability of medial curves (5.1.3) and Fig. 5.5-style comparisons.
//
// Computes: a copy of the mesh whose every vertex moves along its normal (the sum of the
// incident triangles' area vectors, normalised) by amplitude x u, u uniform in [-1, 1],
// drawn from std::mt19937_64(seed) in vertex order; connectivity unchanged. The moved
// surface is within `amplitude` of the original in Hausdorff distance (each point of a
// triangle moves by at most the largest move of its corners).
// Contract: amplitude >= 0; a small amplitude relative to the mesh's features keeps the
// surface embedded, which is not checked here (the axis builders refuse a mesh that is
// not). Complexity: O(vertices + triangles).
#pragma once

#include <cstdint>

#include "geometry3/triangle_mesh.h"

namespace grassfire {

TriangleMesh3 perturb_mesh(const TriangleMesh3& mesh, double amplitude, std::uint64_t seed);
double mesh_bounding_diagonal(const TriangleMesh3& mesh);

}  // namespace grassfire
