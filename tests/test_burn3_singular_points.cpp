// The link rule at singular points on the exact engine (Definition 9, Prop 6; docs/exact-engine.md), on
// the medial axes of seeded random cuts of the cube (medial3/convex/convex_polyhedron_axis.h,
// built exactly: points where four or more sheets meet, joined by singular curves). BT at
// every vertex the link rule decides is compared with two computations made another way:
//  - the link rule applied afresh (MedialComplex::link_burns) to the limits of BT along
//    sequences into the vertex, one per link element: a sector's limit from BT at
//    x = v + 2^-20 (c_t - v) in each of its triangles t (c_t the centroid), a pole's from
//    BT on its singular edge at 2^-20 of the edge from v; each within d = |x - v| of the
//    limit (Prop 4: BT is 1-Lipschitz in a sheet and along a curve). With L(T) = "the
//    elements whose limits are <= T leave no cycle in the link", v burns at the least such
//    T; from the enclosures' upper ends this gives an upper bound of that T, from the lower
//    ends a lower bound (link_burns is monotone in the arrivals), and BT(v) must meet both;
//  - the discrete baseline (burn_discrete, h = 0.1): its paths are real burning paths, so
//    it bounds BT from above at every vertex.
// Regression: the junction rule used to continue a piece of a singular curve across it
// only when the sweep had passed the upper end of the piece's times, so its windows were
// made after the sweep had passed their keys and arrived at singular points that had
// already burned: point 22 of the cut at seed 4 burned at 0.9407 while fire had reached
// it through every sector by 0.9095 (the baseline at h = 0.1: 0.9177; the proof report's
// Prop 5.1 and Prop 6 rows on convex polyhedra). Now it burns at 0.909525471047.
#include <catch2/catch.hpp>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/exact_burning.h"
#include "medial3/convex/convex_polyhedron_axis.h"
#include "geometry3/exact_predicates3.h"

using namespace grassfire;

namespace {

struct Burned {
  MedialComplex mc;
  ExactBurning eb;
  explicit Burned(const ConvexPolyhedron& p) : mc(convex_polyhedron_axis(p).complex), eb(mc) {
    mc.validate();
    eb.add_border_ignition();
    eb.run();
  }
};

const mpq_class kStep(1, 1 << 20);

double length_up(const ExactPoint3& a, const ExactPoint3& b) {
  return std::sqrt(squared_distance(a, b).get_d()) * (1 + 0x1p-40);
}

Interval widened(const Interval& x, double d) {
  return x.is_infinite() ? x : Interval(round_down(x.lo - d), round_up(x.hi + d));
}

// An enclosure of the limit of BT at v through link element j (see the header).
Interval element_limit(Burned& b, std::uint32_t v, const LinkElement& el) {
  const ExactPoint3& p = b.mc.vertex(v).exact;
  if (el.is_pole) {
    const ComplexEdge& e = b.mc.edge(el.id);
    const ExactPoint3& q = b.mc.vertex(e.v[0] == v ? e.v[1] : e.v[0]).exact;
    const ExactPoint3 x = p + kStep * (q - p);
    const Interval bt = e.stratum == EdgeStratum::Dangling
                            ? b.eb.segment_burn_time(el.id, e.v[0] == v ? kStep : 1 - kStep)
                            : b.eb.edge_burn_time(el.id, x);
    return widened(bt, length_up(x, p));
  }
  Interval limit(-INFINITY, INFINITY);
  for (std::uint32_t t : b.mc.sectors()[el.id].triangles) {
    const auto& tv = b.mc.triangle(t).v;
    const ExactPoint3 c = mpq_class(1, 3) * (b.mc.vertex(tv[0]).exact + b.mc.vertex(tv[1]).exact + b.mc.vertex(tv[2]).exact);
    const ExactPoint3 x = p + kStep * (c - p);
    const Interval bt = widened(b.eb.burn_time(t, x), length_up(x, p));
    if (bt.is_infinite()) return bt;
    limit = Interval(std::max(limit.lo, bt.lo), std::min(limit.hi, bt.hi));  // one limit per sector
  }
  CHECK(limit.lo <= limit.hi);
  return limit;
}

// The least T among `ends` at which the elements with end <= T let v burn (infinity: none).
double link_time(const MedialComplex& mc, std::uint32_t v, const std::vector<double>& ends) {
  double best = INFINITY;
  for (double T : ends) {
    std::vector<bool> arrived(ends.size());
    for (std::size_t i = 0; i < ends.size(); ++i) arrived[i] = ends[i] <= T;
    if (mc.link_burns(v, arrived)) best = std::min(best, T);
  }
  return best;
}

// Checks every link-rule vertex of the burned axis; returns how many were checked.
int check_link_rule(Burned& b) {
  int checked = 0;
  for (std::uint32_t v = 0; v < b.mc.vertex_count(); ++v) {
    if (!b.eb.propagation().is_link_rule_vertex(v) || b.mc.is_border_point(v)) continue;
    std::vector<double> lo, hi;
    for (const LinkElement& el : b.mc.link_elements(v)) {
      const Interval a = element_limit(b, v, el);
      lo.push_back(a.is_infinite() ? INFINITY : a.lo);
      hi.push_back(a.is_infinite() ? INFINITY : a.hi);
    }
    const Interval bt = b.eb.vertex_burn_time(v);
    const double upper = link_time(b.mc, v, hi), lower = link_time(b.mc, v, lo);
    CAPTURE(v, bt.lo, bt.hi, lower, upper);
    CHECK(bt.lo <= upper);
    CHECK(lower <= bt.hi);
    ++checked;
  }
  return checked;
}

}  // namespace

