// The circle enclosures of voronoi_circle.h against the exact forms, on a wavy polygon with
// many reflex vertices (the PPS circles whose point lies on the segment's line, solved by
// their linear formula, and the PSS circles of nearly parallel lines), and the exact
// integer shortcut of orientation (geometry2/predicates2.h) against rationals.
#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <random>

#include "geometry2/predicates2.h"
#include "medial2/polygon/segment_voronoi.h"
#include "medial2/polygon/voronoi_circle.h"
#include "number/mpfr_bounds.h"
#include "shapes/validate_shape.h"

using namespace grassfire;

namespace {

// Integer wavy circle: r(t) = R (1 + 0.1 sin(7 t + 0.3)), rounded (bench_polygon_axis's curve).
Shape2 wavy(int n, double radius) {
  Shape2 s;
  s.name = "wavy";
  Ring r;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n, rad = radius * (1 + 0.1 * std::sin(7 * t + 0.3));
    r.points.push_back({std::round(rad * std::cos(t)), std::round(rad * std::sin(t))});
  }
  s.rings.push_back(r);
  validate_shape(s, s.name);
  return s;
}

// The exact value lies in the interval [lo, hi].
bool contains(const Interval& a, const ExactSum& x) {
  MpfrBounds b(256);
  x.enclose(b.lo, b.hi);
  return mpfr_cmp_d(b.lo, a.lo) >= 0 && mpfr_cmp_d(b.hi, a.hi) <= 0;
}

bool tight(const Interval& a, double scale) { return a.hi - a.lo <= std::ldexp(scale, -40); }

}  // namespace

TEST_CASE("polygon circle enclosures contain the exact circle, and tangent PPS circles are tight in doubles", "[exact2d]") {
  const PolygonSites sites = make_sites(wavy(2000, 1e6), 1.0);
  const VoronoiTopology topo = boost_segment_voronoi(sites);
  int tangent_pps = 0, checked = 0, tight_tangent = 0;
  for (const auto& v : topo.vertices) {
    const VoronoiCircle c = classify_circle(sites, v);
    if (c.kind == CircleKind::Apex) continue;
    const auto exact = solve_exact(sites, c);
    if (!exact) continue;  // a nested radical
    ++checked;
    const CircleValue<Interval> iv = solve_interval(sites, c);
    const CircleValue<DDBall> dd = solve_dd(sites, c);
    REQUIRE(contains(iv.x, exact->x));
    REQUIRE(contains(iv.y, exact->y));
    REQUIRE(contains(iv.r, exact->r));
    REQUIRE(contains(dd.x.to_interval(), exact->x));
    REQUIRE(contains(dd.y.to_interval(), exact->y));
    REQUIRE(contains(dd.r.to_interval(), exact->r));
    if (c.kind == CircleKind::PPS && c.tangent) {
      ++tangent_pps;
      // P (tangent 1) or Q (tangent 2) lies on L's line, exactly.
      const std::uint32_t on = c.sites[c.tangent - 1], l = c.sites[2];
      REQUIRE(orientation(sites.vertex[sites.seg_start(l)], sites.vertex[sites.seg_end(l)], sites.vertex[on]) == 0);
      const double scale = std::fmax(std::fabs(iv.r.hi), std::fmax(std::fabs(iv.x.hi), std::fabs(iv.y.hi)));
      tight_tangent += tight(iv.r, std::fabs(iv.r.hi)) && tight(iv.x, scale) && tight(iv.y, scale);
    }
  }
  CHECK(checked > 2500);  // 2753 when written
  // About one PPS circle per reflex vertex has its point on its own segment's line.
  CHECK(tangent_pps > 500);
  CHECK(tight_tangent == tangent_pps);
}

TEST_CASE("orientation of integer points: the double shortcut equals rationals, collinear included", "[exact2d]") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-(1 << 24), 1 << 24), small(-3, 3);
  int zeros = 0;
  for (int k = 0; k < 20000; ++k) {
    const Point2 a{double(coord(rng)), double(coord(rng))};
    // b and c on or near the line through a in a random integer direction.
    const double dx = small(rng), dy = small(rng);
    const double s = small(rng), t = small(rng);
    const Point2 b{a.x + s * dx, a.y + s * dy};
    const Point2 c{a.x + t * dx + (k % 3 == 0 ? small(rng) : 0), a.y + t * dy};
    const mpq_class det = (mpq_class(a.x) - c.x) * (mpq_class(b.y) - c.y) - (mpq_class(a.y) - c.y) * (mpq_class(b.x) - c.x);
    REQUIRE(orientation(a, b, c) == sgn(det));
    zeros += sgn(det) == 0;
  }
  CHECK(zeros > 10000);
}
