// border_edge_minimum.h -- min over a piece of a border edge of distance + ignition.
//
// Computes: a certified enclosure (Arb ball) of
//     m = min over s in [s_a, s_b] of |x - y(s)| + f(y(s)),   y(s) = a + s (b - a),
// for a rational point x in R^3 and a border edge ab with its ignition rule (raw_complex.h,
// 4.2.3): Linear, f(y(s)) = (1 - s) R_a + s R_b with R = sqrt(R^2); DistanceToPoint,
// f(y) = |y - p|. This is the inner step of BT(x) = min over border points y of
// d(x, y) + f(y) on a planar sheet, once y is known to be visible from x.
// Closed forms (both functions are convex in s, so the minimum over [s_a, s_b] is at the
// unconstrained minimiser s* clamped to the interval). With s0 the foot of x on the line,
// H^2 = dist(x, line)^2 and L = |b - a|:
//  - Linear, dR = R_b - R_a: if |dR| < L, s* = s0 - dR sqrt(H^2) / (L sqrt(L^2 - dR^2));
//    otherwise f grows at least as fast as the distance falls and the minimum is at an end.
//    |dR| < L is decided exactly (ExactSum: signs of sums of square roots of rationals).
//  - DistanceToPoint: unfolding p about the line into the plane of x (rotation keeps
//    distances to the line's points), the minimiser is where the segment from x to the
//    unfolded p crosses the line: s* = (s0 h_p + s_p h) / (h + h_p) (h, h_p the distances
//    of x and p to the line); when both are 0, s* = s0.
// Certification: s* is a ball; when it does not separate from s_a or s_b, the result is
// the union of the enclosures of f at the ball and at that end, which holds the true
// minimum either way. Every operation is Arb's, so the ball is rigorous.
// Contract: a != b; 0 <= s_a <= s_b <= 1; R^2 >= 0. Never-rule edges return nothing.
// Complexity: O(1) ball operations at the current BallPrecision.
#pragma once

#include <gmpxx.h>

#include <optional>

#include "complex3/raw_complex.h"
#include "number/ball.h"

namespace grassfire {

struct IgnitedEdge {
  ExactPoint3 a, b;
  IgnitionRule rule = IgnitionRule::Linear;
  mpq_class ra2, rb2;  // R^2 at a and b (Linear)
  ExactPoint3 point;   // p (DistanceToPoint)
};

std::optional<Ball> min_distance_plus_ignition(const IgnitedEdge& e, const ExactPoint3& x, const mpq_class& s_a,
                                               const mpq_class& s_b);

}  // namespace grassfire
