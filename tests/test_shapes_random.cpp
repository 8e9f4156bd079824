// The fast validation (exact edge grid) against the O(n^2) all-pairs reference on seeded
// random polygons, the grid's guarantees directly, and metamorphic checks of the verdict.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>

#include "shapes/edge_grid.h"
#include "shapes/validate_shape.h"

using namespace grassfire;

namespace {

struct Outcome {
  bool valid = false;
  std::string message;
  long ring = -2, vertex = -2;
  Shape2 shape;
};

Outcome run(Shape2 s, PairSearch search) {
  Outcome o;
  try {
    validate_shape(s, "random", search);
    o.valid = true;
    o.shape = std::move(s);
  } catch (const InvalidShapeError& e) {
    o.message = e.what();
    o.ring = e.ring();
    o.vertex = e.vertex();
  }
  return o;
}

// A star-shaped ring about (cx, cy): n random angles, random radii in [r0, r1], coordinates
// rounded to multiples of `snap` (0: no rounding). Rounding to a coarse grid creates the
// degenerate cases (touching vertices, collinear overlaps, spikes, crossings).
std::vector<Point2> star(std::mt19937_64& rng, int n, double cx, double cy, double r0, double r1, double snap) {
  std::uniform_real_distribution<double> angle(0, 2 * std::acos(-1.0)), radius(r0, r1);
  std::vector<double> a(n);
  for (double& t : a) t = angle(rng);
  std::sort(a.begin(), a.end());
  std::vector<Point2> p;
  for (double t : a) {
    const double r = radius(rng);
    double x = cx + r * std::cos(t), y = cy + r * std::sin(t);
    if (snap > 0) {
      x = std::round(x / snap) * snap;
      y = std::round(y / snap) * snap;
    }
    p.push_back({x, y});
  }
  return p;
}

// Outer ring plus up to three holes; sometimes two vertices swapped.
Shape2 random_shape(std::mt19937_64& rng, double snap) {
  std::uniform_int_distribution<int> vertices(3, 30), holes(0, 3), coin(0, 3);
  std::uniform_real_distribution<double> centre(2, 18);
  Shape2 s{"random", {Ring{star(rng, vertices(rng), 10, 10, 3, 10, snap)}}};
  const int h = holes(rng);
  for (int k = 0; k < h; ++k) s.rings.push_back(Ring{star(rng, vertices(rng) % 7 + 3, centre(rng), centre(rng), 0.5, 3, snap)});
  if (coin(rng) == 0) {
    std::vector<Point2>& p = s.rings[0].points;
    std::uniform_int_distribution<std::size_t> pick(0, p.size() - 1);
    std::swap(p[pick(rng)], p[pick(rng)]);
  }
  return s;
}

void require_same(const Outcome& fast, const Outcome& slow) {
  REQUIRE(fast.valid == slow.valid);
  REQUIRE(fast.message == slow.message);
  if (!fast.valid) return;
  REQUIRE(fast.shape.rings.size() == slow.shape.rings.size());
  for (std::size_t r = 0; r < fast.shape.rings.size(); ++r) REQUIRE(fast.shape.rings[r].points == slow.shape.rings[r].points);
}

}  // namespace

TEST_CASE("grid validation equals the all-pairs reference on random shapes", "[shapes]") {
  std::mt19937_64 rng(2011);
  int valid = 0, invalid = 0;
  for (int i = 0; i < 3000; ++i) {
    const double snap = i % 3 == 0 ? 1.0 : i % 3 == 1 ? 0.25 : 0.0;
    const Shape2 s = random_shape(rng, snap);
    INFO("instance " << i);
    const Outcome fast = run(s, PairSearch::Grid), slow = run(s, PairSearch::AllPairs);
    require_same(fast, slow);
    (fast.valid ? valid : invalid)++;
  }
  // Both verdicts occur often, so the comparison means something either way.
  CHECK(valid > 300);
  CHECK(invalid > 300);
}

TEST_CASE("grid validation equals the reference on large polygons with long edges", "[shapes]") {
  std::mt19937_64 rng(42);
  for (int i = 0; i < 6; ++i) {
    INFO("instance " << i);
    // Star-shaped with 3000 vertices, plus long chords: every 500th vertex removed in a
    // run of 40 (long edges spanning many grid cells, also diagonally). The last two lie
    // far from the origin, where the grid's cells are anchored.
    const Point2 centre = i < 4 ? Point2{0.5, -0.25} : Point2{1e9, -3e9};
    std::vector<Point2> p = star(rng, 3000, centre.x, centre.y, 1, 1.2, 0.0);
    std::vector<Point2> q;
    for (std::size_t k = 0; k < p.size(); ++k)
      if (k % 500 >= 40) q.push_back(p[k]);
    Shape2 s{"large", {Ring{q}}};
    if (i % 2 == 1) {  // move one vertex somewhere random: usually a self-intersection
      std::uniform_int_distribution<std::size_t> pick(0, q.size() - 1);
      std::uniform_real_distribution<double> u(-1.2, 1.2);
      s.rings[0].points[pick(rng)] = {centre.x + u(rng), centre.y + u(rng)};
    }
    require_same(run(s, PairSearch::Grid), run(s, PairSearch::AllPairs));
  }
}

