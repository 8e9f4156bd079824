// border_edge_minimum.cpp -- see border_edge_minimum.h.
#include "burn3/border_edge_minimum.h"

#include <functional>

#include "geometry3/exact_predicates3.h"
#include "number/exact_sum.h"

namespace grassfire {
namespace {

// The line through a and b, seen from a point: foot parameter and squared distance.
struct LineView {
  mpq_class foot, height2;
};

LineView view(const ExactPoint3& a, const ExactPoint3& ab, const mpq_class& length2, const ExactPoint3& x) {
  const mpq_class s0 = dot(x - a, ab) / length2;
  return {s0, squared_distance(x, a + s0 * ab)};
}

// |x - y(s)| = sqrt(L^2 (s - s0)^2 + H^2) at a ball s.
Ball distance_at(const Ball& s, const mpq_class& length2, const LineView& v) {
  const Ball u = s - ball_of(v.foot);
  return sqrt(ball_of(length2) * u * u + ball_of(v.height2));
}

// min over [s_a, s_b] of a convex phi whose unconstrained minimiser is (enclosed by) s_star.
Ball clamped_minimum(const std::function<Ball(const Ball&)>& phi, const Ball& s_star, const mpq_class& s_a,
                     const mpq_class& s_b) {
  const Ball lo = ball_of(s_a), hi = ball_of(s_b);
  const int below = (s_star - lo).sign(), above = (s_star - hi).sign();
  if (below == -1) return phi(lo);
  if (above == 1) return phi(hi);
  if (below == 1 && above == -1) return phi(s_star);
  // Not separated from an end (or equal to it): the true value is phi at that end or at
  // s*, and the union holds both.
  Ball r = phi(s_star);
  if (below != 1) r = hull(r, phi(lo));
  if (above != -1) r = hull(r, phi(hi));
  return r;
}

}  // namespace

std::optional<Ball> min_distance_plus_ignition(const IgnitedEdge& e, const ExactPoint3& x, const mpq_class& s_a,
                                               const mpq_class& s_b) {
  if (e.rule == IgnitionRule::Never) return std::nullopt;
  const ExactPoint3 ab = e.b - e.a;
  const mpq_class length2 = dot(ab, ab);
  const LineView vx = view(e.a, ab, length2, x);
  if (e.rule == IgnitionRule::DistanceToPoint) {
    const LineView vp = view(e.a, ab, length2, e.point);
    auto phi = [&](const Ball& s) { return distance_at(s, length2, vx) + distance_at(s, length2, vp); };
    if (sgn(vx.height2) == 0 && sgn(vp.height2) == 0) return clamped_minimum(phi, ball_of(vx.foot), s_a, s_b);
    const Ball h = sqrt(ball_of(vx.height2)), hp = sqrt(ball_of(vp.height2));
    return clamped_minimum(phi, (ball_of(vx.foot) * hp + ball_of(vp.foot) * h) / (h + hp), s_a, s_b);
  }
  const Ball ra = sqrt(ball_of(e.ra2)), rb = sqrt(ball_of(e.rb2)), dr = rb - ra;
  auto phi = [&](const Ball& s) { return distance_at(s, length2, vx) + ra + s * dr; };
  // |dR| < L, exactly: both sqrt(rb2) - sqrt(ra2) - L and sqrt(ra2) - sqrt(rb2) - L negative.
  const ExactSum up = ExactSum::sqrt_of(e.rb2) - ExactSum::sqrt_of(e.ra2) - ExactSum::sqrt_of(length2);
  const ExactSum down = ExactSum::sqrt_of(e.ra2) - ExactSum::sqrt_of(e.rb2) - ExactSum::sqrt_of(length2);
  if (sign(up) >= 0 || sign(down) >= 0) return min(phi(ball_of(s_a)), phi(ball_of(s_b)));  // monotone
  const Ball l2 = ball_of(length2);
  const Ball s_star = ball_of(vx.foot) - dr * sqrt(ball_of(vx.height2)) / (sqrt(l2) * sqrt(l2 - dr * dr));
  return clamped_minimum(phi, s_star, s_a, s_b);
}

}  // namespace grassfire
