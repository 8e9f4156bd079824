// Exact planar predicates (geometry2/predicates2.h): orientation with its filter and GMP
// fallback, segment intersection classes, point location.
#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <random>

#include "geometry2/predicates2.h"

using namespace grassfire;

namespace {
constexpr double kUlpHalf = 0x1p-53;  // the spacing of doubles in [0.5, 1)
}

TEST_CASE("orientation of clear left, right and collinear triples", "[shapes]") {
  OrientationStats st;
  CHECK(orientation({0, 0}, {1, 0}, {0, 1}, &st) == 1);
  CHECK(orientation({0, 0}, {0, 1}, {1, 0}, &st) == -1);
  CHECK(orientation({0, 0}, {1, 1}, {3, 3}, &st) == 0);
  CHECK(orientation({2, 5}, {2, 7}, {2, -1}, &st) == 0);  // vertical: exact-zero shortcut
  CHECK(orientation({1, 1}, {1, 1}, {4, 2}, &st) == 0);   // repeated point
  // The collinear diagonal triple and the repeated point are not decided by the filter
  // (det evaluates to 0 within a positive error bound); the other three are.
  CHECK(st.filtered == 3);
  CHECK(st.exact == 2);
}

TEST_CASE("near-degenerate orientations are decided by the exact fallback", "[shapes]") {
  // Kettner et al., "Classroom examples of robustness problems": p = (0.5 + i u, 0.5 + j u)
  // with u = 2^-53, q = (12, 12), r = (24, 24). Expanding the determinant gives exactly
  // orient(p, q, r) = 12 (j - i) u, so its sign is sign(j - i).
  OrientationStats st;
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) {
      const Point2 p{0.5 + i * kUlpHalf, 0.5 + j * kUlpHalf};
      const int expected = (j > i) - (j < i);
      INFO("i = " << i << ", j = " << j);
      REQUIRE(orientation(p, {12, 12}, {24, 24}, &st) == expected);
      REQUIRE(orientation({12, 12}, {24, 24}, p, &st) == expected);  // cyclic shift
      REQUIRE(orientation({24, 24}, {12, 12}, p, &st) == -expected);  // swap
    }
  // Every one of these is within the filter's error bound: all went to GMP.
  CHECK(st.exact == 3 * 24 * 24);
  CHECK(st.filtered == 0);
}

TEST_CASE("orientation beyond the filter's range: overflow and underflow", "[shapes]") {
  OrientationStats st;
  // Products overflow to infinity.
  CHECK(orientation({0, 0}, {1e300, 1e300}, {-1e300, 1e300}, &st) == 1);
  CHECK(orientation({-1e308, -1e308}, {1e308, 1e308}, {1e308, -1e308}, &st) == -1);
  // Products underflow to zero although the determinant is not zero.
  CHECK(orientation({0, 0}, {1e-200, 0}, {0, 1e-200}, &st) == 1);
  CHECK(orientation({0, 0}, {4e-320, 0}, {0, -4e-320}, &st) == -1);
  CHECK(st.exact == 4);
}

TEST_CASE("orientation equals the sign of the exact mpq determinant on random near-collinear triples", "[shapes]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  OrientationStats st;
  int signs[3] = {0, 0, 0};
  for (int k = 0; k < 2000; ++k) {
    const Point2 a{u(rng), u(rng)}, b{u(rng), u(rng)};
    const double t = u(rng) / 10;
    // A point on segment ab, rounded, then nudged by a few ulps: sign of either kind.
    Point2 c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    c.x = std::nextafter(c.x, k % 2 ? 1e9 : -1e9);
    // The reference: (b - a) x (c - a) in rationals (doubles convert exactly).
    const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y);
    const int exact = sgn(mpq_class((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)));
    ++signs[exact + 1];
    REQUIRE(orientation(a, b, c, &st) == exact);
    REQUIRE(orientation(b, c, a) == exact);
    REQUIRE(orientation(b, a, c) == -exact);
  }
  CHECK(st.exact > 0);     // some triples went past the filter to GMP
  CHECK(st.filtered > 0);  // and the filter decided others
  CHECK(signs[0] > 0);     // both signs occur
  CHECK(signs[2] > 0);
}

