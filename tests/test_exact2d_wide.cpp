// The wide and mp binary policies (medial2/polygon/polygon_axis.h, boost_wide_traits.h,
// boost_mp_traits.h): Boost.Polygon's builder on 62-bit integer frames, and on integers of
// any size (filter stage and MPFR run), against CGAL's Segment_Delaunay_graph_2 on the same
// exact polygon, Voronoi topology site by site, on seeded polygons with arbitrary
// (full-mantissa) double coordinates spanning up to ~2000 bits; and where the policy sends
// which input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <tuple>

#include "medial2/polygon/polygon_axis.h"
#include "medial2/polygon/segment_voronoi.h"
#include "shapes/validate_shape.h"
#include "binary_frame.h"
#include "support.h"

using namespace grassfire;

namespace {

Shape2 ring_shape(std::vector<Point2> ring, const std::string& name) {
  Shape2 s;
  s.name = name;
  s.rings.push_back({std::move(ring)});
  validate_shape(s, name);
  return s;
}

// A star polygon around (cx, cy): n vertices at seeded random radii in [0.3 r, r], every
// coordinate a double as computed (full mantissa, on no decimal or int32 binary grid).
Shape2 random_star(std::mt19937& rng, int n, double cx, double cy, double r) {
  std::uniform_real_distribution<double> radius(0.3 * r, r), jitter(-0.3, 0.3);
  std::vector<Point2> ring;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * (k + jitter(rng)) / n, rk = radius(rng);
    ring.push_back({cx + rk * std::cos(t), cy + rk * std::sin(t)});
  }
  return ring_shape(ring, "star " + std::to_string(n));
}

// A dense sample of a smooth wavy closed curve (the near-degenerate case for filters: nearly
// cocircular consecutive vertices).
Shape2 wavy(int n, double cx, double cy, double r, double phase) {
  std::vector<Point2> ring;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n, rk = r * (1 + 0.1 * std::sin(7 * t + phase));
    ring.push_back({cx + rk * std::cos(t), cy + rk * std::sin(t)});
  }
  return ring_shape(ring, "wavy " + std::to_string(n));
}

// A Voronoi diagram as sets of site triples (rotated to start at the smallest site, the
// counter-clockwise order kept; apexes marked) and of edges (the two sites and the two
// end vertices' triples, unordered): equal sets = the same topology.
using Triple = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, bool>;
Triple canonical(const VoronoiTopology::Vertex& v) {
  auto s = v.sites;
  while (s[0] > s[1] || s[0] > s[2]) s = {s[1], s[2], s[0]};
  return {s[0], s[1], s[2], v.apex};
}
struct Canonical {
  std::multiset<Triple> vertices;
  std::multiset<std::tuple<std::uint32_t, std::uint32_t, Triple, Triple>> edges;
};
Canonical canonical(const VoronoiTopology& t) {
  Canonical c;
  for (const auto& v : t.vertices) c.vertices.insert(canonical(v));
  for (const auto& e : t.edges) {
    Triple a = canonical(t.vertices[e.u]), b = canonical(t.vertices[e.v]);
    if (b < a) std::swap(a, b);
    c.edges.insert({std::min(e.site_a, e.site_b), std::max(e.site_a, e.site_b), a, b});
  }
  return c;
}

void require_same_topology(const Shape2& s) {
  const PolygonSites sites = testing::binary_frame(s);
  REQUIRE(fits_wide_boost(sites));
  const Canonical b = canonical(boost_segment_voronoi_wide(sites)), c = canonical(cgal_segment_voronoi(sites));
  INFO(s.name);
  REQUIRE(b.vertices.size() == c.vertices.size());
  CHECK(b.vertices == c.vertices);
  CHECK(b.edges == c.edges);
}

}  // namespace

TEST_CASE("wide Boost = CGAL SDG on 60 seeded star polygons with full-mantissa doubles", "[exact2d]") {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<double> centre(-1e4, 1e4), log_r(-3, 6);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 5 + (trial * 37) % 240;
    const double r = std::pow(10.0, log_r(rng));
    // The centre at least 3 r from the axes: coordinates stay away from 0, where a
    // full-mantissa double would need more than 62 bits in the frame.
    const double cx = std::copysign(3 * r + std::fabs(centre(rng)), centre(rng));
    const double cy = std::copysign(3 * r + std::fabs(centre(rng)), centre(rng));
    CAPTURE(trial, n, r, cx, cy);
    require_same_topology(random_star(rng, n, cx, cy, r));
  }
}

TEST_CASE("wide Boost = CGAL SDG on dense wavy curves with full-mantissa doubles", "[exact2d]") {
  // Generic phases: no four sites cocircular. (Phase 0 is mirror-symmetric up to rounding
  // and has exactly cocircular sites, where the two constructions may split a degree-4
  // vertex along different diagonals: compared after contraction, on the axis, in
  // test_exact2d_polygon.cpp.)
  for (const auto& [n, phase] : {std::pair<int, double>{500, 0.3}, {1500, 1.1}, {3000, 0.3}}) {
    CAPTURE(n, phase);
    require_same_topology(wavy(n, 3e6, -2.5e6, 1e6, phase));
  }
}

