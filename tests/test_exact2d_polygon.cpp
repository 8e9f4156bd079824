// The exact polygon medial axis (medial2/polygon/polygon_axis.h): hand-built shapes with exact
// expected values, the definition-level validation, Boost vs CGAL, engine vs oracle.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "burn2/edf_definition.h"
#include "burn2/extended_grassfire.h"
#include "medial2/polygon/polygon_axis.h"
#include "medial2/polygon/polygon_axis_geometry.h"
#include "medial2/polygon/polygon_axis_validate.h"
#include "number/sqrt_field.h"
#include "io/load_shape.h"
#include "shapes/validate_shape.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

Shape2 polygon(std::vector<std::vector<Point2>> rings, const std::string& name = "test") {
  Shape2 s;
  s.name = name;
  for (auto& r : rings) s.rings.push_back({std::move(r)});
  validate_shape(s, name);
  return s;
}

// The node nearest to (x, y), which must be within 1e-9 (relative for |x| + |y| > 1).
std::uint32_t node_at(const MedialGraph& g, double x, double y) {
  std::uint32_t best = 0;
  double bd = 1e300;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const double d = std::hypot(g.node(v).position.x - x, g.node(v).position.y - y);
    if (d < bd) bd = d, best = v;
  }
  REQUIRE(bd < 1e-9 * std::max(1.0, std::fabs(x) + std::fabs(y)));  // relative beyond 1: double positions
  return best;
}

bool equals(const ExactSum& a, const ExactSum& b) {
  ExactSum d = a - b;
  d.simplify();
  return d.constant_terms().empty() && is_zero_sqrt_part(d);
}

ExactSum root(long n) { return ExactSum::sqrt_of(n); }
ExactSum rat(long n, long d = 1) { return ExactSum::rational(make_rational(n, d)); }

// The Boost and CGAL constructions node by node: a bijection of the nodes by their
// defining sites (every site of a node's contracted group: a combinatorial key common to
// both constructions, which also tells apart distinct nodes closer than double precision),
// the nearest unused one by position among equal keys, at the same position (relative
// 1e-9); R equal exactly, or, when the two ran on polygons that differ by the
// nearest-double rounding of their decimals (< 1.2e-16 for coordinates in [-1, 1]), within
// 1e-12 (relative beyond 1) plus the enclosures, which a different node would exceed by
// far; and the same edge set, with the same edge kinds. Returns the bijection.
std::vector<std::uint32_t> require_same_axis(const MedialGraph& a, const MedialGraph& b, bool exact_radii) {
  REQUIRE(a.node_count() == b.node_count());
  REQUIRE(a.edge_count() == b.edge_count());
  const auto& ga = dynamic_cast<const PolygonAxisGeometry&>(a.geometry());
  const auto& gb = dynamic_cast<const PolygonAxisGeometry&>(b.geometry());
  std::map<std::vector<std::uint32_t>, std::vector<std::uint32_t>> by_sites;
  for (std::uint32_t w = 0; w < b.node_count(); ++w) by_sites[gb.node_data(w).sites].push_back(w);
  std::vector<std::uint32_t> to_b(a.node_count());
  std::vector<bool> used(b.node_count(), false);
  for (std::uint32_t v = 0; v < a.node_count(); ++v) {
    const Point2 p = a.node(v).position;
    CAPTURE(v, p.x, p.y);
    const auto it = by_sites.find(ga.node_data(v).sites);
    REQUIRE(it != by_sites.end());
    std::uint32_t w = 0;
    double best = 1e300;
    for (std::uint32_t c : it->second) {
      const double d = std::hypot(b.node(c).position.x - p.x, b.node(c).position.y - p.y);
      if (!used[c] && d < best) best = d, w = c;
    }
    REQUIRE(best < 1e-9 * std::max(1.0, std::fabs(p.x) + std::fabs(p.y)));
    used[w] = true;
    to_b[v] = w;
    if (exact_radii)
      CHECK(compare(a.geometry().exact_radius(v), b.geometry().exact_radius(w)) == 0);
    else
      CHECK(std::fabs(a.node(v).radius.mid() - b.node(w).radius.mid()) <=
            1e-12 * std::max(1.0, std::fabs(a.node(v).radius.mid())) + a.node(v).radius.radius() +
                b.node(w).radius.radius());
  }
  std::multiset<std::tuple<std::uint32_t, std::uint32_t, EdgeKind>> ea, eb;
  for (const MedialEdge& e : a.edges())
    ea.insert({std::min(to_b[e.u], to_b[e.v]), std::max(to_b[e.u], to_b[e.v]), e.kind});
  for (const MedialEdge& e : b.edges()) eb.insert({std::min(e.u, e.v), std::max(e.u, e.v), e.kind});
  CHECK(ea == eb);
  return to_b;
}

