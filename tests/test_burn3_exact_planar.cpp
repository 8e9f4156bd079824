// Exact burning engine on planar sheets: point sources and border ignition against exact
// closed forms and the brute-force reference (docs/exact-engine.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "burn3/burn3_reference.h"
#include "burn3/exact/burn_outputs.h"
#include "burn3/exact/exact_burning.h"
#include "complex3/synthetic_complexes.h"
#include "number/sqrt_field.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

ExactSum exact_distance(const ExactPoint3& a, const ExactPoint3& b) {
  ExactSum d = ExactSum::sqrt_of(squared_distance(a, b));
  d.simplify();
  return d;
}

// Whether the segment a -> b meets the open box (x0, x1) x (y0, y1) (exact, Liang-Barsky).
bool segment_meets_open_box(const ExactPoint3& a, const ExactPoint3& b, const mpq_class& x0, const mpq_class& x1,
                            const mpq_class& y0, const mpq_class& y1) {
  mpq_class lo = 0, hi = 1;
  const mpq_class d[2] = {b.x - a.x, b.y - a.y};
  const mpq_class p[2] = {a.x, a.y};
  const mpq_class mins[2] = {x0, y0}, maxs[2] = {x1, y1};
  for (int k = 0; k < 2; ++k) {
    if (sgn(d[k]) == 0) {
      if (p[k] <= mins[k] || p[k] >= maxs[k]) return false;
      continue;
    }
    mpq_class t0 = (mins[k] - p[k]) / d[k], t1 = (maxs[k] - p[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0), hi = std::min(hi, t1);
  }
  return lo < hi;
}

}  // namespace

TEST_CASE("point source on a planar grid: BT = |x - s| exactly", "[exact3]") {
  const MedialComplex mc = built(grid_sheet(4, 3, 2));
  ExactBurning eb(mc);
  const ExactPoint3 s{mpq_class(3, 2), mpq_class(5, 4), 0};
  std::uint32_t ts = kNoIndex;
  for (std::uint32_t t = 0; t < mc.triangle_count() && ts == kNoIndex; ++t) {
    const auto& v = mc.triangle(t).v;
    const ExactPoint3 &a = mc.vertex(v[0]).exact, &b = mc.vertex(v[1]).exact, &c = mc.vertex(v[2]).exact;
    const int s0 = sgn(dot(cross(b - a, s - a), cross(b - a, c - a)));
    const int s1 = sgn(dot(cross(c - b, s - b), cross(c - b, a - b)));
    const int s2 = sgn(dot(cross(a - c, s - c), cross(a - c, b - c)));
    if (s0 >= 0 && s1 >= 0 && s2 >= 0) ts = t;
  }
  REQUIRE(ts != kNoIndex);
  eb.add_point_source(ts, s, 0);
  eb.run();
  CHECK(eb.certification().uncertified == 0);
  std::mt19937 rng(3);
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
    for (const ExactPoint3& x : sample_triangle(mc, t, 4, rng)) {
      const auto e = eb.exact_burn_time(t, x);
      REQUIRE(e);
      CHECK(exact_sign(*e - exact_distance(x, s)) == 0);
      const Interval i = eb.burn_time(t, x);
      CHECK(encloses(i, distance3(to_vec(x), to_vec(s))));
      CHECK(i.hi - i.lo < 1e-12);
    }
}

