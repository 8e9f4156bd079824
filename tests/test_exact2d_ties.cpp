// Exact ties that no value class proves (docs/exactness.md): hat-4 and watch-18 of the
// shapes2d dataset (tests/data/ties2d/README.md). The burning must leave no uncertified
// decision, the tied values must be proved equal (root_separation.h, arc primitives), and
// an independent Arb evaluation of the same values from the circle formulas (no exact
// forms) must agree to thousands of bits.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "burn2/edf_definition.h"
#include "burn2/extended_grassfire.h"
#include "medial2/polygon/polygon_axis.h"
#include "medial2/polygon/polygon_axis_geometry.h"
#include "medial2/polygon/polygon_axis_validate.h"
#include "io/load_shape.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

constexpr long kCheckBits = 4000;

std::string tie_shape(const std::string& name) { return std::string(GF_TEST_DATA) + "/ties2d/" + name; }

std::uint32_t node_near(const MedialGraph& g, double x, double y) {
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (std::hypot(g.node(v).position.x - x, g.node(v).position.y - y) < 1e-8) return v;
  FAIL("no node at (" << x << ", " << y << ")");
  return 0;
}

std::uint32_t edge_between(const MedialGraph& g, std::uint32_t a, std::uint32_t b) {
  std::uint32_t found = g.edge_count();
  g.for_each_incident(a, [&](std::uint32_t e) {
    if (g.other_end(e, a) == b) found = e;
  });
  REQUIRE(found < g.edge_count());
  return found;
}

// The edges of the path through the nodes at these input positions.
std::vector<std::uint32_t> path(const MedialGraph& g, const std::vector<Point2>& at) {
  std::vector<std::uint32_t> edges;
  for (std::size_t i = 0; i + 1 < at.size(); ++i)
    edges.push_back(edge_between(g, node_near(g, at[i].x, at[i].y), node_near(g, at[i + 1].x, at[i + 1].y)));
  return edges;
}

ExactSum exact_sum_of(const MedialGraph& g, const std::vector<std::uint32_t>& edges) {
  ExactSum s;
  for (std::uint32_t e : edges) s += g.geometry().exact_length(e);
  return s;
}

// The same lengths from the circle formulas in Arb (voronoi_circle.h's solve_ball and
// polygon_axis_geometry.h's edge_length): no exact form, no root-separation bound.
Ball ball_sum_of(const MedialGraph& g, const std::vector<std::uint32_t>& edges) {
  const auto& geo = dynamic_cast<const PolygonAxisGeometry&>(g.geometry());
  BallPrecision guard(kCheckBits);
  Ball s(0.0);
  for (std::uint32_t e : edges) {
    const AxisEdgeData& d = geo.edge_data(e);
    s += edge_length(geo.sites(), d, solve_ball(geo.sites(), geo.node_data(d.u).circle),
                     solve_ball(geo.sites(), geo.node_data(d.v).circle));
  }
  return s * ball_of(geo.to_input());
}

// a = b proved exactly, and the independent Arb difference is within 2^-(kCheckBits - 100).
void require_proved_equal(const MedialGraph& g, const std::vector<std::uint32_t>& a,
                          const std::vector<std::uint32_t>& b) {
  NumberStats st;
  CHECK(compare(exact_sum_of(g, a), exact_sum_of(g, b), &st) == 0);
  CHECK(st.uncertified_zero == 0);
  CHECK(st.exact_zero == 1);
  BallPrecision guard(kCheckBits);
  const Ball diff = ball_sum_of(g, a) - ball_sum_of(g, b);
  CHECK(diff.sign() == kUndecided);  // contains zero
  CHECK(arb_rel_accuracy_bits(ball_sum_of(g, a).get()) > kCheckBits - 100);
  CHECK(mag_cmp_2exp_si(arb_radref(diff.get()), -(kCheckBits - 100)) < 0);
}

// by_bound: comparisons of the burning decided by the root-separation bound.
void require_no_uncertified_and_oracle(const MedialGraph& g, const PolygonAxisReport& rep, std::uint64_t by_bound) {
  CHECK(rep.uncertified_contractions == 0);
  const GrassfireResult r = extended_grassfire(g);
  CHECK(r.stats().uncertified_zero == 0);
  CHECK(r.stats().separation_decided == by_bound);
  CHECK(validate_polygon_axis(g).ok());
  require_equal_to_definition(g, r, edf_by_definition(g));
}

}  // namespace

TEST_CASE("watch-18: two corner bisectors of equal length in different square classes", "[exact2d]") {
  PolygonAxisReport rep;
  const MedialGraph g = exact_polygon_axis(load_shape(tie_shape("watch-18.json")), {}, &rep);
  // From the apexes at (0.4326, 0.059561) and (0.38871, 0.059561) to their SSS circles.
  const std::vector<std::uint32_t> a = path(g, {{0.4326, 0.059561}, {0.442847908, 0.131296352}});
  const std::vector<std::uint32_t> b = path(g, {{0.38871, 0.059561}, {0.388712311, 0.132024648}});
  require_proved_equal(g, a, b);
  require_no_uncertified_and_oracle(g, rep, 1);
}

TEST_CASE("hat-4: two paths of arcs and segments, equal sums of unequal pieces", "[exact2d]") {
  PolygonAxisReport rep;
  const MedialGraph g = exact_polygon_axis(load_shape(tie_shape("hat-4.json")), {}, &rep);
  // A nested-radical PSS node, an arc split at a collinear vertex, straight pieces to an SSS
  // node; the second path is the first's mirror image, moved up, split at other vertices.
  const std::vector<std::uint32_t> a =
      path(g, {{0.218922128, 0.704828680}, {0.2118342, 0.71053}, {0.19737, 0.72368}, {0.18421, 0.73684},
               {0.17105, 0.75}, {0.166023855, 0.755026145}});
  const std::vector<std::uint32_t> b =
      path(g, {{0.754767872, 0.717988680}, {0.7618438, 0.72368}, {0.77632, 0.73684}, {0.78948, 0.75},
               {0.80263, 0.76315}, {0.807666145, 0.768186145}});
  CHECK(g.edge(a[0]).kind == EdgeKind::ParabolicArc);
  CHECK(g.edge(b[1]).kind == EdgeKind::ParabolicArc);
  require_proved_equal(g, a, b);
  // The pieces differ one by one (a tie of sums, not of edges).
  for (std::size_t i : {0, 1, 3, 4}) {
    NumberStats st;
    CHECK(compare(g.geometry().exact_length(a[i]), g.geometry().exact_length(b[i]), &st) != 0);
  }
  // The arcs telescope and their mirror images cancel as S[p;xi] constants; the straight
  // pieces are sums of square roots: no bound needed.
  require_no_uncertified_and_oracle(g, rep, 0);
}
