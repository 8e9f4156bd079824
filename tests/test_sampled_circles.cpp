// Certified circumcircles of sample triangles (geometry2/lazy_point.h): the double
// (interval_circle) and x87 (long_circle) enclosures of the centre and the radius contain
// the exact circle, on random, thin (dense boundary sampling) and nearly collinear
// triangles. Guards any change that tightens these semi-static error bounds.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "geometry2/lazy_point.h"

using namespace grassfire;

namespace {

bool contains(const Interval& i, const mpq_class& x) { return mpq_class(i.lo) <= x && x <= mpq_class(i.hi); }
// A long double as an exact rational: its 64-bit significand is the sum of two doubles.
mpq_class exact_value(long double v) {
  const double hi = static_cast<double>(v);
  return mpq_class(hi) + mpq_class(static_cast<double>(v - hi));
}
bool contains(const LongInterval& i, const mpq_class& x) { return exact_value(i.lo) <= x && x <= exact_value(i.hi); }

// Checks both enclosures of the circumcircle of (a, b, c) against the exact circle.
void check_circle(const Point2& a, const Point2& b, const Point2& c) {
  const ExactPoint2 e = exact_circumcenter(a, b, c);
  const mpq_class dx = e.x - mpq_class(a.x), dy = e.y - mpq_class(a.y);
  const mpq_class r2 = dx * dx + dy * dy;
  const Circle k = interval_circle(a, b, c);
  REQUIRE(contains(k.center.x, e.x));
  REQUIRE(contains(k.center.y, e.y));
  REQUIRE(mpq_class(k.radius.lo) * mpq_class(k.radius.lo) <= r2);
  REQUIRE(r2 <= mpq_class(k.radius.hi) * mpq_class(k.radius.hi));
  LongInterval x, y, r;
  if (long_circle(a, b, c, x, y, r)) {
    REQUIRE(contains(x, e.x));
    REQUIRE(contains(y, e.y));
    const mpq_class rl = exact_value(r.lo), rh = exact_value(r.hi);
    REQUIRE(rl * rl <= r2);
    REQUIRE(r2 <= rh * rh);
  }
}

}  // namespace

TEST_CASE("circumcircle enclosures contain the exact circle: random triangles", "[sampled][circles]") {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> coord(-3.0, 3.0);
  for (int i = 0; i < 2000; ++i) {
    const Point2 a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)}, c{coord(rng), coord(rng)};
    check_circle(a, b, c);
  }
}

TEST_CASE("circumcircle enclosures contain the exact circle: thin boundary triangles", "[sampled][circles]") {
  // Two nearby samples of one boundary arc and a far sample across the shape, as in a
  // dense sampling (the circumcentre is far from the short side), at many scales.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double h = std::ldexp(1.0, -static_cast<int>(8 + 30 * unit(rng)));
    const double t = 6.283185307179586 * unit(rng), s = 0.3 + unit(rng);
    const Point2 a{0.5 + 0.1 * unit(rng), 0.25 + 0.1 * unit(rng)};
    const Point2 b{a.x + h * std::cos(t), a.y + h * std::sin(t)};
    const Point2 c{a.x + s * std::cos(t + 1.0 + unit(rng)), a.y + s * std::sin(t + 1.0 + unit(rng))};
    check_circle(a, b, c);
    check_circle(b, c, a);
    check_circle(c, a, b);
  }
}

TEST_CASE("circumcircle enclosures contain the exact circle: nearly collinear triangles", "[sampled][circles]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Point2 a{unit(rng), unit(rng)}, b{unit(rng), unit(rng)};
    const double t = unit(rng);
    Point2 c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    c.x = std::nextafter(c.x, i % 2 ? 2.0 : -2.0);  // a few ulps off the line
    if (a == c || b == c) continue;
    const mpq_class cross = (mpq_class(b.x) - a.x) * (mpq_class(c.y) - a.y) - (mpq_class(b.y) - a.y) * (mpq_class(c.x) - a.x);
    if (cross == 0) continue;
    check_circle(a, b, c);
  }
}
