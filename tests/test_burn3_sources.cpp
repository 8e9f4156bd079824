// Exact point location, point sources in the discrete baseline, and its BT at any point.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/discrete/discrete_query.h"
#include "complex3/point_location.h"
#include "complex3/synthetic_complexes.h"
#include "number/exact_sum.h"
#include "test_complex3_support.h"
#include "test_sheets_support.h"

using namespace grassfire;
using testing::built;

namespace {

ExactPoint3 pt(const mpq_class& x, const mpq_class& y, const mpq_class& z) { return {x, y, z}; }
mpq_class q(long n, long d = 1) { return make_rational(n, d); }

double dist(const Vec3d& a, const Vec3d& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// The flat square [0, 4]^2 (cells of side 1/2) that only its point sources burn.
RawComplex square_sheet() { return without_border_ignition(testing::grid_sheet({{"####", "####", "####", "####"}, 2})); }

PointSource source_at(const ComplexLocator& locator, const ExactPoint3& p, const mpq_class& t0) {
  ComplexPoint x = locator.locate(p);
  REQUIRE(sgn(x.snap_squared) == 0);
  return {x, t0};
}

}  // namespace

TEST_CASE("point location: vertices, edges, triangles and nearest points, exactly", "[burn3][locate]") {
  const MedialComplex mc = built(tetrahedron_surface());  // (0,0,0), (1,0,0), (0,1,0), (0,0,1)
  const ComplexLocator locator(mc);
  ComplexPoint x = locator.locate(pt(1, 0, 0));
  CHECK(x.kind == ComplexPoint::Kind::Vertex);
  CHECK(mc.vertex(x.id).exact == pt(1, 0, 0));
  CHECK(sgn(x.snap_squared) == 0);
  x = locator.locate(pt(q(1, 2), q(1, 2), 0));
  CHECK(x.kind == ComplexPoint::Kind::Edge);
  CHECK(x.parameter == q(1, 2));
  x = locator.locate(pt(q(1, 3), q(1, 5), 0));
  REQUIRE(x.kind == ComplexPoint::Kind::Triangle);
  CHECK(x.barycentric[0] + x.barycentric[1] + x.barycentric[2] == 1);
  CHECK(x.point == pt(q(1, 3), q(1, 5), 0));
  // Off the complex: the nearest point, and the exact squared distance to it.
  x = locator.locate(pt(-1, q(1, 4), q(1, 4)));
  CHECK(x.kind == ComplexPoint::Kind::Triangle);
  CHECK(x.point == pt(0, q(1, 4), q(1, 4)));
  CHECK(x.snap_squared == 1);
  CHECK(x.snap() == 1.0);
  x = locator.locate(pt(2, 0, 0));
  CHECK((x.kind == ComplexPoint::Kind::Vertex && x.point == pt(1, 0, 0) && x.snap_squared == 1));
  x = locator.locate(pt(q(1, 2), q(1, 2), -1));
  CHECK((x.kind == ComplexPoint::Kind::Edge && x.parameter == q(1, 2) && x.snap_squared == 1));
  x = locator.locate(pt(q(1, 10), q(1, 10), q(1, 10)));  // inside: three faces tie at 1/10
  CHECK(x.snap_squared == q(1, 100));
}

TEST_CASE("point location: the nearest point is a true projection and no sample is nearer", "[burn3][locate]") {
  const MedialComplex mc = built(board_cylinder({8, 2, 3, 2.0, 6, 4, false}));
  const ComplexLocator locator(mc);
  std::mt19937 rng(11);
  std::uniform_int_distribution<long> coord(-50, 50);
  for (int i = 0; i < 60; ++i) {
    const ExactPoint3 p = pt(q(coord(rng), 10), q(coord(rng), 10), q(coord(rng), 10));
    const ComplexPoint x = locator.locate(p);
    CHECK(x.snap_squared == squared_distance(x.point, p));
    // First-order optimality: q - x is orthogonal to the cell holding x.
    const ExactPoint3 r = p - x.point;
    if (x.kind == ComplexPoint::Kind::Triangle) {
      const ComplexTriangle& t = mc.triangle(x.id);
      const ExactPoint3& a = mc.vertex(t.v[0]).exact;
      CHECK(sgn(dot(r, mc.vertex(t.v[1]).exact - a)) == 0);
      CHECK(sgn(dot(r, mc.vertex(t.v[2]).exact - a)) == 0);
      for (const mpq_class& w : x.barycentric) CHECK(sgn(w) > 0);
    } else if (x.kind == ComplexPoint::Kind::Edge) {
      const ComplexEdge& e = mc.edge(x.id);
      CHECK(sgn(dot(r, mc.vertex(e.v[1]).exact - mc.vertex(e.v[0]).exact)) == 0);
    }
    // Global optimality against samples of every triangle (independent of the filter).
    for (const ComplexTriangle& t : mc.triangles())
      for (int a = 0; a <= 4; ++a)
        for (int b = 0; a + b <= 4; ++b) {
          const ExactPoint3 s = q(4 - a - b, 4) * mc.vertex(t.v[0]).exact + q(a, 4) * mc.vertex(t.v[1]).exact +
                                q(b, 4) * mc.vertex(t.v[2]).exact;
          if (squared_distance(s, p) < x.snap_squared) FAIL("a sample of a triangle is nearer than the located point");
        }
  }
}

TEST_CASE("discrete point sources: an upper bound on t0 + distance, converging in h", "[burn3][sources]") {
  const MedialComplex mc = built(square_sheet());
  const ComplexLocator locator(mc);
  // Inside a triangle, inside an edge, at a vertex; different start times.
  const std::vector<PointSource> sources = {source_at(locator, pt(q(13, 10), q(21, 10), 0), q(1, 2)),
                                            source_at(locator, pt(3, q(7, 10), 0), 1),
                                            source_at(locator, pt(q(7, 2), q(7, 2), 0), 0)};
  CHECK(sources[0].location.kind == ComplexPoint::Kind::Triangle);
  CHECK(sources[1].location.kind == ComplexPoint::Kind::Edge);
  CHECK(sources[2].location.kind == ComplexPoint::Kind::Vertex);
  auto exact = [&](const Vec3d& p) {
    double best = 1e300;
    for (const PointSource& s : sources) best = std::min(best, s.t0.get_d() + dist(p, s.location.approx()));
    return best;
  };
  std::mt19937 rng(5);
  std::uniform_int_distribution<long> coord(0, 400);
  std::vector<ComplexPoint> queries;
  for (int i = 0; i < 200; ++i) queries.push_back(locator.locate(pt(q(coord(rng), 100), q(coord(rng), 100), 0)));
  double previous = 1e9;
  for (double h : {0.25, 0.125, 0.0625}) {
    DiscreteBurningOptions o;
    o.spacing = h;
    o.sources = sources;
    const DiscreteBurning d = burn_discrete(mc, o);
    double worst = 0;
    for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
      const double e = d.vertex_bt[v] - exact(mc.vertex(v).approx);
      CHECK(e >= -1e-12);  // a flat sheet: the geodesic distance is the straight one
      worst = std::max(worst, e);
    }
    for (const ComplexPoint& x : queries) {
      const double e = discrete_burning_time_at(mc, d, sources, x) - exact(x.approx());
      CHECK(e >= -1e-12);
      worst = std::max(worst, e);
    }
    for (const PointSource& s : sources)  // a source burns at its t0
      CHECK(discrete_burning_time_at(mc, d, sources, s.location) == s.t0.get_d());
    CAPTURE(h, worst);
    CHECK(worst <= 0.65 * h);  // measured 0.62 h, 0.45 h, 0.33 h: first order near the sources
    CHECK(worst < previous);
    previous = worst;
  }
}

