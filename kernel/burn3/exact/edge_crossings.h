// edge_crossings.h -- where two arrivals at a singular edge cross: every crossing of two
// windows' times along the edge isolated in a certified bracket, so that between the
// brackets their order is proved and never changes (the junction rule's breakpoints,
// 4.2.1, Fig. 4.4; docs/design.md 3, 5a).
//
// Computes, for windows wa, wb of triangles on the edge E = v[0] + l (v[1] - v[0]) and a
// parameter range [lo, hi], the brackets [l1, l2] each holding exactly one sign change of
// f(l) = time_a(l) - time_b(l), by certified subdivision (real root isolation with interval
// Newton's exclusion and monotonicity tests) on the fronts' closed forms along E
// (edge_fronts.h: coefficients from Arb once per window and edge). Boxes have double ends
// (exact rationals, so no rational arithmetic in the loop):
//  - monotone: f' over the box [a, b] excludes 0: at most one root, present iff the
//    certified signs of f at a and b differ;
//  - exclusion: f over the box, or the centred form f(m) + f'([a, b]) ([a, b] - m),
//    excludes 0: no root;
//  - each test first on the coefficients' double enclosures, then in Arb at 128 bits (and
//    max_bits) on boxes whose double width is spent (the value at m as wide as the centred
//    form: a finer box would not help), else the box is halved; a zero of f proved at m
//    (exact arithmetic or identical expressions) is a crossing at exactly m.
// Signs of f at points: the double enclosure, Arb at 128 bits, else Certifier::compare_times
// (deciding: escalating to max_bits). A bracket found is narrowed by bisection while the
// double enclosures decide (to about 2^-44 of the edge), so its midpoint orders it among
// the other breakpoints. Where the subdivision leaves a box undecided, the exact path is
// tried: every root of f is among the roots of the squared polynomial (junction_kinks.h
// crossing_candidates), placed by exact signs.
// A source relayed on E (a first window r of an edge point Q of E whose offset is w's time
// at Q, or the time at Q of the window equal to w there by Q's defining crossing):
// r = w(Q) + |x - Q| >= w(x) along E (w is 1-Lipschitz in arc length), one sign (`equal`).
// Identical fronts (their exact data equal, junction_kinks.h identical_along_edge): f = 0
// on the whole line, no crossing (`equal`); asked only where the coefficients bound |f| by
// 2^-64 on the range (the exact data costs far more than the whole isolation).
// Ties along a stretch: f is sigma_a + sqrt(P_a) - sigma_b - sqrt(P_b) with P quadratic in l
// (or has a plane wave, linear in l), so squaring twice leaves a polynomial of degree <= 4:
// f proved 0 at five distinct points makes it vanish identically, and then f is 0 on the
// whole line (the fronts are one expression along E) and has no crossing.
// Two fronts whose difference is bounded by 2^-64 on the whole range (from the coefficients'
// differences, edge_fronts.h front_difference_bound, or Arb's centred form; or on a box no
// test settles) are a tie there: either order moves the (k-1)-th arrival by at most that (order
// statistics are 1-Lipschitz in the sup norm), so no crossing is claimed and the box is
// counted `negligible`, not undecided (tripod-s2: 30 pairs on singular edges ~1e-17 long).
// What no stage settles (a box at the depth or node budget, an end sign undecided at
// max_bits) is counted in `undecided`, and a sign change across it, if certified, is kept
// as a crossing bracket; the caller counts `undecided` as uncertified decisions.
// Contract: the windows' triangles contain E; 0 <= lo < hi <= 1 (ends that are not doubles
// are widened outwards to the nearest doubles).
// Complexity: O(1) box evaluations for separated fronts, O(log(1 / width)) per crossing;
// at most kNodeBudget boxes per pair. `fronts` keeps the coefficients between calls.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <vector>

#include "burn3/exact/window_certify.h"

namespace grassfire {

struct CrossingBracket {
  mpq_class lo, hi;  // lo == hi: a proved zero at that rational
  double at = 0.0;   // a double inside the bracket (orders the breakpoints)
};

struct EdgeCrossings {
  std::vector<CrossingBracket> roots;
  std::uint32_t undecided = 0;  // boxes or signs no stage settled
  bool equal = false;           // f proved 0 on the whole line, or of one sign (a front thrown by the other)
  std::uint32_t negligible = 0; // ties within 2^-64 at a range end, on a box or on the whole range
  std::uint32_t boxes = 0;      // boxes examined (cost)
};

class EdgeFronts;
EdgeCrossings isolate_crossings(const Unfolding& u, const WindowStore& s, Certifier& cert, EdgeFronts& fronts,
                                std::uint32_t edge, std::uint32_t wa, std::uint32_t wb, const mpq_class& lo,
                                const mpq_class& hi);

}  // namespace grassfire