TEST_CASE("every pair of edges that meet is a grid candidate", "[shapes]") {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 300; ++i) {
    // Random edge soups on a coarse grid: many touching and overlapping pairs.
    std::vector<Ring> rings;
    std::uniform_int_distribution<int> count(3, 25), coord(0, 12);
    std::uniform_real_distribution<double> far(-1000, 1000);
    for (int r = 0; r < 3; ++r) {
      Ring ring;
      const int n = count(rng);
      for (int k = 0; k < n; ++k) ring.points.push_back({coord(rng) * 0.5, coord(rng) * 0.5});
      if (i % 10 == 0) ring.points.push_back({far(rng), far(rng)});  // a very long edge
      rings.push_back(ring);
    }
    const EdgeGrid grid(rings);
    std::set<std::pair<std::uint32_t, std::uint32_t>> candidates;
    grid.for_each_candidate_pair([&](std::uint32_t a, std::uint32_t b) { candidates.insert({a, b}); });
    auto endpoints = [&](std::uint32_t g) {
      const EdgeGrid::EdgeId e = grid.edge(g);
      const std::vector<Point2>& p = rings[e.ring].points;
      return std::make_pair(p[e.index], p[(e.index + 1) % p.size()]);
    };
    std::size_t meeting = 0;
    for (std::uint32_t a = 0; a < grid.edge_count(); ++a)
      for (std::uint32_t b = a + 1; b < grid.edge_count(); ++b) {
        const auto [p0, p1] = endpoints(a);
        const auto [q0, q1] = endpoints(b);
        if (classify_segments(p0, p1, q0, q1) == SegmentIntersection::Disjoint) continue;
        ++meeting;
        INFO("instance " << i << ", edges " << a << ", " << b);
        REQUIRE(candidates.count({a, b}) == 1);
      }
    CHECK(meeting > 0);
  }
}

TEST_CASE("grid ray windings equal point location on random rings", "[shapes]") {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-2, 22);
  for (int i = 0; i < 200; ++i) {
    std::vector<Ring> rings;
    for (int r = 0; r < 3; ++r) rings.push_back(Ring{star(rng, 5 + r * 7, 6 + 4 * r, 10, 2, 7, r == 1 ? 1.0 : 0.0)});
    const EdgeGrid grid(rings);
    for (int k = 0; k < 20; ++k) {
      // Queries on a half-integer grid, so rays often pass through vertices.
      const Point2 q{std::round(2 * u(rng)) / 2, std::round(2 * u(rng)) / 2};
      bool on_boundary = false;
      for (const Ring& r : rings) on_boundary |= locate_in_ring(q, r.points) == BoundedSide::Boundary;
      if (on_boundary) continue;
      std::vector<long> winding(rings.size(), 0);
      grid.add_ray_windings(q, 99, winding);
      for (std::size_t r = 0; r < rings.size(); ++r) {
        INFO("instance " << i << ", ring " << r << ", q = (" << q.x << ", " << q.y << ")");
        REQUIRE((winding[r] != 0) == (locate_in_ring(q, rings[r].points) == BoundedSide::Inside));
      }
    }
  }
}

TEST_CASE("the verdict is invariant under exact translation, scaling and reversal", "[shapes]") {
  std::mt19937_64 rng(77);
  for (int i = 0; i < 1000; ++i) {
    const Shape2 s = random_shape(rng, i % 2 ? 1.0 : 0.5);  // small dyadic coordinates
    const Outcome base = run(s, PairSearch::Grid);
    INFO("instance " << i << ": " << base.message);
    // Translation by dyadic amounts and scaling by powers of two are exact here.
    for (const Point2 d : {Point2{1024, -4096.5}, Point2{-0.125, 3e6}}) {
      Shape2 t = s;
      for (Ring& r : t.rings)
        for (Point2& p : r.points) p = {p.x + d.x, p.y + d.y};
      const Outcome moved = run(t, PairSearch::Grid);
      REQUIRE(moved.valid == base.valid);
      REQUIRE(moved.ring == base.ring);
      REQUIRE(moved.vertex == base.vertex);
    }
    Shape2 scaled = s;
    for (Ring& r : scaled.rings)
      for (Point2& p : r.points) p = {std::ldexp(p.x, -60), std::ldexp(p.y, 70)};
    REQUIRE(run(scaled, PairSearch::Grid).valid == base.valid);
    // Reversing every ring's vertex order, and the order of the holes.
    Shape2 reversed = s;
    for (Ring& r : reversed.rings) std::reverse(r.points.begin(), r.points.end());
    std::reverse(reversed.rings.begin() + 1, reversed.rings.end());
    REQUIRE(run(reversed, PairSearch::Grid).valid == base.valid);
  }
}