// Radii without certified constants (rationals and sums of square roots, whose identity
// does not depend on the frame) of matched nodes (to_b: require_same_axis) are equal
// exactly: CHECKs that, returns how many nodes it compared.
int equal_exact_radii(const MedialGraph& a, const MedialGraph& b, const std::vector<std::uint32_t>& to_b) {
  int exact = 0;
  for (std::uint32_t v = 0; v < a.node_count(); ++v) {
    const ExactSum ra = a.geometry().exact_radius(v), rb = b.geometry().exact_radius(to_b[v]);
    if (!ra.constant_terms().empty() || !rb.constant_terms().empty()) continue;
    CHECK(equals(ra, rb));
    ++exact;
  }
  return exact;
}

void require_valid_and_burns_like_oracle(const MedialGraph& g) {
  g.validate();
  const AxisValidation v = validate_polygon_axis(g);
  INFO((v.failures.empty() ? std::string() : v.failures.front()));
  REQUIRE(v.ok());
  const GrassfireResult r = extended_grassfire(g);
  require_equal_to_definition(g, r, edf_by_definition(g));
}

std::size_t leaves(const MedialGraph& g) {
  std::size_t n = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) n += g.is_leaf(v);
  return n;
}

}  // namespace

TEST_CASE("decimal policy: shortest decimal of a double, up to 9 digits", "[exact2d]") {
  long long m = 0;
  CHECK(decimal_digits(0.34174, 9, &m) == 5);
  CHECK(m == 34174);
  CHECK(decimal_digits(3.0, 9, &m) == 0);
  CHECK(decimal_digits(0.1 + 0.2, 9, &m) == -1);  // 0.30000000000000004 is no short decimal
  CHECK(decimal_digits(-1.5, 9, &m) == 1);
  CHECK(m == -15);
  CHECK(decimal_digits(1.0 / 3.0, 9, &m) == -1);
}

TEST_CASE("rectangle 4 x 2: four R = 0 leaves, two junctions R = 1, EMA at the centre", "[exact2d]") {
  const Shape2 s = polygon({{{0, 0}, {4, 0}, {4, 2}, {0, 2}}});
  PolygonAxisReport rep;
  const MedialGraph g = exact_polygon_axis(s, {}, &rep);
  CHECK(rep.construction == AxisConstruction::BoostPolygon);
  REQUIRE(g.node_count() == 6);
  REQUIRE(g.edge_count() == 5);
  CHECK(leaves(g) == 4);
  const std::uint32_t a = node_at(g, 1, 1), b = node_at(g, 3, 1);
  CHECK(equals(g.geometry().exact_radius(a), rat(1)));
  CHECK(equals(g.geometry().exact_radius(node_at(g, 0, 0)), rat(0)));
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const bool middle = (g.edge(e).u == a && g.edge(e).v == b) || (g.edge(e).u == b && g.edge(e).v == a);
    CHECK(equals(g.geometry().exact_length(e), middle ? rat(2) : root(2)));
    CHECK(g.edge(e).kind == EdgeKind::Segment);
  }
  const GrassfireResult r = extended_grassfire(g);
  const ExtendedMedialAxis& ema = r.ema.at(0);
  REQUIRE_FALSE(ema.point.at_node);
  CHECK(equals(ema_offset_sum(r, ema).exact(g), rat(1)));
  CHECK(equals(ema_edf_sum(r, ema).exact(g), rat(1) + root(2)));  // (sqrt2 + sqrt2 + 2) / 2
  require_valid_and_burns_like_oracle(g);
}

