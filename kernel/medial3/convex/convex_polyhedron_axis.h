// convex_polyhedron_axis.h -- the exact medial axis of a convex polyhedron (2.1.1).
//
// Computes: for P = {x : a_i x + b_i y + c_i z <= d_i}, the closure of the interior points
// with two or more nearest boundary points, as a RawComplex with R^2 per vertex. Inside a
// convex polyhedron the distance to the boundary is D(x) = min_i g_i(x), g_i the distance
// to facet plane i; D is a minimum of affine functions, the cells C_i = {g_i <= g_j for
// all j} tile P face-to-face, and the medial axis is the union of the 2-faces C_i ∩ C_j
// (each polygon triangulated as a fan). Its border is the edge set of P, where R = 0.
// Exactness: g_i = (d_i - n_i . x) / |n_i| is rational up to a common factor when every
// |n_i|^2 lies in one square class s (|n_i|^2 = s q_i^2, q_i rational): axis-aligned and
// Pythagorean normals (s = 1), the octahedron's (1,1,1) (s = 3), and so on. Then every
// vertex, R^2 = (min_i (d_i - n_i . x) / q_i)^2 / s and every decision is exact.
// Otherwise ("approximate mode") each plane whose |n_i| is irrational is replaced by the
// plane through its facet's centroid with a rational unit normal within 2^-bits of n_i/|n_i|
// (inverse stereographic projection of a rounded point); the result is the exact medial
// axis of that polyhedron P', and `distance_bound` certifies |D_P - D_P'| <= bound on P ∩ P'.
// Contract: P bounded with non-empty interior; a mesh must be a closed, consistently
// oriented, convex triangle mesh (checked exactly; std::invalid_argument names the file
// and the offending triangle and vertex). Redundant planes are dropped and counted.
// Complexity: m facets, O(m) clips per cell of O(cell size) filtered sign tests each:
// O(m^2 k) with k the typical cell size.
#pragma once

#include <gmpxx.h>

#include <istream>
#include <string>
#include <vector>

#include "medial3/convex/exact_cell.h"
#include "complex3/raw_complex.h"
#include "geometry3/triangle_mesh.h"

namespace grassfire {

struct HalfSpace {
  mpq_class a, b, c, d;  // a x + b y + c z <= d
};

struct ConvexPolyhedron {
  std::string source;
  std::vector<HalfSpace> planes;
};

// The half-space text format (.hs files) is read by io/halfspace_list.h.
// The facet planes of a closed convex triangle mesh (coplanar triangles merged).
ConvexPolyhedron convex_polyhedron_from_mesh(const TriangleMesh3& mesh);
// A seeded random test polyhedron: the cube [-2, 2]^3 cut by 1-4 planes whose normals have
// rational length (every |n|^2 a square, so the builder is exact), at offsets from |n| (at
// distance 1 from the centre) to just below the largest n . x on the cube.
ConvexPolyhedron random_cut_cube(std::uint32_t seed);

struct ConvexAxisOptions {
  long approximation_bits = 24;  // approximate mode: rational unit normals within about 2^-bits
};

struct ConvexAxis {
  RawComplex complex;
  bool exact = true;          // every |n_i| in one square class: no approximation at all
  double distance_bound = 0;  // approximate mode: |D_P - D_P'| <= distance_bound on P ∩ P'
  // The polyhedron whose axis this is: g_i(x) = (e_i - u_i . x) / sqrt(s), one per facet.
  std::vector<ExactPoint3> u;
  std::vector<mpq_class> e;
  mpq_class s = 1;
  std::size_t redundant_planes = 0;
  std::size_t polygons = 0;                    // medial faces C_i ∩ C_j before triangulation
  mpq_class volume, cell_volume_sum;           // of P', and of its cells (equal when correct)
  ClipStats stats;
};

ConvexAxis convex_polyhedron_axis(const ConvexPolyhedron& p, const ConvexAxisOptions& options = {});

// Definition-level check (exact): at every vertex and at the centroid of every triangle
// of the axis, at least two facet planes attain the minimum distance and the point lies in
// P; R^2 at every vertex equals min g_i^2. Returns the number of points checked and the
// first failure.
struct DefinitionCheck {
  std::size_t points = 0;
  std::size_t failures = 0;
  std::string first_failure;
};
DefinitionCheck check_convex_axis(const ConvexAxis& axis);

}  // namespace grassfire