TEST_CASE("discrete point sources: a closed surface burns from its sources only", "[burn3][sources]") {
  const MedialComplex mc = built(tetrahedron_surface());
  const ComplexLocator locator(mc);
  const DiscreteBurning none = burn_discrete(mc, {0.1});
  for (double bt : none.vertex_bt) CHECK(bt == DiscreteBurning::kInfinity);  // no border, no source
  CHECK(discrete_burning_time_at(mc, none, {}, locator.locate(pt(q(1, 3), q(1, 3), 0))) == DiscreteBurning::kInfinity);
  DiscreteBurningOptions o;
  o.spacing = 0.1;
  o.sources = {source_at(locator, pt(0, 0, 0), 2)};
  const DiscreteBurning d = burn_discrete(mc, o);
  CHECK(d.vertex_bt[testing::vertex_at(mc, pt(0, 0, 0))] == 2);
  CHECK(d.vertex_bt[testing::vertex_at(mc, pt(1, 0, 0))] == Approx(3).epsilon(1e-14));  // along the edge
  // A source exactly at a Steiner point (edge of length 1 at h = 1/4: points at 1/4, 1/2, 3/4).
  o.spacing = 0.25;
  o.sources = {source_at(locator, pt(q(1, 2), 0, 0), 0)};
  const DiscreteBurning s = burn_discrete(mc, o);
  CHECK(s.vertex_bt[testing::vertex_at(mc, pt(1, 0, 0))] == Approx(0.5).epsilon(1e-14));
  CHECK(s.vertex_bt[testing::vertex_at(mc, pt(0, 0, 0))] == Approx(0.5).epsilon(1e-14));
  // The apex (0,0,1) across the face y = 0 from (1/2, 0, 0): sqrt(1/4 + 1).
  CHECK(s.vertex_bt[testing::vertex_at(mc, pt(0, 0, 1))] >= std::sqrt(1.25) - 1e-12);
  CHECK(s.vertex_bt[testing::vertex_at(mc, pt(0, 0, 1))] <= std::sqrt(1.25) + 0.05);
}

TEST_CASE("discrete BT at any point: the link rule at a point of a singular edge", "[burn3][sources]") {
  // Y junction: pages of widths 2, 3, 4; the spine burns at the second arrival, T = 3.
  const BookOptions o = y_junction_options(2);
  const MedialComplex mc = built(book(o));
  const ComplexLocator locator(mc);
  const DiscreteBurning d = burn_discrete(mc, {0.125});
  const ComplexPoint spine = locator.locate(pt(0, 0, q(51, 10)));  // inside a spine edge
  REQUIRE(spine.kind == ComplexPoint::Kind::Edge);
  CHECK(mc.edge(spine.id).stratum == EdgeStratum::Singular);
  const double bt = discrete_burning_time_at(mc, d, {}, spine);
  CHECK(bt >= 3 - 1e-12);
  CHECK(bt <= 3 + 0.05);
}