TEST_CASE("L-shaped sheet: fire bends around the reflex corner exactly", "[exact3]") {
  // [0, 4]^2 without the quadrant [2, 4]^2; the source sees part of the far arm only.
  const std::vector<std::pair<int, int>> holes{{2, 2}, {2, 3}, {3, 2}, {3, 3}};
  const MedialComplex mc = built(grid_sheet(4, 4, 1, holes));
  const ExactPoint3 s{mpq_class(7, 2), mpq_class(1, 2), 0}, corner{2, 2, 0};
  std::uint32_t ts = kNoIndex;
  for (std::uint32_t t = 0; t < mc.triangle_count() && ts == kNoIndex; ++t) {
    const auto& v = mc.triangle(t).v;
    bool in = true;
    for (int k = 0; k < 3; ++k) {
      const ExactPoint3 &a = mc.vertex(v[k]).exact, &b = mc.vertex(v[(k + 1) % 3]).exact, &c = mc.vertex(v[(k + 2) % 3]).exact;
      in = in && sgn(dot(cross(b - a, s - a), cross(b - a, c - a))) >= 0;
    }
    if (in) ts = t;
  }
  REQUIRE(ts != kNoIndex);
  ExactBurning eb(mc);
  eb.add_point_source(ts, s, 0);
  eb.run();
  CHECK(eb.certification().uncertified == 0);
  std::mt19937 rng(5);
  int bent = 0;
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
    for (const ExactPoint3& x : sample_triangle(mc, t, 6, rng)) {
      const bool blocked = segment_meets_open_box(s, x, 2, 4, 2, 4);
      const ExactSum expected = blocked ? exact_distance(s, corner) + exact_distance(corner, x) : exact_distance(s, x);
      bent += blocked;
      const auto e = eb.exact_burn_time(t, x);
      REQUIRE(e);
      CAPTURE(t, x.x.get_d(), x.y.get_d(), to_string(*e), to_string(expected));
      CHECK(exact_sign(*e - expected) == 0);
    }
  CHECK(bent > 10);
}

TEST_CASE("refined sampling, iso-lines, the front at t and the event log", "[exact3]") {
  const MedialComplex mc = built(grid_sheet(4, 3, 2, {{3, 3}}));
  const ExactPoint3 s{mpq_class(1, 2), mpq_class(1, 2), 0};
  ExactBurning eb(mc);
  std::uint32_t ts = kNoIndex;
  for (std::uint32_t t = 0; t < mc.triangle_count() && ts == kNoIndex; ++t)
    if (corner_of(mc.triangle(t), vertex_at(mc, s)) >= 0) ts = t;
  eb.add_point_source(ts, s, 0);
  eb.run();
  const RefinedBurn r = refine(eb, 4);
  CHECK(r.triangles.size() == 16 * mc.triangle_count());
  // Grid points (multiples of 1/8, exact in doubles) that see s past the hole [3/2, 2]^2
  // burn at |x - s|; the others at more.
  int seen = 0, shadowed = 0;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const double d = distance3(r.points[i], to_vec(s));
    const ExactPoint3 x{r.points[i][0], r.points[i][1], 0};
    if (segment_meets_open_box(s, x, mpq_class(3, 2), 2, mpq_class(3, 2), 2)) {
      ++shadowed;
      CHECK(r.bt[i].value + r.bt[i].error > d + 1e-9);
    } else {
      ++seen;
      CHECK(std::abs(r.bt[i].value - d) <= r.bt[i].error + 1e-15);
    }
  }
  CHECK(seen > 100);
  CHECK(shadowed > 10);
  // The iso-line at t = 1 (a circle arc): its vertices within the interpolation error of a
  // grid of spacing 1/8 (h^2 / 2r).
  const auto lines = iso_lines(r, {1.0});
  REQUIRE(lines[0].size() > 10);
  for (const Segment3& g : lines[0]) {
    CHECK(std::abs(distance3(g.a, to_vec(s)) - 1) < 0.01);
    CHECK(std::abs(distance3(g.b, to_vec(s)) - 1) < 0.01);
  }
  // The burned region at t = 1 (marching triangles on the refined values).
  double area = 0;
  for (const auto& poly : front_at(r, 1.0))
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      const Vec3d &a = poly[0], &b = poly[k], &c = poly[k + 1];
      area += 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
  // Reference: the disc of radius 1 about s = (1/2, 1/2) clipped to x, y >= 0 (the hole is
  // farther than 1 from s), by the midpoint rule on a 2000^2 grid over [-1/2, 3/2]^2.
  double ref = 0;
  for (int i = 0; i < 2000; ++i)
    for (int j = 0; j < 2000; ++j) {
      const double x = (i + 0.5) / 1000 - 0.5, y = (j + 0.5) / 1000 - 0.5;
      if (x >= -0.5 && y >= -0.5 && x * x + y * y <= 1) ref += 1e-6;
    }
  CHECK(std::abs(area - ref) < 0.01);
  // The event log: the vertex sources in the order of their exact times.
  const auto log = event_log(eb);
  CHECK(!log.empty());
  for (std::size_t k = 1; k < log.size(); ++k)
    CHECK(eb.propagation().store().times[log[k - 1].time].value.lo <= eb.propagation().store().times[log[k].time].value.hi);
}