TEST_CASE("square: the two Voronoi vertices at the centre are contracted exactly", "[exact2d]") {
  const Shape2 s = polygon({{{0, 0}, {2, 0}, {2, 2}, {0, 2}}});
  PolygonAxisReport rep;
  const MedialGraph g = exact_polygon_axis(s, {}, &rep);
  CHECK(rep.contracted_edges == 1);
  CHECK(rep.uncertified_contractions == 0);
  REQUIRE(g.node_count() == 5);
  REQUIRE(g.edge_count() == 4);
  const std::uint32_t c = node_at(g, 1, 1);
  CHECK(g.degree(c) == 4);
  CHECK(equals(g.geometry().exact_radius(c), rat(1)));
  const GrassfireResult r = extended_grassfire(g);
  REQUIRE(r.ema.at(0).point.at_node);
  CHECK(r.ema[0].point.node == c);
  require_valid_and_burns_like_oracle(g);
}

TEST_CASE("collinear vertex: a degree-2 node where its normal meets the axis", "[exact2d]") {
  const Shape2 s = polygon({{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {0, 2}}});
  const MedialGraph g = exact_polygon_axis(s);
  REQUIRE(g.node_count() == 7);
  REQUIRE(g.edge_count() == 6);
  CHECK(leaves(g) == 4);
  CHECK(g.degree(node_at(g, 2, 1)) == 2);
  CHECK(equals(g.geometry().exact_radius(node_at(g, 2, 1)), rat(1)));
  require_valid_and_burns_like_oracle(g);
}

TEST_CASE("L-shape: the reflex vertex gives two parabolic arcs meeting at R = 4 - 2 sqrt 2", "[exact2d]") {
  const Shape2 s = polygon({{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}});
  PolygonAxisReport rep;
  const MedialGraph g = exact_polygon_axis(s, {}, &rep);
  REQUIRE(g.node_count() == 10);
  REQUIRE(g.edge_count() == 9);
  CHECK(leaves(g) == 5);
  CHECK(rep.parabolic_arcs == 2);
  const double j = 4 - 2 * std::sqrt(2.0);
  const std::uint32_t junction = node_at(g, j, j);
  CHECK(g.degree(junction) == 3);
  CHECK(equals(g.geometry().exact_radius(junction), rat(4) - root(8)));
  CHECK(equals(g.geometry().exact_radius(node_at(g, 2, 1)), rat(1)));
  // The arc from (2, 1) to the junction: focus (2, 2), directrix y = 0, p = 2, xi from 0
  // to 2 - 2 sqrt 2: length S(2 sqrt 2 - 2) with S(x) = x/2 sqrt(1 + x^2/4) + asinh(x/2).
  const double x = 2 * std::sqrt(2.0) - 2;
  const double expected = 0.5 * x * std::sqrt(1 + x * x / 4) + std::asinh(x / 2);
  int arcs = 0;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    if (g.edge(e).kind != EdgeKind::ParabolicArc) continue;
    ++arcs;
    const Interval len = g.edge(e).length;
    CHECK(len.hi - len.lo <= std::ldexp(len.hi, -40));  // kTightBits
    CHECK(std::fabs(len.mid() - expected) < 1e-13);
    const Interval hi_prec = g.geometry().exact_length(e).approx();
    CHECK(hi_prec.lo <= len.hi);
    CHECK(len.lo <= hi_prec.hi);
  }
  CHECK(arcs == 2);
  require_valid_and_burns_like_oracle(g);
}

TEST_CASE("square with a square hole: a loop of 16 nodes, EMA = the cycle", "[exact2d]") {
  const Shape2 s = polygon({{{0, 0}, {6, 0}, {6, 6}, {0, 6}}, {{2, 2}, {2, 4}, {4, 4}, {4, 2}}});
  PolygonAxisReport rep;
  const MedialGraph g = exact_polygon_axis(s, {}, &rep);
  REQUIRE(g.node_count() == 16);
  REQUIRE(g.edge_count() == 16);
  CHECK(leaves(g) == 4);
  CHECK(rep.parabolic_arcs == 8);
  CHECK(g.cycle_rank() == 1);
  const GrassfireResult r = extended_grassfire(g);
  CHECK(r.ema.at(0).kind == ExtendedMedialAxis::Kind::Cycles);
  require_valid_and_burns_like_oracle(g);
}

