// polytope_cells.h -- convex polytopes with rational vertices from rational half-spaces.
//
// Computes: the intersection of a box with rational half-spaces (exact_cell.h with rational
// planes), read back as rational vertices and labelled outward faces; the polytope of a
// list of half-spaces with exact checks that it is bounded and has interior; exact
// centroids and volumes. Used by the convex-polyhedron medial axis (its facet cells).
// Boundedness: after scaling each plane to integer coefficients of magnitude <= M, every
// vertex of the arrangement solves a 3x3 integer system, so |coordinate| <= 3! M^3
// (Cramer; a nonzero integer determinant is >= 1 in magnitude). The box [-B, B]^3 with
// B = 6 M^3 + 1 therefore contains every vertex of the polytope, and the polytope is
// unbounded exactly when a box face survives the clipping.
// Contract: planes with rational coefficients only (no radicals).
// Complexity: as exact_cell.h, O(planes x cell size) sign tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "medial3/convex/exact_cell.h"

namespace grassfire {

struct PolytopeFace {
  std::vector<std::uint32_t> vertices;  // counter-clockwise seen from outside
  std::uint64_t label = 0;              // label of the plane that made the face
};

struct PolytopeCell {
  std::vector<ExactPoint3> points;
  std::vector<PolytopeFace> faces;
  bool touches_box = false;  // a face of the initial box survived
  ClipStats stats;
};

// Box planes carry labels 0..5; callers must use labels >= 6 for their planes.
constexpr std::uint64_t kFirstFreeLabel = 6;

// The box [lo, hi] clipped by `cuts` in order (empty faces when nothing is left).
PolytopeCell clip_box(const ExactPoint3& lo, const ExactPoint3& hi, const std::vector<CellPlane>& cuts);

// The polytope of the half-spaces; std::invalid_argument "<source>: ..." when it is empty,
// has no interior or is unbounded.
PolytopeCell polytope_from_planes(const std::vector<CellPlane>& planes, const std::string& source);

ExactPoint3 polygon_centroid(const PolytopeCell& cell, const PolytopeFace& face);  // vertex average
mpq_class polytope_volume(const PolytopeCell& cell);

}  // namespace grassfire
