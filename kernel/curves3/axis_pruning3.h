// axis_pruning3.h -- a 3D medial axis pruned by erosion thickness ET = BT - R and shape
// tubularity ST = 1 - R / BT (3.4.1, 3.5.1 lifted to the burning time of ch. 4; Yan, Sykes,
// Chambers, Letscher, Ju 2016), cut exactly where a threshold is crossed, keeping the
// homotopy type of the axis.
//
// What is cut. BT jumps across singular curves (Prop. 6), so one value per vertex cannot
// describe it on every sheet: the values are read per cell.
//  - On a triangle t of M: BT_t, the linear interpolation of t's side times at its corners
//    (burning_field.h: the limit of BT from inside t, the time t's own fire reached the
//    corner; at a corner inside one sheet, an interior or border vertex, it equals the point
//    time, BT being continuous within a sheet, Prop. 4), and R, the linear interpolation of
//    the corners' radii.
//  - On an edge of M (border, manifold, singular or dangling) and at a vertex of M: BT, the
//    linear interpolation of the point times at the edge's ends (the link rule applied),
//    and R likewise.
// With these piecewise-linear fields, ET >= T is the half-plane E = BT - R - T >= 0 of each
// cell and ST >= S is the half-plane G = (1 - S) BT - R >= 0 (R <= (1 - S) BT). Where
// BT = 0 (then R = 0: a border igniting at 0) ST is undefined and G = 0; such points fail
// a threshold S > 0, so that failing sheets can collapse from that border. The threshold lines
// E = 0 and G = 0 cut every triangle into convex pieces; their points on the edges of M
// (and the edges' own crossings) split the edges, so the pieces, fanned into triangles
// (from an added centroid where a side carries split points of a neighbour), form a
// subdivision K of M. Every cut point is an exact rational point: the field values are the
// doubles the burning gives, taken at their exact binary values, and the crossing
// parameter on an edge, (0 - E(a)) / (E(b) - E(a)), is rational. BT = infinity (a corner
// that never burns) makes E and G infinite wherever that corner's weight is positive: a
// triangle with such a corner is not cut by that function and its interior passes.
// A simplex of K fails when E < 0 or G < 0 at its centroid (exactly, in rationals; no
// threshold given: that function is not used). Points with E = 0 or G = 0 pass (as prune2d:
// ET >= T is kept).
//
// Homotopy. The failing simplices are removed by elementary collapses only, from the free
// border inward, in the order of the fire (the largest BT of the removed pair's larger
// simplex, then its index): a failing triangle with a free failing edge (no other
// triangle left on it) goes with that edge; a failing edge with no triangle left and a free
// failing end (no other edge left at it) goes with that vertex. Every step is a
// deformation retraction, so the result has the homotopy type of M: a threshold never
// opens a hole, closes a cavity's shell or splits or removes a component. Failing simplices
// that no collapse reaches stay (a failing disk shrinks to a point, a failing tube to a
// cycle) and are counted (`kept_failing_*`). The Betti numbers of M, of K and of the result
// are computed by simplicial homology over GF(2) (complex3/simplicial_homology.h),
// independently of the collapse, and must all agree (std::logic_error otherwise).
//
// Certification. The cut is exact for the fields above. Whether those fields are the true
// BT is the burning method's claim: the exact engine gives each vertex's BT with a
// certified error bound; a vertex (of M) whose E or G is within that bound of 0 may lie on
// the other side of the true threshold and is counted as `uncertified` (with the
// discrete baseline, an upper bound without a lower one, nothing is certified).
//
// Contract: a validated MedialComplex; vertex_bt per vertex, corner_bt per triangle
// (corners in t.v order), both >= 0 or +infinity; vertex_bt_error per vertex or empty;
// thresholds >= 0, S <= 1.
// Complexity: O(n) exact rational clippings for n cells, O(k log k) for the collapse of the
// k simplices of K, plus the homology (near-linear: free faces are peeled first).
// Section: 3.4.1, 3.5.1 (ET, ST, pruning), 5.1.2 (deformation retract following the fire),
// ch. 4 (Definitions 9-10, Prop. 6).
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "complex3/simplicial_homology.h"
#include "complex3/medial_complex.h"
#include "complex3/raw_complex.h"

namespace grassfire {

struct AxisValues3 {
  std::vector<double> vertex_bt;                  // per vertex of M: BT of the point
  std::vector<std::array<double, 3>> corner_bt;   // per triangle: BT_t at t.v[0..2] (side times)
  std::vector<double> vertex_bt_error;            // per vertex, or empty: none certified
};

struct PruningThresholds3 {
  std::optional<mpq_class> erosion;     // T, absolute: keep ET >= T
  std::optional<mpq_class> tubularity;  // S in [0, 1]: keep ST >= S
};

struct PrunedVertex3 {
  enum class On : std::uint8_t { Vertex, Edge, Triangle };
  On on = On::Vertex;
  std::uint32_t cell = 0;  // the vertex, edge or triangle of M it lies in
  double radius = 0, bt = 0;  // the fields above at the point (bt infinite where nothing burns)
  bool fails = false;
};

struct Pruning3Stats {
  std::uint64_t refined_vertices = 0, refined_edges = 0, refined_triangles = 0;  // K
  std::uint64_t cut_points = 0;  // vertices of K that are not vertices of M
  std::uint64_t failing_triangles = 0, failing_edges = 0, failing_vertices = 0;  // in K
  std::uint64_t removed_triangles = 0, removed_edges = 0, removed_vertices = 0;
  std::uint64_t kept_failing_triangles = 0, kept_failing_edges = 0, kept_failing_vertices = 0;
  std::uint64_t uncertified = 0;  // vertices of M within their BT error of a threshold
  double seconds = 0;
};

struct PrunedAxis3 {
  RawComplex complex;                  // the result, exact (R^2 exact at M's vertices,
                                       // (interpolated R)^2 at cut points)
  std::vector<PrunedVertex3> vertices; // per vertex of `complex`
  BettiNumbers betti_axis, betti_refined, betti_pruned;
  Pruning3Stats stats;
};

PrunedAxis3 prune_axis3(const MedialComplex& mc, const AxisValues3& values, const PruningThresholds3& thresholds);

}  // namespace grassfire