TEST_CASE("near-regular hexagon and octagon (5 decimals): valid, Boost equals CGAL", "[exact2d]") {
  for (int n : {6, 8, 12}) {
    std::vector<Point2> ring;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * k / n;
      ring.push_back({std::round(std::cos(t) * 1e5) / 1e5, std::round(std::sin(t) * 1e5) / 1e5});
    }
    const Shape2 s = polygon({ring});
    PolygonAxisOptions boost_opt, cgal_opt;
    boost_opt.construction = AxisConstruction::BoostPolygon;
    cgal_opt.construction = AxisConstruction::CgalSdg;
    const MedialGraph gb = exact_polygon_axis(s, boost_opt), gc = exact_polygon_axis(s, cgal_opt);
    INFO("n = " << n);
    CHECK(leaves(gb) == static_cast<std::size_t>(n));
    require_same_axis(gb, gc, false);
    require_valid_and_burns_like_oracle(gb);
    require_valid_and_burns_like_oracle(gc);
  }
}

TEST_CASE("seeded random star polygons with 4 decimals: Boost and CGAL agree, valid, engine = oracle", "[exact2d]") {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> radius(0.3, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 5 + trial * 3;
    std::vector<Point2> ring;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * k / n, r = radius(rng);
      ring.push_back({std::round(r * std::cos(t) * 1e4) / 1e4, std::round(r * std::sin(t) * 1e4) / 1e4});
    }
    const Shape2 s = polygon({ring});
    PolygonAxisOptions cgal_opt;
    cgal_opt.construction = AxisConstruction::CgalSdg;
    PolygonAxisReport rb, rc;
    const MedialGraph gb = exact_polygon_axis(s, {}, &rb), gc = exact_polygon_axis(s, cgal_opt, &rc);
    INFO("trial " << trial);
    // The CGAL frame is the input doubles, Boost's the decimals: the same polygon up to the
    // nearest-double rounding of 4-decimal inputs.
    require_same_axis(gb, gc, false);
    require_valid_and_burns_like_oracle(gb);
    require_valid_and_burns_like_oracle(gc);
  }
}

TEST_CASE("an integer polygon gives the identical axis under Boost and CGAL: nodes, exact R, edges", "[exact2d]") {
  const Shape2 s = polygon({{{0, 0}, {7, 0}, {7, 3}, {4, 3}, {5, 6}, {1, 5}, {2, 2}, {0, 2}}});
  PolygonAxisOptions cgal_opt;
  cgal_opt.construction = AxisConstruction::CgalSdg;
  const MedialGraph gb = exact_polygon_axis(s), gc = exact_polygon_axis(s, cgal_opt);
  require_same_axis(gb, gc, true);
  require_valid_and_burns_like_oracle(gb);
}

TEST_CASE("every shape of data/shapes2d: exact axis valid by definition, engine = oracle", "[exact2d]") {
  int shapes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(GF_PROJECT_DATA "/shapes2d")) {
    if (entry.path().extension() != ".json") continue;
    const Shape2 s = load_shape(entry.path().string());
    PolygonAxisReport rep;
    const MedialGraph g = exact_polygon_axis(s, {}, &rep);
    INFO(entry.path().filename().string());
    CHECK(rep.construction == AxisConstruction::BoostPolygon);
    CHECK(g.component_count() == 1);
    CHECK(g.cycle_rank() == s.rings.size() - 1);
    require_valid_and_burns_like_oracle(g);
    ++shapes;
  }
  CHECK(shapes >= 100);
}

