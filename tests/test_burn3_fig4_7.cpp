// Fig. 4.7 (4.2.3): a burning time that is an infimum, not a minimum. A board [-6, 6]^2
// ignited only along its side y = -6 (f = 0) carries a hollow "cylinder": a prism of height
// 12 over a 9-gon of radius 2 whose vertices are rational points of the circle
// (synthetic_complexes.h board_cylinder). The prism's foot is a singular curve (the board
// outside, the board inside, the prism). With 9 sides (odd), vertices 4 and 5 are the mirror
// images c +- i a of each other (rational_unit_direction rounds tan(theta/2) symmetrically):
// c = -7950/4217, a = 2816/4217, so the side between them is the vertical segment x = c,
// |y| <= a, the leftmost part of the prism.
// Closed form (derived by hand). Every path to x on the board starts on y = -6, so BT(x) >=
// y + 6 (on the board the distance to that line is at least y + 6; paths over the prism are
// longer, and the prism's rim, igniting at 0, is at least 12 away). The fire from y = -6 is
// the plane wave y + 6 wherever the vertical segment below x stays outside the 9-gon.
//  - P1 = (c, 3): its vertical path runs along the singular side, which does not burn until
//    its second arrival (the prism's fire, time 12; the board inside the 9-gon has no fire
//    before the curve burns), so no burning path realises y + 6 = 9; the paths x = c - eps
//    do, with length 9 + O(eps) -> BT(P1) = 9, an infimum that is not attained.
//  - P2 = (-1, 4), in the shadow of the prism: the shortest path climbs x = c to the corner
//    (c, a) (again along the side: an infimum) and runs straight to P2 (outside the 9-gon:
//    P2 lies left of the line through vertices 4 and 3): BT(P2) = 6 + a + |P2 - (c, a)| =
//    6 + 2816/4217 + sqrt(3733^2 + 14052^2)/4217 = 10.1152..., below the path around the
//    right (6 + |P2 - (2, 0)| = 11).
// The discrete baseline, whose paths must leave the singular side too, stays above the
// exact BT at every vertex, with the gap shrinking as the spacing h does.
#include <catch2/catch.hpp>

#include <cmath>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/exact_burning.h"
#include "complex3/point_location.h"
#include "complex3/synthetic_complexes.h"
#include "number/sqrt_field.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

BoardCylinderOptions fig_4_7_options() {
  BoardCylinderOptions o;
  o.sides = 9;
  o.radius = 2;
  o.half_width = 6;
  o.height = 12;
  o.near_side_only = true;
  return o;
}

// The exact BT at x (the exact value when every candidate window is exact, else none) and
// its certified enclosure.
std::pair<std::optional<ExactSum>, Interval> burn_at(ExactBurning& eb, const ComplexLocator& where, const ExactPoint3& x) {
  const ComplexPoint p = where.locate(x);
  REQUIRE(p.snap_squared == 0);
  REQUIRE(p.kind == ComplexPoint::Kind::Triangle);
  return {eb.exact_burn_time(p.id, x), eb.burn_time(p)};
}

}  // namespace

TEST_CASE("Fig. 4.7: the board and hollow cylinder burn at an infimum that is not attained", "[exact3][junction][fig4_7]") {
  const MedialComplex mc = built(board_cylinder(fig_4_7_options()));
  const mpq_class c(-7950, 4217), a(2816, 4217);
  // The 9-gon's vertices 4 and 5 are (c, a) and (c, -a).
  int corners = 0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const ExactPoint3& p = mc.vertex(v).exact;
    corners += sgn(p.z) == 0 && p.x == c && (p.y == a || p.y == -a);
  }
  REQUIRE(corners == 2);
  ExactBurning eb(mc);
  eb.add_border_ignition();
  eb.run();
  CHECK(eb.certification().uncertified == 0);
  const ComplexLocator where(mc);
  // P1 = (c, 3): BT = 9.
  const auto [e1, i1] = burn_at(eb, where, {c, 3, 0});
  CAPTURE(i1.lo, i1.hi);
  CHECK(i1.lo <= 9);
  CHECK(9 <= i1.hi);
  CHECK(i1.hi - i1.lo < 1e-12);
  REQUIRE(e1);
  CHECK(exact_sign(*e1 - ExactSum::rational(9)) == 0);
  // P2 = (-1, 4): BT = 6 + a + sqrt(3733^2 + 14052^2) / 4217.
  ExactSum bt2 = ExactSum::sqrt_of(mpq_class(3733L * 3733 + 14052L * 14052, 4217L * 4217));
  bt2 += ExactSum::rational(6 + a);
  bt2.simplify();
  const auto [e2, i2] = burn_at(eb, where, {-1, 4, 0});
  CAPTURE(i2.lo, i2.hi, bt2.to_double());
  CHECK(i2.lo <= bt2.approx().hi);
  CHECK(bt2.approx().lo <= i2.hi);
  CHECK(i2.hi - i2.lo < 1e-12);
  REQUIRE(e2);
  CHECK(exact_sign(*e2 - bt2) == 0);
  // The discrete baseline: an upper bound everywhere, converging from above at P2's nearest
  // kind of point (the vertices in the prism's shadow).
  const std::vector<Interval> exact = eb.vertex_burn_times();
  double previous_gap = INFINITY;
  for (double h : {0.5, 0.25, 0.125}) {
    DiscreteBurningOptions o;
    o.spacing = h;
    const DiscreteBurning d = burn_discrete(mc, o);
    double shadow_gap = 0;
    for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
      if (exact[v].is_infinite()) continue;
      CAPTURE(h, v, exact[v].lo, d.vertex_bt[v]);
      CHECK(d.vertex_bt[v] >= exact[v].lo - 1e-12);
      const Vec3d p = mc.vertex(v).approx;
      if (p[2] == 0 && p[0] > c.get_d() && p[0] < 2 && p[1] > 2) shadow_gap = std::max(shadow_gap, d.vertex_bt[v] - exact[v].hi);
    }
    CAPTURE(h, shadow_gap, previous_gap);
    CHECK(shadow_gap > 0);
    CHECK(shadow_gap < previous_gap);
    previous_gap = shadow_gap;
  }
}
