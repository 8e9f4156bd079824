// lpdf.h -- the largest-plate distance function (LPDF, 4.1.1, Definitions 5-7), where it
// can be computed: by enumerating the resolutions of the singular curves.
//
// Definition 7: LPDF(x) = sup over disks f containing x of r_f(x), r_f(x) = min over z on
// the boundary of f of d_f(x, z) + R(z); a disk is a local embedding of a disk into M
// (Definition 5), so it may cross a singular curve from any sheet into any other one.
//
// Discrete algorithm (ours). A RESOLUTION rho picks, for every singular curve of M (a
// maximal chain of singular edges through points of M1, whose k sheets are followed along
// the chain through the sectors of its vertices), a maximal matching of its k sheets:
// matched sheets are glued across the curve, an unmatched sheet is cut there. Gluing every
// manifold edge as well, rho turns M into a surface S_rho (each vertex splits into the
// components of its resolved link; a component that is a path is a boundary point), whose
// boundary is M's igniting border (value f) and the cut sides (value R). A geodesic ball
// of S_rho that avoids its boundary develops into a locally embedded disk, so
//   LPDF_res(x) = max over rho of min over z on the boundary of S_rho of d_{S_rho}(x, z) + R(z)
// is a lower bound of Definition 7, and one multi-source Dijkstra from the boundary of S_rho
// (over the baseline's graph: vertices and Steiner points at spacing h, straight moves
// across triangles, discrete_burning.h) gives the inner minimum at every graph point at
// once. Why only maximal matchings: gluing two more sheets removes boundary and adds paths
// that must cross the curve through points that were boundary before, so no distance to
// the boundary gets shorter. Why per curve and not per point: a disk that switches pairs
// along a curve has a boundary point where it switches; we do not search those disks, nor
// disks that cross the same curve twice with different pairs (local embedding allows it).
// Equality with Definition 7 holds on the board and fin (the closed form below, derived in
// the .cpp, is checked by the tests), on books (the plate of page j pairs it with the
// widest other page: LPDF = min(w_j - u, max_{i != j} w_i + u, z, S - z), which equals BT)
// and on complexes without singular curves (one resolution: the distance to the border).
// Truncation borders that never ignite (IgnitionRule::Never) are not boundary: they stand
// for sheets that go on.
//
// Cost: prod over curves c of m(k_c) Dijkstra runs, m(3) = m(4) = 3, m(5) = m(6) = 15,
// m(k) = k!! or (k - 1)!!: 3 runs on the board and fin, 3^8 on a box axis, and beyond any
// budget on a medial axis of a mesh or a union of balls with tens of singular curves: that is
// where it stops being tractable (options.max_resolutions refuses, std::invalid_argument).
// The error against the true LPDF_res is that of graph distances: an over-estimate, O(h).
// Contract: a validated MedialComplex; spacing h > 0.
// Complexity: O(resolutions x (N log N + moves)) for N graph points.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "complex3/medial_complex.h"

namespace grassfire {

struct LpdfOptions {
  double spacing = 0.25;
  std::uint64_t max_resolutions = 20000;
  std::uint64_t max_points = 20'000'000;
};

struct LpdfResult {
  double spacing = 0;
  std::vector<double> vertex_lpdf;   // per vertex: max over resolutions and vertex copies
  std::vector<double> steiner_lpdf;  // per Steiner point, edge by edge (the baseline's layout)
  std::vector<std::uint64_t> edge_first_steiner;
  // The value seen from triangle t at its corner c (max over resolutions of the copy that
  // holds t): the LPDF jumps across singular curves like BT, and drawings need the sides.
  std::vector<double> corner_lpdf;   // at 3 t + c
  std::uint64_t singular_curves = 0, resolutions = 0;
  double seconds = 0;
};

LpdfResult largest_plate_distance(const MedialComplex& mc, const LpdfOptions& options);

// The closed form on the zero-radius board and fin (4.1.2, Fig. 4.3; derivation in the
// .cpp): the fin (z > 0): sqrt2 (s - 1), its distance to F; the junction N (x = y >= 1,
// z = 0): max(s, sqrt2 (s - 1)); the front side of the board (y > x) beyond c's line
// (x > 1): max(y, |p - c|) with c = (1, 1, 0); the rest of the board: y.
double board_fin_lpdf(const std::array<double, 3>& p);
// The zone of Fig. 4.3: 1 the fin, 2 where |p - c| wins (front side, x > 1, |p - c| > y),
// 3 the rest of the board (distance to B); points of N count as zone 1.
int board_fin_lpdf_zone(const std::array<double, 3>& p);

}  // namespace grassfire