TEST_CASE("a strip with teeth off the decimal grid (wide Boost and CGAL): a finite EMA equal to the decimal one", "[exact2d]") {
  // Fig. 5.3's strip (length 4, half thickness 0.01, 20 teeth of height 0.1 on its left
  // half), once with coordinates computed as j * 0.1 / 2 and 0.1 - 0.01 in doubles (not the
  // doubles nearest to decimals: CGAL's segment Delaunay graph), once in thousandths (the
  // decimal grid: Boost.Polygon). The EMA inside an edge had an offset of [-inf, inf] on
  // the CGAL path (a NaN position); all must now give the same finite point. The doubles
  // run twice: by the input policy (the wide binary frame, 61 bits) and forced on CGAL.
  auto strip = [](bool decimal) {
    std::vector<Point2> ring;
    auto x = [&](int j) { return decimal ? j * 50 / 1000.0 : j * 0.1 / 2; };
    auto y = [&](int j, int side) { return decimal ? ((j % 2) * 100 + side * 10) / 1000.0 : (j % 2) * 0.1 + side * 0.01; };
    for (int j = 0; j <= 40; ++j) ring.push_back({x(j), y(j, -1)});
    ring.push_back({4, -0.01});
    ring.push_back({4, 0.01});
    for (int j = 40; j >= 0; --j) ring.push_back({x(j), y(j, 1)});
    return polygon({ring}, decimal ? "teeth (decimal)" : "teeth (doubles)");
  };
  Point2 ema[3];
  for (int run = 0; run < 3; ++run) {
    const bool decimal = run == 1;
    PolygonAxisOptions opt;
    if (run == 2) opt.construction = AxisConstruction::CgalSdg;
    PolygonAxisReport rep;
    const MedialGraph g = exact_polygon_axis(strip(decimal), opt, &rep);
    const AxisConstruction expected[3] = {AxisConstruction::BoostPolygonWide, AxisConstruction::BoostPolygon,
                                          AxisConstruction::CgalSdg};
    CHECK(rep.construction == expected[run]);
    const GrassfireResult r = extended_grassfire(g);
    REQUIRE(r.ema.size() == 1);
    const GraphPoint& p = r.ema[0].point;
    if (!p.at_node) {
      INFO("offset [" << p.offset.lo << ", " << p.offset.hi << "]");
      CHECK(p.offset.hi - p.offset.lo < 1e-9);
    }
    ema[run] = position_of(g, p);
    REQUIRE(std::isfinite(ema[run].x));
    REQUIRE(std::isfinite(ema[run].y));
  }
  CHECK(std::hypot(ema[0].x - ema[1].x, ema[0].y - ema[1].y) < 1e-9);
  CHECK(std::hypot(ema[0].x - ema[2].x, ema[0].y - ema[2].y) < 1e-12);
  CHECK(ema[0].x > 1.4);  // the teeth pull the EMA left of the strip's centre (x = 2)
  CHECK(ema[0].x < 1.6);
}

TEST_CASE("binary policy: exponent of the lowest set bit", "[exact2d]") {
  CHECK(lowest_bit_exponent(1.0) == 0);
  CHECK(lowest_bit_exponent(6.0) == 1);
  CHECK(lowest_bit_exponent(-0.375) == -3);
  CHECK(lowest_bit_exponent(std::ldexp(12345.0, -40)) == -40);
  CHECK(lowest_bit_exponent(1.0 / 3.0) == -54);  // 6004799503160661 x 2^-54, an odd mantissa
  CHECK(lowest_bit_exponent(std::ldexp(1.0, 60)) == 60);
}

TEST_CASE("seeded random star polygons on a binary grid: Boost on exact integers equals CGAL", "[exact2d]") {
  // Coordinates m / 2^20 (not short decimals: 1/2^20 needs 20 decimal digits): the binary
  // policy scales them exactly to integers and Boost runs; CGAL's SDG runs on the same
  // doubles. The two constructions see one exact polygon, so the radii agree exactly.
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> radius(0.3, 1.0);
  int nested = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const int n = 5 + trial * 4;
    std::vector<Point2> ring;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * k / n, r = radius(rng);
      ring.push_back({std::ldexp(std::round(std::ldexp(r * std::cos(t), 20)), -20),
                      std::ldexp(std::round(std::ldexp(r * std::sin(t), 20)), -20)});
    }
    const Shape2 s = polygon({ring});
    PolygonAxisOptions cgal_opt;
    cgal_opt.construction = AxisConstruction::CgalSdg;
    PolygonAxisReport rb, rc;
    const MedialGraph gb = exact_polygon_axis(s, {}, &rb), gc = exact_polygon_axis(s, cgal_opt, &rc);
    INFO("trial " << trial);
    CHECK(rb.construction == AxisConstruction::BoostPolygon);
    CHECK(rb.decimal_digits == -1);
    CHECK(rb.binary_digits <= 20);
    CHECK(rb.binary_digits >= 17);
    CHECK(rc.construction == AxisConstruction::CgalSdg);
    require_same_axis(gb, gc, false);
    // Every radius is equal exactly across the two frames (2^K apart), nested-radical PSS
    // circles included: their constants are square roots of sums (solve_radical), decided
    // by identity or by the root-separation bound, never by an identity of site indices
    // (which named a different value in each frame and once gave sign -1 here).
    for (std::uint32_t v = 0; v < gb.node_count(); ++v) {
      const Point2 p = gb.node(v).position;
      const ExactSum a = gb.geometry().exact_radius(v), b = gc.geometry().exact_radius(node_at(gc, p.x, p.y));
      NumberStats st;
      CHECK(compare(a, b, &st) == 0);
      CHECK(st.uncertified_zero == 0);
      nested += !a.constant_terms().empty();
      // Names built from site indices differ between the two axes (the fallback constants
      // of one frame must never merge with the other's by name).
      CHECK(dynamic_cast<const PolygonAxisGeometry&>(gb.geometry()).node_identity(v) !=
            dynamic_cast<const PolygonAxisGeometry&>(gc.geometry()).node_identity(node_at(gc, p.x, p.y)));
    }
    require_valid_and_burns_like_oracle(gb);
  }
  CHECK(nested >= 10);  // radii with square roots of sums were compared
}

