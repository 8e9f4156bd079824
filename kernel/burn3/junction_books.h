// junction_books.h -- three-page books whose burning time is known in closed form, built to
// break a junction rule that burns too early (Definition 9, 4.2.1; docs/design.md 5).
//
// The complex. One singular edge N = [0, 1] x {0} x {0} and three rectangular pages on it,
// each two triangles: A = {x in [0, 1], 0 <= s <= 1} along the direction a = (0, 1, 0) (the
// plane z = 0, y >= 0); B of height H along a rational unit direction b; C of width W along a
// rational unit direction c (default b = (0, 0, 1), c = (0, -1, 0)). The far edge of B
// (s = H) and of C (s = W) ignite at f = 0 (Linear, zero radius); every other border edge
// never ignites. Point sources (x_i, s_i) with start t_i lie in A (s_i > 0) or on N (s_i = 0).
// Zero radius everywhere.
//
// The closed form (derived from Definition 9; every page is a convex planar rectangle, so
// distances inside a page are Euclidean and every straight path stays in it):
//  - Arrivals at the point x of N. Page B's plane wave arrives at H, page C's at W (H <= W;
//    the x = 0 and x = 1 ends never ignite). A source on N, o(x) = min over sources on N of
//    t_i + |x - x_i|, reaches x through every page. A source in A reaches x through A at
//    a(x) = min over sources in A of t_i + sqrt((x - x_i)^2 + s_i^2) (the segment lies in A).
//  - The junction rule: x burns at the 2nd of its three side arrivals, min(a, o), min(H, o),
//    min(W, o), which is min(o(x), min(max(a(x), H), W)) (min with o commutes with order
//    statistics). That function is 1-Lipschitz in x (order statistics and minima of
//    1-Lipschitz functions), so no fire running along N, and no fire leaving N into a page
//    and coming back to N, is earlier: BT_N(x) = min(o(x), W, min_i max(a_i(x), H)), a
//    minimum of finitely many convex functions phi_j of x (a_i the cone of source i in A).
//  - A page point p at distance s from N in page P (A, B or C) burns at
//      BT(p) = min(direct_P(p), min over j of min over x' in [0, 1] of phi_j(x') + |p - (x', 0, 0)|),
//    direct_A = min over sources in A of t_i + |p - source|, direct_B = H - s, direct_C = W - s
//    (fire enters a page from N at BT_N, Definition 9 admits any non-crossing path from a
//    burned point; the inner minimum is of a convex function, evaluated by golden-section
//    search to about 1e-14, far below the 1e-9 the tests ask).
//  - Worked instance (the six-triangle book of the docs): H = 1/2, W = 3/5, one source at
//    (0.3, 0.001) in A starting at 0.4985. At x = 0.3 the sides arrive at 0.4995, 0.5, 0.6,
//    so BT_N(0.3) = 0.5; the dip where a(x) < H is |x - 0.3| < sqrt(0.0015^2 - 0.001^2);
//    in C at (0.3, -0.01, 0) BT = 0.5 + 0.01 = 0.51 (every phi_j >= 0.5, and the foot
//    x' = 0.3 attains it). A rule taking the first arrival gives 0.4995 and 0.5095.
// Bent spine (bend > 0): N runs from (0, 0, 0) to (1/2, 0, 0) to (1, -bend, 0), two singular
// edges meeting at the angle pi - 2 atan(2 bend); A and C stay in z = 0 (above and below N,
// each in two pieces), B stands vertically on both pieces. B unfolds to a flat rectangle
// (distances there are those of the unfolding), C is convex, and A has one reflex corner at
// (1/2, 0, 0), so a shortest path in A is straight when the segment stays above N and goes
// via the corner otherwise. Page C arrives at N(x) at W + y(x) (straight down to y = -W);
// the formulas above hold with these distances, W replaced by W + y(x), and |x - x'| along
// N by arclength (each phi_j is then convex on each of the two pieces; for points of A the
// inner minimum is found by a scan of 4001 points refined by golden section).
// The families (junction_books): the docs' book; a front dipping under B's for a stretch
// 3d/2 long (source depth d from 1e-6 to 1e-2, start H - 5d/4, so a(x) = H at x_i +- 3d/4);
// several sources; two crossings 6e-7 apart; a tangent front (start H - d: a(x) >= H with
// equality at x_i only); pages at near-degenerate dihedral angles (about 2e-3 rad); a
// spine bent by 2e-3 rad with a dip at the corner;
// source on N and one 1e-6 next to it. Check points sit in the dips, just outside them, on
// the crossings, and in the pages near and away from N.
// Contract: as built here (0 <= x <= 1 for check points, H <= W). Complexity: a check
// point's closed form costs O(sources * 200) distance evaluations.
#pragma once

#include <gmpxx.h>

#include <string>
#include <vector>

#include "complex3/raw_complex.h"

namespace grassfire {

struct JunctionBookSource {
  mpq_class x, s, t0;  // in A at (x, s) (s > 0), or on N at x (s = 0)
};

// A point of page 'A', 'B', 'C' at (x, s), or of N ('N', s = 0).
struct JunctionBookPoint {
  char page = 'N';
  mpq_class x, s;
};

struct JunctionBook {
  std::string name;
  mpq_class height_b = mpq_class(1, 2), width_c = mpq_class(3, 5);
  ExactPoint3 b{0, 0, 1}, c{0, -1, 0};  // rational unit directions of B and C
  mpq_class bend = 0;  // > 0: N bent at (1/2, 0, 0) towards (1, -bend, 0) (then b, c as default)
  std::vector<JunctionBookSource> sources;
  std::vector<JunctionBookPoint> checks;
};

// The complex (six triangles, border rules as above).
RawComplex junction_book_complex(const JunctionBook& book);
// The point of R^3 of a check point (exact).
ExactPoint3 junction_book_point(const JunctionBook& book, const JunctionBookPoint& p);
// The burning time at p from the closed form above.
double junction_book_burning_time(const JunctionBook& book, const JunctionBookPoint& p);
// BT_N(x) of the closed form, and the arrival of page A's sources at x (for reports).
double junction_book_spine_time(const JunctionBook& book, double x);
// Every family listed above, with its check points.
std::vector<JunctionBook> junction_books();

}  // namespace grassfire
