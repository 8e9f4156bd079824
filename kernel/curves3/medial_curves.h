// medial_curves.h -- medial curves of a 3D medial axis from its burning (5.1.2, Fig. 5.2).
//
// Definition (continuous). Let M be a medial complex with burning time BT (Definitions
// 9-10) and burning paths (burning_field.h). At a point x of M with BT(x) finite, each
// sheet-side i of x (the two half-disks of a point of a sheet, cut along a line through x;
// the k sectors of a point of a singular curve, 4.2.2) carries the direction d_i in which
// the fire moves at x inside side i, the side time BT_i(x) (burning_field.h), and the
// outward conormal n_i of side i at x. Side i ARRIVES when <d_i, n_i> > 0 (its fire runs
// into x) and DEPARTS when < 0 (fire leaves x into it). x is a PATH END (a raw medial-curve
// point: some burning path ends at x) when
//  (a) some side arrives and none departs: the arriving fire cannot go on (inside a sheet:
//      fronts from different directions quench, a ridge of BT; on a singular curve: the
//      fire ends there); or
//  (b) x lies on a singular curve and a side arrives before x burns, BT_i(x) < BT(x): its
//      front reached the curve and died while the curve waited for its (k-1)-th arrival
//      (4.2.1).
// Not path ends: points where the arriving fire passes through into the last sheet (one
// arrival at BT(x), one departure), or arrives from two sheets at the same time and goes on
// into a third (the edges of the box's middle rectangle); border points (there fire
// starts; on a medial axis BT >= R = f, so no front arrives early). Dangling segments
// (1-dimensional parts of M) are medial curves as they are. The board and fin: the
// junction N beyond the kink k (the back side's fire arrives first and dies); before k the
// back side's fire passes through N into the front side and the fin's runs along N.
//
// Why the raw ends are not yet the answer. Their closure can be disconnected (Fig. 5.2) and
// can also hold a cycle that bounds a disk of M: on the Y of widths 2, 3, 4 (height 10)
// page 1's fire dies on the spine for 2 < z < 8, and page 3 has a ridge at u = 1/2 joined
// to the spine at z = 3 and z = 7; spine and ridge enclose a strip of page 3. Joining
// pieces by burning paths alone would keep that cycle. So the curves are made homotopy
// preserving by a deformation retraction that follows the fire (5.1.2: "the extended
// grassfire can also be used to define a deformation retract"):
//
// Construction (discrete, on the refinement K of axis_refinement.h).
//  1. Raw ends: an edge of K lying inside M (not on M's border) is a raw end when the rule
//     above holds with d_i the fire's direction at the centroid of each incident triangle
//     of K, n_i its outward conormal, BT_i(x) the mean of that triangle's side times at
//     the edge's ends and BT(x) the mean of their point times; "arrives" means a cosine
//     above arrive_cosine and "departs" one below -depart_cosine (hysteresis: a smooth
//     front crossing an edge of K at a shallow angle has cosines c and -c on its two sides,
//     and direction noise must not turn it into an end; an edge of K need not follow a
//     ridge, which then crosses K as a staircase of edges where one side arrives and the
//     other runs along), and "before" means earlier by more than time_margin (the field's
//     error scale: its resolution h for the baseline, 0 for an exact field). Fronts that
//     run into x at less than asin(arrive_cosine) are not ends: a significance threshold,
//     like the separation angle of 2.2.1. Then closed up: from every end of a piece of
//     raw ends, the shortest path of at most closing_hops edges of K to another piece
//     is added (a ridge crossing K obliquely is a staircase whose steps meet at vertices or
//     one edge apart), and pieces shorter than min_length are dropped (significance by
//     length; a piece of one or two edges is discretisation noise at a corner), and so
//     are pieces whose largest ET = BT - R stays below min_et_fraction of the axis' largest
//     ET (significance by erosion thickness, 3.4.1: fronts that meet right after they
//     start, at the bumps of a sampled surface, carve no shape; 0 keeps them all).
//  2. Punctures: the triangles of K that never burn (BT = infinity: the maximal closed
//     subcomplex, Prop. 7) carry the 2-cycles of M. The triangles whose boundary columns
//     reduce to zero over GF(2) are removed; there are b2 of them, and b0, b1 do not change
//     (removing a triangle whose boundary is a sum of other boundaries).
//  3. Burning collapse: the triangles of K are removed in the order of their burn key (the
//     largest corner time BT_t: when the fire has swept them), each together with a free
//     edge (an edge with no other remaining triangle) that is not a raw end, taking the one
//     that became free first (the edge the fire came through): an elementary collapse, as
//     the fire burns a triangle from its free side. On a singular edge of M with k sheets
//     the edge is free once k-1 are gone: Definition 9's (k-1)-th arrival. Raw ends are
//     walls: never collapsed, so the fire's quench lines stay. When no triangle can go, a
//     wall is opened: the blocked triangle with the smallest key loses the wall edge the
//     fire entered it through (largest cosine); this breaks cycles like the Y's.
//  4. Peeling: what remains is a graph (no triangle has a free edge left unless the
//     residue is a closed part that punctures could not open: then `residual_triangles` >
//     0 and validate() fails). Leaves whose edge is not a raw end (or a dangling segment of
//     M) are peeled repeatedly: the hair of the discrete fronts goes, the raw ends and the
//     edges joining them stay.
// Every step is an elementary collapse or a puncture of step 2, so the graph is a
// deformation retract of M minus the punctures: it has the b0 and b1 of M (and b2 = 0).
// The joins between pieces of raw ends are edges where the discrete fronts met at angles
// below the threshold, or singular-curve edges along which the fire ran while the sheets
// burned beside it (the Y's spine below z = 3): pieces of quench lines and of burning
// paths; they are not computed as burning paths.
//
// Contract: a BurningField of a validated complex (any implementation, burning_field.h).
// Guarantees checked by validate(): a graph (1-dimensional); every edge a segment of one
// closed cell of M (a triangle, or an edge of M), exactly: both its nodes lie in that
// cell's closure combinatorially (a vertex of it, a point of one of its edges, or a point
// inside it), each node is a convex combination of its own cell's vertices (weights in
// [0, 1] summing to 1, within 1e-12), and its double position is that combination within
// 1e-9 of the bounding diagonal (a direct evaluation, well conditioned even on slivers);
// and b0, b1 equal to those of M by simplicial homology over GF(2)
// (complex3/simplicial_homology.h), computed independently of the construction.
// Complexity: O(K log K) for K triangles of the refinement, plus the GF(2) reduction of the
// never-burning part (quadratic in its size in the worst case).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "curves3/axis_refinement.h"
#include "burn3/burning_field.h"
#include "complex3/simplicial_homology.h"