TEST_CASE("singular points of convex axes burn by the link rule applied to their sectors' limits",
          "[exact3][junction][link]") {
  int points = 0;
  for (std::uint32_t seed : {4u, 0u, 1u, 2u, 3u, 5u}) {
    Burned b(random_cut_cube(seed));
    CAPTURE(seed);
    CHECK(b.eb.certification().uncertified == 0);
    points += check_link_rule(b);
    // The discrete baseline bounds BT from above at every vertex.
    const DiscreteBurning d = burn_discrete(b.mc, {0.1});
    for (std::uint32_t v = 0; v < b.mc.vertex_count(); ++v) {
      CAPTURE(v);
      CHECK(d.vertex_bt[v] >= b.eb.vertex_burn_time(v).lo - 1e-9);
    }
  }
  CHECK(points >= 12);
}

// The point (14/19, -23/19, 21/19), where the sheets of four facets meet: the baseline
// converges to BT there from above (h = 0.1: 0.9177, h = 0.05: 0.9106; the engine before
// the fix: 0.9407).
TEST_CASE("the cut cube at seed 4: singular point 22 burns below the discrete baseline, which converges to it",
          "[exact3][junction][link]") {
  Burned b(random_cut_cube(4));
  std::uint32_t v = 0;
  const ExactPoint3 p{mpq_class(14, 19), mpq_class(-23, 19), mpq_class(21, 19)};
  while (v < b.mc.vertex_count() && !(b.mc.vertex(v).exact == p)) ++v;
  REQUIRE(v < b.mc.vertex_count());
  REQUIRE(b.mc.is_singular_point(v));
  const Interval bt = b.eb.vertex_burn_time(v);
  const double coarse = burn_discrete(b.mc, {0.1}).vertex_bt[v], fine = burn_discrete(b.mc, {0.05}).vertex_bt[v];
  CAPTURE(bt.lo, bt.hi, coarse, fine);
  CHECK(bt.hi - bt.lo < 1e-10);
  CHECK(bt.lo <= fine + 1e-9);
  CHECK(fine - bt.hi < 0.5 * (coarse - bt.hi));  // the gap shrinks with h
  CHECK(fine - bt.hi < 0.002);
}