TEST_CASE("input policy: which construction runs for which doubles", "[exact2d]") {
  std::mt19937 rng(5);
  PolygonAxisReport rep;
  // Full-mantissa doubles away from 0: the wide binary frame.
  exact_polygon_axis(random_star(rng, 40, 3e6, 2e6, 1e5), {}, &rep);
  CHECK(rep.construction == AxisConstruction::BoostPolygonWide);
  CHECK(rep.binary_digits > 20);
  // Integers below 2^31: the decimal policy (int32 Boost); forced wide on the same polygon.
  const Shape2 ints = ring_shape({{0, 0}, {7, 0}, {7, 3}, {4, 3}, {5, 6}, {1, 5}, {2, 2}, {0, 2}}, "integers");
  exact_polygon_axis(ints, {}, &rep);
  CHECK(rep.construction == AxisConstruction::BoostPolygon);
  PolygonAxisOptions wide;
  wide.construction = AxisConstruction::BoostPolygonWide;
  exact_polygon_axis(ints, wide, &rep);
  CHECK(rep.construction == AxisConstruction::BoostPolygonWide);
  // A full-mantissa coordinate next to 0 with others near 1: beyond 62 bits, the mp traits
  // (CGAL's SDG only when asked for).
  const Shape2 tiny = ring_shape({{1.0 / 3, 1e-30 / 3}, {1, 0.1}, {0.7, 0.9}, {0.1, 0.6}}, "tiny");
  exact_polygon_axis(tiny, {}, &rep);
  CHECK(rep.construction == AxisConstruction::BoostPolygonMp);
  CHECK(rep.mp_input_bits > 126);
  CHECK(testing::error_of([&] { exact_polygon_axis(tiny, wide); }).find("62 bits") != std::string::npos);
  PolygonAxisOptions sdg;
  sdg.construction = AxisConstruction::CgalSdg;
  exact_polygon_axis(tiny, sdg, &rep);
  CHECK(rep.construction == AxisConstruction::CgalSdg);
}

namespace {

// A star polygon about the origin whose vertex k = 0 lies at angle pi/2 as computed
// (x = r cos(pi/2 as a double) ~ 6e-17 r, full mantissa) and, when `tiny` is not 0, whose
// vertex k = n/4 (at angle pi) has y = tiny times a seeded full-mantissa factor: spans of ~107 bits
// (tiny = 0) or 52 + log2(r / tiny) bits.
Shape2 spanning_star(std::mt19937& rng, int n, double r, double tiny) {
  std::uniform_real_distribution<double> radius(0.3 * r, r), jitter(-0.3, 0.3), factor(1, 2);
  std::vector<Point2> ring;
  for (int k = 0; k < n; ++k) {
    const double t = k == 0 ? M_PI / 2 : M_PI / 2 + 2 * M_PI * (k + jitter(rng)) / n, rk = k == 0 ? r : radius(rng);
    ring.push_back({rk * std::cos(t), rk * std::sin(t)});
  }
  if (tiny != 0) ring[n / 4] = {-radius(rng), tiny * factor(rng) / 3};  // at angle pi
  return ring_shape(ring, "spanning star " + std::to_string(n));
}

// The mp traits (the filter stage and the MPFR run alone) and CGAL's SDG give one topology.
MpTier require_mp_topology(const Shape2& s) {
  const PolygonSites sites = make_sites(s, 1.0);
  MpTier tier, reference;
  const Canonical f = canonical(boost_segment_voronoi_mp(sites, &tier));
  const Canonical m = canonical(boost_segment_voronoi_mp(sites, &reference, false));
  const Canonical c = canonical(cgal_segment_voronoi(sites));
  INFO(s.name << ": " << tier.input_bits << "-bit integers, " << tier.float_bits << "-bit floats");
  REQUIRE(f.vertices.size() == c.vertices.size());
  CHECK(f.vertices == c.vertices);
  CHECK(f.edges == c.edges);
  CHECK(m.vertices == c.vertices);
  CHECK(m.edges == c.edges);
  CHECK(tier.input_bits == reference.input_bits);
  return tier;
}

}  // namespace

TEST_CASE("mp Boost (filter stage and MPFR) = CGAL SDG on 60 seeded stars spanning ~107 bits", "[exact2d]") {
  std::mt19937 rng(20261205);
  std::uniform_real_distribution<double> log_r(-3, 6);
  int filtered = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 5 + (trial * 37) % 240;
    const double r = std::pow(10.0, log_r(rng));
    CAPTURE(trial, n, r);
    const MpTier t = require_mp_topology(spanning_star(rng, n, r, 0));
    CHECK(t.input_bits > 90);  // beyond the wide traits' 62
    CHECK(t.input_bits <= 126);
    filtered += t.filtered;
  }
  CHECK(filtered >= 50);  // the filter stage decides (almost) every construction
}

