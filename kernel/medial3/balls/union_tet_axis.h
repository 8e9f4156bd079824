// union_tet_axis.h -- the medial axis of a union of balls inside the tetrahedra of its
// dual complex: the Voronoi diagram of the boundary vertices, cut to each tetrahedron.
//
// Computes: for every tetrahedron tau of K (union_alpha_complex.h), Vor(V) ∩ tau where V
// is the set of vertices of the union's boundary; by Amenta-Kolluri (2001, Thm. 2) this
// is the medial axis inside |K| away from the singular simplices. Per tetrahedron, a
// candidate set C ⊇ {v in V nearest to some x in tau} is selected (below), and for each
// v in C its Voronoi cell tau ∩ {|x - v| <= |x - u|, u in C} is clipped exactly
// (exact_cell.h); the cell faces on bisector planes are the axis polygons.
// Candidates: with B = min_u max_{corners c} |c - u| (an upper bound of the distance from
// any x in tau to V, since |x - u| is convex), every v nearest to a point of tau has
// dist(v, tau) <= B; the test dist(v, bbox(tau)) <= B with outward-rounded intervals
// keeps a superset, which is all correctness needs.
// Identity of points across cells: a vertex's key is (the balls of the smallest face of
// tau containing it, the boundary vertices it is equidistant to by non-structural
// bisectors); a bisector of two boundary vertices on the sphere of every ball of that face
// passes through the face for structural reasons (and gives exact zeros without
// arithmetic). In general position equal points get equal keys; in degenerate positions
// points whose interval boxes overlap are compared exactly and merged.
// Contract: the inputs of one AlphaComplex and its boundary vertices (same RadicalTable).
// Complexity: per tetrahedron O(|C|^2) clips in the worst case; cells that a nearer
// candidate excludes at all four corners are skipped without clipping, and on the fast
// path also those excluded piece by piece on the eight tetrahedra of tau's midpoint split
// (with the exact ties at tau's corners and edges; 5.4 cells clipped per tetrahedron
// instead of 28.9 on random_ball_set(10^4)), and each cell's clips skip bisectors that
// certainly miss it (the reach bound and a ball around the cell).
#pragma once

#include <memory>
#include <vector>

#include "medial3/convex/exact_cell.h"
#include "medial3/balls/union_alpha_complex.h"

namespace grassfire {

struct TetAxisVertex {
  std::vector<std::uint32_t> feature;  // balls of the smallest simplex containing it (0..3)
  std::shared_ptr<const LazyPoint3> point;
  std::uint32_t nearest = 0;  // a boundary vertex at distance R
};

struct TetAxisPolygon {
  std::vector<std::uint32_t> vertices;  // convex, in order
  std::uint32_t v = 0, u = 0;           // the bisector of boundary vertices v and u
  std::shared_ptr<const CellPlane> plane;  // a x + b y + c z + d = 0 (exact on demand)
};

struct TetAxis {
  std::vector<TetAxisVertex> vertices;
  std::vector<TetAxisPolygon> polygons;
  ClipStats stats;
  std::size_t tetrahedra = 0;        // tetrahedra of K processed
  std::size_t candidates = 0;        // sum over tetrahedra of |C|
  std::size_t cells_clipped = 0;     // Voronoi cells computed (after the corner test)
  std::size_t clips = 0, beyond_reach = 0;  // bisectors clipped, and skipped by the reach bound
  std::size_t merged_by_position = 0;
  std::size_t key_collisions = 0;
};

// With `reach` (the fast path), a bisector of v and u is not clipped when |u - v| > 2 R
// for R the largest distance from v to a vertex of v's current cell (certified with
// intervals): every point of the cell is then strictly nearer to v, so the clip would
// change nothing (no vertex on the plane either). Without it, every candidate is clipped
// (the definition-level path); the output is the same.
TetAxis tet_axis(const BallSet& balls, const AlphaComplex& k, const std::vector<BoundaryVertex>& boundary,
                 const RadicalTable& table, bool reach = true);

// Exact equality of two points given homogeneously.
bool same_point(const HomogeneousPoint& a, const HomogeneousPoint& b, NumberStats* stats = nullptr);

}  // namespace grassfire