TEST_CASE("segment intersection classes", "[shapes]") {
  using SI = SegmentIntersection;
  CHECK(classify_segments({0, 0}, {2, 2}, {0, 2}, {2, 0}) == SI::Crossing);
  CHECK(classify_segments({0, 0}, {2, 0}, {1, 0}, {1, 5}) == SI::Touching);   // T junction
  CHECK(classify_segments({0, 0}, {2, 0}, {2, 0}, {3, 4}) == SI::Touching);   // shared endpoint
  CHECK(classify_segments({0, 0}, {2, 0}, {1, 1}, {1, 5}) == SI::Disjoint);
  CHECK(classify_segments({0, 0}, {2, 0}, {0, 1}, {2, 1}) == SI::Disjoint);   // parallel
  CHECK(classify_segments({0, 0}, {2, 0}, {1, 0}, {3, 0}) == SI::Overlap);
  CHECK(classify_segments({0, 0}, {2, 0}, {2, 0}, {3, 0}) == SI::Touching);   // collinear, end to end
  CHECK(classify_segments({0, 0}, {2, 0}, {3, 0}, {4, 0}) == SI::Disjoint);   // collinear, apart
  CHECK(classify_segments({0, 0}, {4, 4}, {3, 3}, {1, 1}) == SI::Overlap);    // contained, reversed
  CHECK(classify_segments({1, 0}, {1, 4}, {1, 4}, {1, 6}) == SI::Touching);   // vertical
  CHECK(classify_segments({1, 0}, {1, 4}, {1, 2}, {1, 6}) == SI::Overlap);
  // Zero-length segments.
  CHECK(classify_segments({1, 1}, {1, 1}, {0, 0}, {2, 2}) == SI::Touching);
  CHECK(classify_segments({1, 1}, {1, 1}, {0, 0}, {2, 3}) == SI::Disjoint);
  CHECK(classify_segments({1, 1}, {1, 1}, {1, 1}, {1, 1}) == SI::Touching);
  CHECK(classify_segments({1, 1}, {1, 1}, {1, 2}, {1, 2}) == SI::Disjoint);
}

TEST_CASE("segment classes at the resolution of doubles", "[shapes]") {
  using SI = SegmentIntersection;
  OrientationStats st;
  // q0 is one ulp above, on, or below the line through p0 = (0.5, 0.5) and p1 = (24, 24).
  const Point2 p0{0.5, 0.5}, p1{24, 24};
  CHECK(classify_segments(p0, p1, {0.5 + kUlpHalf, 0.5}, {1, 0}, &st) == SI::Disjoint);
  CHECK(classify_segments(p0, p1, {0.5, 0.5 + kUlpHalf}, {1, 0}, &st) == SI::Crossing);
  CHECK(classify_segments(p0, p1, {12, 12}, {13, 0}, &st) == SI::Touching);
  CHECK(classify_segments(p0, p1, {12, 12}, {30, 30}, &st) == SI::Overlap);
  CHECK(st.exact > 0);
}

TEST_CASE("point location in a ring, including rays through vertices", "[shapes]") {
  // A comb: vertices at y = 0, 2, 4 so that horizontal rays pass through vertices.
  const std::vector<Point2> comb = {{0, 0}, {6, 0}, {6, 4}, {5, 4}, {5, 2}, {4, 2}, {4, 4},
                                    {2, 4}, {2, 2}, {1, 2}, {1, 4}, {0, 4}};
  auto at = [&](double x, double y) { return locate_in_ring({x, y}, comb); };
  CHECK(at(0.5, 2) == BoundedSide::Inside);    // ray through vertices (1,2), (2,2), (4,2), (5,2)
  CHECK(at(1.5, 2) == BoundedSide::Boundary);  // on the horizontal edge between the teeth
  CHECK(at(1.5, 3) == BoundedSide::Outside);   // in a gap
  CHECK(at(3, 3) == BoundedSide::Inside);      // in the middle tooth
  CHECK(at(-1, 2) == BoundedSide::Outside);
  CHECK(at(-1, 4) == BoundedSide::Outside);    // ray along the top edges
  CHECK(at(3, 4) == BoundedSide::Boundary);
  CHECK(at(6, 4) == BoundedSide::Boundary);    // a vertex
  CHECK(at(7, 0) == BoundedSide::Outside);
  CHECK(at(5.5, 1) == BoundedSide::Inside);
  // Orientation does not matter.
  const std::vector<Point2> reversed(comb.rbegin(), comb.rend());
  for (double y = -0.5; y <= 4.5; y += 0.5)
    for (double x = -0.5; x <= 6.5; x += 0.5) REQUIRE(locate_in_ring({x, y}, reversed) == at(x, y));
}

TEST_CASE("winding_step counts crossings of the rightward ray", "[shapes]") {
  CHECK(winding_step({0, 0}, {1, -1}, {1, 1}) == 1);
  CHECK(winding_step({0, 0}, {1, 1}, {1, -1}) == -1);
  CHECK(winding_step({2, 0}, {1, -1}, {1, 1}) == 0);  // left of q
  // A vertex on the ray's line counts as below it.
  CHECK(winding_step({0, 0}, {1, 0}, {1, 1}) == 1);
  CHECK(winding_step({0, 0}, {1, -1}, {1, 0}) == 0);
  CHECK(winding_step({0, 0}, {1, 0}, {1, -1}) == 0);
  CHECK(winding_step({0, 0}, {1, 1}, {1, 0}) == -1);
}

TEST_CASE("point location in a shape with a hole", "[shapes]") {
  Shape2 s{"square with hole",
           {Ring{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, Ring{{{3, 3}, {3, 7}, {7, 7}, {7, 3}}}}};
  CHECK(locate_in_shape({1, 1}, s) == BoundedSide::Inside);
  CHECK(locate_in_shape({5, 5}, s) == BoundedSide::Outside);
  CHECK(locate_in_shape({3, 5}, s) == BoundedSide::Boundary);
  CHECK(locate_in_shape({10, 5}, s) == BoundedSide::Boundary);
  CHECK(locate_in_shape({11, 5}, s) == BoundedSide::Outside);
  CHECK(locate_in_shape({5, 7.5}, s) == BoundedSide::Inside);
}