TEST_CASE("mp Boost = CGAL SDG on dense wavy curves about the origin (~107 bits)", "[exact2d]") {
  // Nearly cocircular consecutive sites: the filters' hardest case (generic phases).
  for (const auto& [n, phase] : {std::pair<int, double>{1500, 0.3}, {3000, 1.1}}) {
    CAPTURE(n, phase);
    const MpTier t = require_mp_topology(wavy(n, 0, 0, 1e6, phase));
    CHECK(t.input_bits > 100);
    // The corner circles (a vertex and its two segments, radius 0) are formed without MPFR
    // and cancellation in robust_fpt's error bookkeeping is decided in the filter
    // (boost_filter_robust_fpt.h); before, fallbacks > n (one MPFR circle per vertex).
    CHECK(t.filtered);
    CHECK(t.fallbacks < static_cast<std::uint64_t>(n) / 15);
  }
}

namespace {

// A star polygon about the origin whose vertices are integer points of radius 3..14 (many
// cocircular and collinear quadruples), in increasing angle, each coordinate moved by
// m 2^-48 (m seeded in -2..2: exact ties and near ties below the double intervals'
// resolution); the vertex on the ray at angle 0 gets y = 1e-18 / 3 (~118-bit span).
Shape2 grid_star(std::mt19937& rng) {
  std::vector<std::pair<double, std::pair<int, int>>> by_angle;
  for (int x = -14; x <= 14; ++x)
    for (int y = -14; y <= 14; ++y)
      if (x * x + y * y >= 9 && x * x + y * y <= 196) by_angle.push_back({std::atan2(y, x), {x, y}});
  std::sort(by_angle.begin(), by_angle.end());
  std::bernoulli_distribution keep(0.5);
  std::uniform_int_distribution<int> move(-2, 2);
  std::vector<Point2> ring;
  double last = -10;
  for (const auto& [angle, p] : by_angle)
    if (angle != last && (keep(rng) || angle == 0)) {  // one vertex per ray: a star polygon
      const double x = p.first + std::ldexp(move(rng), -48), y = p.second + std::ldexp(move(rng), -48);
      ring.push_back({x, angle == 0 ? 1e-18 / 3 : y});
      last = angle;
    }
  return ring_shape(ring, "grid star");
}

}  // namespace

TEST_CASE("mp filter stage: every decision it takes is the MPFR predicates' (near-degenerate grid stars)",
          "[exact2d]") {
  // Verification mode: each node comparison, circle event (and its enclosures) and event
  // comparison the double intervals decide is decided again by the MPFR predicates. A
  // filter that guesses where its intervals overlap disagrees on these exact ties.
  std::mt19937 rng(20261208);
  std::uint64_t verified = 0;
  for (int trial = 0; trial < 10; ++trial) {
    CAPTURE(trial);
    const Shape2 s = grid_star(rng);
    const PolygonSites sites = make_sites(s, 1.0);
    MpTier t, reference;
    const Canonical f = canonical(boost_segment_voronoi_mp(sites, &t, true, true));
    CHECK(t.input_bits > 100);
    CHECK(t.filtered);
    CHECK(t.verify_mismatches == 0);
    verified += t.verified;
    // Exact ties: Boost's and CGAL's diagrams split degenerate vertices differently, so the
    // reference is the MPFR run alone, whose branches the filter stage must take.
    const Canonical m = canonical(boost_segment_voronoi_mp(sites, &reference, false));
    CHECK(f.vertices == m.vertices);
    CHECK(f.edges == m.edges);
  }
  CHECK(verified > 10000);
}

TEST_CASE("mp Boost = CGAL SDG on 30 seeded stars spanning 300-500 bits", "[exact2d]") {
  std::mt19937 rng(20261206);
  std::uniform_real_distribution<double> log_tiny(-150, -75);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 6 + (trial * 29) % 200;
    const double tiny = std::pow(10.0, log_tiny(rng));
    CAPTURE(trial, n, tiny);
    const MpTier t = require_mp_topology(spanning_star(rng, n, 1e3, tiny));
    CHECK(t.input_bits > 250);
    CHECK(t.float_bits >= t.input_bits + 64);
  }
}

TEST_CASE("mp Boost on coordinates from 1e-300 to 1e300 (~2000 bits)", "[exact2d]") {
  std::mt19937 rng(20261207);
  for (int trial = 0; trial < 4; ++trial) {
    CAPTURE(trial);
    Shape2 s;
    const std::string err = testing::error_of([&] { s = spanning_star(rng, 8 + 5 * trial, 1e300, 1e-300); });
    INFO(err);
    REQUIRE(err == "no error");  // the validator accepts the polygon
    const MpTier t = require_mp_topology(s);
    CHECK(t.input_bits > 1900);
    CHECK(t.float_bits >= t.input_bits + 64);
  }
}
