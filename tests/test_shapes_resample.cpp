// Uniform arc-length resampling (shapes/resample.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "shapes/builtin_shapes.h"
#include "shapes/resample.h"
#include "shapes/validate_shape.h"

using namespace grassfire;

namespace {

std::size_t total(const BoundarySamples& s) {
  std::size_t n = 0;
  for (const std::vector<Point2>& r : s) n += r.size();
  return n;
}

}  // namespace

TEST_CASE("rectangle samples at unit spacing are exactly the integer boundary points", "[shapes]") {
  const Shape2 rect = builtin_shape("rectangle");  // 10 x 4, perimeter 28
  const BoundarySamples s = resample_by_count(rect, 28);
  REQUIRE(s.size() == 1);
  REQUIRE(s[0].size() == 28);
  std::vector<Point2> expected;
  for (int x = 0; x < 10; ++x) expected.push_back({double(x), 0});
  for (int y = 0; y < 4; ++y) expected.push_back({10, double(y)});
  for (int x = 10; x > 0; --x) expected.push_back({double(x), 4});
  for (int y = 4; y > 0; --y) expected.push_back({0, double(y)});
  CHECK(s[0] == expected);
  // By spacing: ceil(28 / 1.5) = 19 samples, 28/19 apart.
  const BoundarySamples h = resample_by_spacing(rect, 1.5);
  CHECK(h[0].size() == 19);
  CHECK(h[0][0] == Point2{0, 0});
}

TEST_CASE("sample counts: exact total, proportional to length, at least 8 per ring", "[shapes]") {
  const Shape2 hole = builtin_shape("hole");
  const double outer = ring_length(hole.rings[0]), inner = ring_length(hole.rings[1]);
  for (std::size_t n : {16, 17, 50, 333, 1000, 4097}) {
    INFO("N = " << n);
    const BoundarySamples s = resample_by_count(hole, n);
    REQUIRE(total(s) == n);
    const double share = n * inner / (outer + inner);
    const double m = static_cast<double>(s[1].size());
    CHECK(m >= 8);
    if (share >= 8) CHECK(std::fabs(m - share) < 1.0);
  }
  // N = 16: the hole's share (about 4.5) is raised to 8, the outer ring gives them up.
  const BoundarySamples small = resample_by_count(hole, 16);
  CHECK(small[0].size() == 8);
  CHECK(small[1].size() == 8);
  CHECK_THROWS_WITH(resample_by_count(hole, 15), Catch::Contains("between 16 (8 per ring)"));
  CHECK_THROWS_AS(resample_by_spacing(hole, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(resample_by_spacing(hole, std::nan("")), std::invalid_argument);
  CHECK_THROWS_AS(resample_by_spacing(hole, 1e-12), std::invalid_argument);  // over 10^9 samples
  // By spacing, every ring gets ceil(L / h), at least 8.
  const BoundarySamples h = resample_by_spacing(hole, 0.5);
  CHECK(h[0].size() == static_cast<std::size_t>(std::ceil(outer / 0.5)));
  CHECK(h[1].size() == static_cast<std::size_t>(std::ceil(inner / 0.5)));
  CHECK(resample_by_spacing(hole, 100)[1].size() == 8);
}

TEST_CASE("samples are distinct, in ring order, and on the boundary", "[shapes]") {
  for (const BuiltinShapeInfo& info : builtin_shape_list()) {
    INFO(info.name);
    const Shape2 shape = builtin_shape(info.name);
    const BoundarySamples s = resample_by_count(shape, 3000);
    std::set<std::pair<double, double>> seen;
    for (std::size_t r = 0; r < s.size(); ++r) {
      CHECK(s[r][0] == shape.rings[r].points[0]);
      for (const Point2& p : s[r]) seen.insert({p.x, p.y});
      // Sample k lies on the ring (on one of its edges, up to rounding) at arc length
      // k L / m from the first vertex: on the boundary and in ring order.
      const std::vector<Point2>& ring = shape.rings[r].points;
      const double length = ring_length(shape.rings[r]), spacing = length / static_cast<double>(s[r].size());
      for (std::size_t k = 0; k < s[r].size(); ++k) {
        const Point2& p = s[r][k];
        double off = 1e300, arc = 0, at = 0;
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Point2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
          const double len = std::hypot(b.x - a.x, b.y - a.y);
          const double t = std::clamp(((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / (len * len), 0.0, 1.0);
          const double d = std::hypot(a.x + t * (b.x - a.x) - p.x, a.y + t * (b.y - a.y) - p.y);
          if (d < off) off = d, at = arc + t * len;
          arc += len;
        }
        CAPTURE(r, k, off, at);
        REQUIRE(off <= 1e-12 * (1 + std::hypot(p.x, p.y)));
        REQUIRE(std::fabs(at - static_cast<double>(k) * spacing) <= 1e-9 * length);
      }
    }
    CHECK(seen.size() == total(s));
  }
}

TEST_CASE("coincident samples are an error, not a silent output", "[shapes]") {
  // A triangle a few ulps wide: 64 samples cannot be distinct doubles.
  Shape2 tiny{"tiny", {Ring{{{1, 1}, {1 + 0x1p-50, 1}, {1, 1 + 0x1p-50}}}}};
  validate_shape(tiny, "tiny");
  CHECK_THROWS_WITH(resample_by_count(tiny, 64), Catch::StartsWith("tiny: ring 0 (outer): sample ") &&
                                                     Catch::Contains("coincide at"));
  CHECK(total(resample_by_count(tiny, 8)) == 8);  // 8 samples still fit
}