TEST_CASE("seeded star polygons with full-mantissa doubles: wide Boost axis equals CGAL's", "[exact2d]") {
  // Coordinates 3 + r cos t as computed (53 significant bits, no decimal or int32 binary
  // frame; 2^K x them spans under 62 bits): the wide binary policy runs Boost's builder on
  // 64-bit integers; CGAL's SDG runs on the same doubles.
  std::mt19937 rng(20261204);
  std::uniform_real_distribution<double> radius(0.3, 1.0);
  for (int trial = 0; trial < 8; ++trial) {
    const int n = 5 + trial * 4;
    std::vector<Point2> ring;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * k / n, r = radius(rng);
      ring.push_back({3 + r * std::cos(t), 3 + r * std::sin(t)});
    }
    const Shape2 s = polygon({ring});
    PolygonAxisOptions cgal_opt;
    cgal_opt.construction = AxisConstruction::CgalSdg;
    PolygonAxisReport rb, rc;
    const MedialGraph gb = exact_polygon_axis(s, {}, &rb), gc = exact_polygon_axis(s, cgal_opt, &rc);
    INFO("trial " << trial);
    CHECK(rb.construction == AxisConstruction::BoostPolygonWide);
    CHECK(rc.construction == AxisConstruction::CgalSdg);
    CHECK(equal_exact_radii(gb, gc, require_same_axis(gb, gc, false)) >= n);
    require_valid_and_burns_like_oracle(gb);
  }
}

TEST_CASE("seeded star polygons spanning ~107 and ~400 bits: mp Boost axis equals CGAL's, engine = oracle", "[exact2d]") {
  // Vertices r (cos t, sin t) about the origin as computed, one at t = pi/2 (x ~ 6e-17 r,
  // full mantissa): ~107 bits once scaled to integers; in odd trials one vertex at t = pi
  // gets y ~ 1e-110 r: ~420 bits. The mp binary policy runs Boost's builder on those
  // integers (filter stage, or MPFR); CGAL's SDG runs on the same doubles.
  std::mt19937 rng(20261208);
  std::uniform_real_distribution<double> radius(0.3, 1.0), factor(1, 2);
  for (int trial = 0; trial < 8; ++trial) {
    const int n = 8 + trial * 4;
    std::vector<Point2> ring;
    for (int k = 0; k < n; ++k) {
      const double t = M_PI / 2 + 2 * M_PI * k / n, r = radius(rng);
      ring.push_back({r * std::cos(t), r * std::sin(t)});
    }
    if (trial % 2) ring[n / 4].y = 1e-110 * factor(rng);
    const Shape2 s = polygon({ring});
    PolygonAxisOptions cgal_opt;
    cgal_opt.construction = AxisConstruction::CgalSdg;
    PolygonAxisReport rb, rc;
    const MedialGraph gb = exact_polygon_axis(s, {}, &rb), gc = exact_polygon_axis(s, cgal_opt, &rc);
    INFO("trial " << trial << ": " << rb.mp_input_bits << "-bit integers");
    CHECK(rb.construction == AxisConstruction::BoostPolygonMp);
    CHECK(rc.construction == AxisConstruction::CgalSdg);
    CHECK(rb.mp_input_bits > (trial % 2 ? 400 : 100));
    CHECK(rb.uncertified_contractions == 0);
    CHECK(equal_exact_radii(gb, gc, require_same_axis(gb, gc, true)) >= n);
    require_valid_and_burns_like_oracle(gb);
  }
}