namespace grassfire {

struct MedialCurveOptions {
  double arrive_cosine = 0.5;  // step 1: arriving at 30 degrees or more
  double depart_cosine = 0.1;  // step 1: departing at 6 degrees or more
  double time_margin = -1;     // step 1's time threshold; < 0: the field's resolution
  int closing_hops = 2;        // step 1: gaps of up to this many edges of K are closed
  double min_length = -1;      // step 1: shorter pieces are dropped; < 0: 3 x resolution
  double min_et_fraction = 0;  // step 1: pieces whose largest ET is below this fraction of
                               // the axis' largest ET are dropped (0: none)
};

struct CurveNode {
  Vec3d position{};
  double radius = 0, bt = 0;  // ET = bt - radius
  RefinedVertex::On on = RefinedVertex::On::Vertex;  // where it lies in M (axis_refinement.h)
  std::uint32_t cell = 0, index = 0;
  std::array<double, 3> weight{1, 0, 0};
};

struct CurveEdge {
  std::uint32_t u = 0, v = 0;
  double length = 0;
  std::uint32_t on_edge = kNoIndex;      // parent cell in M: an edge of M, or
  std::uint32_t in_triangle = kNoIndex;  // the triangle of M it crosses
  bool raw_end = false;                  // a raw medial-curve edge (step 1), else a join
  bool segment = false;                  // on a dangling segment of M (a 1-dimensional part)
};

struct MedialCurveStats {
  std::uint64_t refined_vertices = 0, refined_edges = 0, refined_triangles = 0;
  std::uint64_t raw_end_edges = 0;      // step 1
  std::uint64_t punctures = 0;          // step 2 (= b2 of M)
  std::uint64_t walls_opened = 0;       // step 3
  std::uint64_t residual_triangles = 0; // not collapsible (0 unless a closed part stays)
  std::uint64_t peeled_edges = 0;       // step 4
  double seconds = 0;
};

struct MedialCurves {
  std::vector<CurveNode> nodes;
  std::vector<CurveEdge> edges;
  BettiNumbers axis_betti;    // of M, by simplicial homology
  BettiNumbers curve_betti;   // of the graph (b2 = 0)
  std::string method;         // the field's
  MedialCurveOptions options;
  MedialCurveStats stats;

  // Throws std::logic_error naming the first violated guarantee (see above).
  void validate(const MedialComplex& mc) const;
  double total_length() const;
};

MedialCurves medial_curves(const BurningField& field, const MedialCurveOptions& options = {});
// The same on a refinement already built from `field` (AxisRefinement::build(field)).
MedialCurves medial_curves(const AxisRefinement& k, const BurningField& field, const MedialCurveOptions& options = {});

// The pieces, exposed for tests and figures.
// Step 1 on a refinement: per edge of K, whether it is a raw end.
std::vector<bool> raw_end_edges(const AxisRefinement& k, const MedialCurveOptions& options, double time_margin);
void close_raw_ends(const AxisRefinement& k, std::vector<bool>& raw, int hops, double min_length, double min_et = 0);
// Betti numbers of M (vertices, triangles, dangling segments) over GF(2).
BettiNumbers complex_betti(const MedialComplex& mc);

}  // namespace grassfire
