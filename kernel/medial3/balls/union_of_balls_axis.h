// union_of_balls_axis.h -- the exact medial axis of a union of balls (2.1.1).
//
// Computes: the medial axis of U = union of balls B_i, after Amenta and Kolluri ("The
// medial axis of a union of balls", CGTA 2001): with K the dual complex of the power
// diagram at alpha = 0 (union_alpha_complex.h) and V the vertices of the boundary of U,
//   MA(U) = (the singular simplices of K)  ∪  (Vor(V) ∩ the tetrahedra of K),
// where a singular simplex is one of dimension < 3 with no coface in K (a ball alone: its
// centre; a singular edge: the segment of the two centres; a singular triangle: the
// triangle of the three centres, equidistant from its two mirror boundary vertices).
// The second part is union_tet_axis.h. Output: a RawComplex (triangles, the singular
// edges as segments, isolated centres as vertices) with R^2 per vertex, DistanceToPoint
// ignition on border edges (R(x) = |x - p| there, p the nearest boundary vertex), and the
// exact description of every vertex.
// Exactness: the combinatorics are exact. The singular simplices have rational vertices
// and rational R^2 (R^2 = |x - z|^2 - w with the simplex's power centre z and power w).
// Inside the tetrahedra, vertices lie in Q(sqrt s_1, ..., sqrt s_k) (the boundary vertices
// are z + sqrt(s) n), so they are irrational in general (not rational as for a union of
// disks' power diagram): they are kept exactly (vertex_info), and the RawComplex gets the
// midpoints of their certified interval enclosures (doubles, as rationals), with the
// error bounds coordinate_error, radius_squared_error, rule_point_error. A value is given
// exactly when a rational of denominator < 2^20 inside its enclosure is confirmed by an
// exact test (centres of symmetric configurations, for instance); vertex_info[v].exact
// says when coordinates and R^2 are all exact.
// Contract: at least one ball, positive squared radii (std::invalid_argument naming
// balls.source). Degenerate inputs (tangent, nested, collinear or cospherical balls) are
// handled by the exact predicates and the open dual complex (rho < 0).
// Complexity: O(n log n) expected for the triangulation, then per tetrahedron of K the
// clipping of union_tet_axis.h.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "geometry3/ball_set.h"
#include "medial3/convex/exact_cell.h"
#include "complex3/simplicial_homology.h"
#include "medial3/balls/union_alpha_complex.h"
#include "complex3/raw_complex.h"

namespace grassfire {

struct UnionOfBallsOptions {
  bool polygon_samples = false;  // one exact point per bisector polygon, for check_union_axis
  // The definition-level path, for tests: every shortcut of the fast path off (the boundary
  // vertices' interval filter, the Voronoi cells' reach bound, the output values' small-
  // integer continued fractions). The output is the same, vertex for vertex.
  bool reference = false;
};

struct AxisVertexInfo {
  bool exact = false;  // coordinates and R^2 in the RawComplex are the exact values
  std::shared_ptr<const LazyPoint3> point;  // exact coordinates (on demand)
  std::int64_t nearest = -1;   // index of a nearest boundary vertex (tetrahedra part)
  std::int64_t simplex = -1;   // index in `singular` of a singular simplex it lies on
};

struct UnionAxisPolygonSample {  // a point of a bisector polygon, for definition checks
  std::shared_ptr<const HomogeneousPoint> point;
  std::uint32_t v = 0, u = 0;  // the two boundary vertices it is equidistant to
};

struct UnionOfBallsAxis {
  RawComplex complex;
  std::vector<AxisVertexInfo> vertex_info;
  double coordinate_error = 0;      // max |approximate - exact| over coordinates
  double radius_squared_error = 0;  // max over R^2
  double rule_point_error = 0;      // max over the coordinates of ignition points
  std::shared_ptr<RadicalTable> radicals;
  std::vector<BoundaryVertex> boundary;
  std::vector<PowerSimplex> singular;  // the singular simplices of K (part of the axis)
  std::vector<UnionAxisPolygonSample> samples;
  // Structure.
  std::size_t balls = 0, hidden_balls = 0;
  int triangulation_dimension = -1;
  std::array<std::size_t, 4> alpha_simplices{};    // simplices of K by dimension
  std::array<std::size_t, 3> singular_simplices{};  // singular vertices, edges, triangles
  std::size_t tet_polygons = 0, tetrahedra_candidates = 0, voronoi_cells = 0;
  std::size_t clips = 0, beyond_reach = 0;  // bisectors clipped, skipped by the reach bound
  std::size_t merged_by_position = 0, key_collisions = 0;
  BettiNumbers union_betti;  // of K, i.e. of the union
  ClipStats stats;
  double triangulation_seconds = 0, total_seconds = 0;
  // The profile: CPU seconds per stage, in order (triangulation, alpha complex, ...).
  std::vector<std::pair<std::string, double>> stage_seconds;
};

UnionOfBallsAxis union_of_balls_axis(const BallSet& balls, const UnionOfBallsOptions& options = {});

// Throws std::invalid_argument "<source>: ..." for an empty set or a non-positive or
// non-finite squared radius.
void require_valid_balls(const BallSet& balls);

}  // namespace grassfire