TEST_CASE("a dense near-symmetric wavy curve with full-mantissa doubles: wide Boost axis equals CGAL's", "[exact2d]") {
  // 1500 samples of r = 10^6 (1 + 0.1 sin 7t) about (3 10^6, -2.5 10^6), as computed: the
  // mirror symmetry survives rounding at some sites, which are then exactly cocircular
  // (degree-4 Voronoi vertices, split by each construction along its own diagonal and
  // contracted by the exact test); the axes must agree.
  std::vector<Point2> ring;
  for (int k = 0; k < 1500; ++k) {
    const double t = 2 * M_PI * k / 1500, r = 1e6 * (1 + 0.1 * std::sin(7 * t));
    ring.push_back({3e6 + r * std::cos(t), -2.5e6 + r * std::sin(t)});
  }
  const Shape2 s = polygon({ring});
  PolygonAxisOptions cgal_opt;
  cgal_opt.construction = AxisConstruction::CgalSdg;
  PolygonAxisReport rb, rc;
  const MedialGraph gb = exact_polygon_axis(s, {}, &rb), gc = exact_polygon_axis(s, cgal_opt, &rc);
  CHECK(rb.construction == AxisConstruction::BoostPolygonWide);
  CHECK(rb.contracted_edges > 0);
  CHECK(rb.uncertified_contractions == 0);
  CHECK(equal_exact_radii(gb, gc, require_same_axis(gb, gc, false)) >= 1500);
}

TEST_CASE("rotated polygons with full-mantissa coordinates (wide Boost or CGAL) = the decimal axis rotated", "[exact2d]") {
  // A rigid motion by an angle whose sine and cosine have full 53-bit mantissas: no decimal
  // or int32 binary frame exists. Every node of the decimal
  // polygon's axis, rotated, is a node of the rotated polygon's axis with the same radius
  // (to the rounding of the rotated coordinates, ~1e-16), and the edge kinds agree.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(0.3, 1.0);
  const double angle = 0.7390851332151607, c = std::cos(angle), sn = std::sin(angle);
  for (int trial = 0; trial < 6; ++trial) {
    const int n = 6 + trial * 5;
    std::vector<Point2> ring, rotated;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * k / n, r = radius(rng);
      const Point2 p{std::round(r * std::cos(t) * 1e4) / 1e4, std::round(r * std::sin(t) * 1e4) / 1e4};
      ring.push_back(p);
      rotated.push_back({c * p.x - sn * p.y, sn * p.x + c * p.y});
    }
    const Shape2 s = polygon({ring}), sr = polygon({rotated});
    PolygonAxisReport rep;
    const MedialGraph g = exact_polygon_axis(s), gr = exact_polygon_axis(sr, {}, &rep);
    INFO("trial " << trial);
    // The wide binary frame when the rotated coordinates span at most 62 bits, else CGAL.
    CHECK(rep.construction != AxisConstruction::BoostPolygon);
    REQUIRE(g.node_count() == gr.node_count());
    REQUIRE(g.edge_count() == gr.edge_count());
    std::vector<std::uint32_t> to_r(g.node_count());
    for (std::uint32_t v = 0; v < g.node_count(); ++v) {
      const Point2 p = g.node(v).position;
      to_r[v] = node_at(gr, c * p.x - sn * p.y, sn * p.x + c * p.y);
      CHECK(std::fabs(g.node(v).radius.mid() - gr.node(to_r[v]).radius.mid()) < 1e-12);
    }
    std::multiset<std::tuple<std::uint32_t, std::uint32_t, EdgeKind>> ea, eb;
    for (const MedialEdge& e : g.edges()) ea.insert({std::min(to_r[e.u], to_r[e.v]), std::max(to_r[e.u], to_r[e.v]), e.kind});
    for (const MedialEdge& e : gr.edges()) eb.insert({std::min(e.u, e.v), std::max(e.u, e.v), e.kind});
    CHECK(ea == eb);
    require_valid_and_burns_like_oracle(gr);
  }
}
