// synthetic_complexes.h -- hand-made medial complexes with known burning times (ch. 4).
//
// Computes: RawComplexes with exact rational vertices, and (where the answer is known in
// closed form) the burning time BT at any point of them:
//  - board and fin (4.1.2, 4.2.1, docs/design.md 5, reference case 1), zero radius, a = 1: the
//    board {z = 0, y >= 0} truncated to [-E, E] x [0, E], the fin {(s, s, z): 1 <= s <= E,
//    0 <= z <= E}, junction N from c = (1, 1, 0) to (E, E, 0). B (y = 0) and F (s = 1)
//    ignite at f = 0; the truncation borders never ignite (IgnitionRule::Never). Every
//    optimal path of the infinite complex stays inside the box, and the truncation changes
//    one thing only: the far end (E, E, 0) of N has a link without cycle (a star of three
//    sectors), so it burns at its first arrival, time E, and fire leaves it early along N.
//    Hence the closed form (board_fin_burning_time) is exact wherever it is <= E.
//  - board and hollow cylinder (Fig. 4.7): a square board with a "cylinder" standing on it;
//    the cylinder is approximated by a prism over a k-gon whose vertices are exact rational
//    points of the circle (not a regular k-gon: rational parametrisation of the circle).
//    Board border and cylinder rim ignite at f = 0 (options: only the side y = -L, and the
//    prism's height). No closed form (docs/design.md gives none).
//  - a book of k pages on one spine (z axis); page j is the rectangle [0, w_j] x [0, S] in
//    the half-plane of a rational unit direction near angle 2 pi j / k. Every border edge
//    ignites at f = 0 (zero radius). (Were top and bottom truncations that never ignite,
//    the spine's ends would be border points with a star link burning at their first
//    arrival, and fire would leak along the spine.) Closed form: a spine point at height z
//    burns at min(z, S - z, T), T the (k-1)-th smallest width (its (k-1)-th sector arrival
//    or its first arrival along the spine), and page j at (u, z) at
//    min(w_j - u, z, S - z, T + u).
//  - a Y of three half-planes: the book with three pages of widths 2, 3, 4 and height 10
//    (spine at 3 in the middle; fronts quench inside the widest page at u = 1/2).
//  - closed and pinched complexes for the strata and Prop-7 tests: tetrahedron surface,
//    octahedron surface (sphere-like), a pinched double cone, a tetrahedron with a flap.
// Contract: parameters as documented per function (checked; std::invalid_argument).
// Complexity: linear in the number of triangles produced.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "complex3/raw_complex.h"

namespace grassfire {

struct BoardFinOptions {
  int extent = 12;          // E: the board is [-E, E] x [0, E], N and the fin run to s = E
  int cells_per_unit = 1;   // grid refinement g: squares of side 1/g, each split in two
};
RawComplex board_fin(const BoardFinOptions& options = {});
// The kink k = (2 + sqrt 2, 2 + sqrt 2, 0) and BT there, 2 + sqrt 2.
std::array<double, 3> board_fin_kink();
// BT of the zero-radius board and fin at a point of it (docs/design.md 5, derived in the .cpp):
// fin (z > 0): sqrt2 (s - 1); N (x = y >= 1, z = 0): max(s, sqrt2 (s - 1));
// board front side (y > x) with x > 2 + sqrt2: 2 + sqrt2 + |p - k|; elsewhere on the board: y.
double board_fin_burning_time(const std::array<double, 3>& p);

struct BoardCylinderOptions {
  int sides = 24;        // k, the prism's number of sides
  int rings = 4;         // rings of the board between the prism and the square
  int rows = 6;          // rows of the prism's side
  double radius = 2.0;   // circle radius (rounded to 1/8)
  double half_width = 6; // the board is [-L, L]^2
  double height = 0;     // of the prism (rounded to 1/8); 0: 2 radius
  bool near_side_only = false;  // only the board side y = -L ignites (others never)
};
RawComplex board_cylinder(const BoardCylinderOptions& options = {});

struct BookOptions {
  int pages = 3;
  std::vector<long> widths;  // per page (integers); empty: all 2
  int height = 0;            // spine length S; 0: 2 max(w) + 2, so the middle sees T
  int cells_per_unit = 2;    // grid refinement of every page
};
RawComplex book(const BookOptions& options);
// BT at the point at distance u from the spine and height z on page `page` (u = 0: the
// spine itself, whose BT is not the limit from every page).
double book_burning_time(const BookOptions& options, int page, double u, double z);
int book_height(const BookOptions& options);
RawComplex y_junction(int cells_per_unit = 2);
BookOptions y_junction_options(int cells_per_unit = 2);

RawComplex tetrahedron_surface();
RawComplex octahedron_surface();
// Two cones of k sides sharing their apex (0,0,0), opening up and down; rims ignite.
RawComplex pinched_double_cone(int sides = 6);
// A closed tetrahedron surface with a square flap (two triangles) hanging off one edge:
// the flap burns, the tetrahedron is the maximal closed subcomplex.
RawComplex tetrahedron_with_flap();

// The exact medial axis of the box [-a, a] x [-b, b] x [-c, c], a >= b > c > 0, with R:
// the rectangle z = 0, |x| <= a - c, |y| <= b - c (R = c); eight trapezoids from its edges
// to the box edges parallel to x and y (R = c - |z|); four triangles from its corners to
// the vertical box edges (R = a - |x| = b - |y|). The rectangle's edges and the segments
// from its corners to the box corners are singular (three sheets); the box edges are the
// border, R = 0 there. Each piece is split into an n x n grid (R stays exact: it is affine
// on every piece). A real medial axis with exact R for the checks.
RawComplex box_medial_axis(long a, long b, long c, int subdivisions = 1);
// BT of box_medial_axis(a, b, c) at a point of it (the box edges ignite at f = R = 0):
//  - trapezoids and triangles: sqrt2 R. Each is the bisector of two box faces at a right
//    angle and burns from its box edge; a point at distance R from both faces is at
//    sqrt(R^2 + R^2) from that edge, and no path through the singular set is shorter: its
//    points burn at sqrt2 R too, and R changes by at most 1/sqrt2 per unit of length in
//    these 45-degree planes, so sqrt2 R(p) <= sqrt2 R(q) + |pq|.
//  - the rectangle (z = 0, |x| <= a - c, |y| <= b - c, R = c): its border is singular and
//    burns at c sqrt2 everywhere (both trapezoids arrive then), so BT = c sqrt2 + the
//    distance to the rectangle's border. The two formulas agree on that border.
double box_medial_axis_burning_time(double a, double b, double c, const std::array<double, 3>& p);

// A seeded random planar convex sheet (the brute-force reference of burn3_reference.h
// applies): a fan around the origin (R = 2) with k = 5 + seed % 6 rim points on a circle of
// radius rho in [6, 12], R at the rim in {0, 1, 2, 3} (so f is 1-Lipschitz along the rim,
// whose edges are longer than 3), and one rim edge that never ignites.
RawComplex random_planar_fan(std::uint32_t seed);

// A rational point of the unit circle near angle theta (rational parametrisation).
std::array<mpq_class, 2> rational_unit_direction(double theta);

// A synthetic complex by name: board-fin, board-cylinder, book:K, y-junction, tetrahedron,
// octahedron, double-cone, tetrahedron-flap, box:A:B:C (box_medial_axis), tube, annulus,
// torus (synthetic_tubes.h). Throws std::invalid_argument listing the names.
RawComplex synthetic_complex(const std::string& name);
std::vector<std::string> synthetic_complex_names();

}  // namespace grassfire
