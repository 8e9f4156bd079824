// The independent two-sided bracket of BT (burn3/bt_bracket.h): the lower bound by the
// junction rule over cells of the singular set and the discrete baseline above. Checked
// against the closed forms (books of junction_books.h, the board and fin, books, the Y),
// shown to shrink as h refines, and compared with the exact engine on seeded synthetic
// complexes: the engine's enclosure must meet [lower, upper] everywhere (both sides).
#include <catch2/catch.hpp>

#include <random>

#include "burn3/bt_bracket.h"
#include "burn3/exact/exact_burning.h"
#include "burn3/junction_books.h"
#include "complex3/synthetic_complexes.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

constexpr double kRounding = 1e-9;

std::vector<PointSource> book_sources(const JunctionBook& b, const ComplexLocator& locator) {
  std::vector<PointSource> r;
  for (const JunctionBookSource& s : b.sources) {
    const JunctionBookPoint p{sgn(s.s) > 0 ? 'A' : 'N', s.x, s.s};
    r.push_back({locator.locate(junction_book_point(b, p)), s.t0});
  }
  return r;
}

// Probe points of a complex: every vertex, the points 1/4, 1/2, 3/4 of every edge, and the
// centroid of every triangle (exact).
std::vector<ComplexPoint> probes(const MedialComplex& mc, const ComplexLocator& locator) {
  std::vector<ComplexPoint> r;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) r.push_back(locator.locate(mc.vertex(v).exact));
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    const ExactPoint3 &a = mc.vertex(mc.edge(e).v[0]).exact, &b = mc.vertex(mc.edge(e).v[1]).exact;
    for (int k = 1; k <= 3; ++k) r.push_back(locator.locate(a + mpq_class(k, 4) * (b - a)));
  }
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
    r.push_back(locator.locate(triangle_point(mc, t, mpq_class(1, 3), mpq_class(1, 3))));
  return r;
}

}  // namespace

TEST_CASE("bt bracket: the junction books' closed forms lie inside it, and it shrinks with h", "[burn3][bracket]") {
  for (const JunctionBook& b : junction_books()) {
    const MedialComplex mc = built(junction_book_complex(b));
    const ComplexLocator locator(mc);
    const std::vector<PointSource> sources = book_sources(b, locator);
    double previous = INFINITY;
    for (double h : {0.05, 0.0125}) {
      const BtBracket bracket(mc, h, sources);
      double widest = 0;
      for (const JunctionBookPoint& p : b.checks) {
        const double cf = junction_book_burning_time(b, p);
        const Interval br = bracket.at(locator.locate(junction_book_point(b, p)));
        CAPTURE(b.name, p.page, p.x.get_d(), p.s.get_d(), h, cf, br.lo, br.hi);
        CHECK(br.lo <= cf + kRounding);
        CHECK(cf <= br.hi + kRounding);
        widest = std::max(widest, br.hi - br.lo);
        // On N the three sides' arrivals come from ignitions: the lower bound loses at most
        // one cell's length to the (k-1)-th arrival (bt_bracket.h).
        if (p.page == 'N') CHECK(br.lo >= cf - h - 1e-9);
      }
      CAPTURE(b.name, h, widest, previous);
      CHECK(widest <= previous + 1e-12);
      previous = widest;
    }
  }
}

TEST_CASE("bt bracket: board and fin, books and the Y: closed forms inside, widths O(h)", "[burn3][bracket]") {
  struct Case {
    std::string name;
    RawComplex raw;
    std::function<double(const Vec3d&)> bt;
  };
  BoardFinOptions bf;
  bf.extent = 6;
  const BookOptions y = y_junction_options(1);
  std::vector<Case> cases = {{"board and fin", board_fin(bf), [](const Vec3d& p) { return board_fin_burning_time(p); }},
                             {"y junction", y_junction(1), [y](const Vec3d& p) {
                                // the page whose half-plane passes nearest (pages at angles 2 pi j / 3)
                                int page = 0;
                                double best = INFINITY;
                                for (int j = 0; j < 3; ++j) {
                                  const double a = 2 * M_PI * j / 3, u = p[0] * std::cos(a) + p[1] * std::sin(a);
                                  const double off = std::abs(-p[0] * std::sin(a) + p[1] * std::cos(a));
                                  if (u >= -1e-9 && off < best) best = off, page = j;
                                }
                                const double u = std::hypot(p[0], p[1]);
                                return book_burning_time(y, page, u, p[2]);
                              }}};
  for (const Case& c : cases) {
    const MedialComplex mc = built(c.raw);
    const ComplexLocator locator(mc);
    double previous = INFINITY;
    for (double h : {0.25, 0.0625}) {
      const BtBracket bracket(mc, h);
      double widest = 0;
      for (const ComplexPoint& x : probes(mc, locator)) {
        const double cf = c.bt(x.approx());
        if (!(cf < 5)) continue;  // keep out of the truncations' reach (synthetic_complexes.h)
        const Interval br = bracket.at(x);
        CAPTURE(c.name, h, x.approx()[0], x.approx()[1], x.approx()[2], cf, br.lo, br.hi);
        CHECK(br.lo <= cf + kRounding);
        CHECK(cf <= br.hi + kRounding);
        widest = std::max(widest, br.hi - br.lo);
      }
      CAPTURE(c.name, h, widest, previous);
      CHECK(widest <= previous + 1e-12);
      previous = widest;
    }
  }
}

TEST_CASE("bt bracket: the exact engine lies inside it on seeded synthetic complexes", "[exact3][bracket]") {
  std::vector<std::pair<std::string, RawComplex>> cases;
  std::mt19937 rng(2026);
  for (int i = 0; i < 4; ++i) {
    BookOptions o;
    o.pages = 3 + i % 2;
    for (int j = 0; j < o.pages; ++j) o.widths.push_back(std::uniform_int_distribution<long>(1, 4)(rng));
    o.cells_per_unit = 1;
    cases.push_back({"random book " + std::to_string(i), book(o)});
  }
  cases.push_back({"box 3 2 1", box_medial_axis(3, 2, 1)});
  cases.push_back({"tetrahedron with flap", tetrahedron_with_flap()});
  cases.push_back({"double cone", pinched_double_cone()});
  for (std::uint32_t s = 0; s < 3; ++s) cases.push_back({"fan " + std::to_string(s), random_planar_fan(2011 + s)});
  for (const auto& [name, raw] : cases) {
    BorderBurn burn(raw);
    const ComplexLocator locator(burn.mc);
    const BtBracket bracket(burn.mc, 0.125);
    for (const ComplexPoint& x : probes(burn.mc, locator)) {
      const Interval e = burn.eb->burn_time(x), br = bracket.at(x);
      CAPTURE(name, x.approx()[0], x.approx()[1], x.approx()[2], e.lo, e.hi, br.lo, br.hi);
      if (e.is_infinite() || std::isinf(br.hi)) {
        CHECK(std::isinf(br.hi) == e.is_infinite());
        continue;
      }
      CHECK(br.lo <= e.hi + kRounding);
      CHECK(e.lo <= br.hi + kRounding);
    }
  }
}

TEST_CASE("bt bracket: the exact engine on the junction books, from both sides", "[exact3][bracket]") {
  // Points where the engine leaves the bracket are reported by the closed-form tests too
  // (test_burn3_junction_closed_forms.cpp); here the bracket, not the closed form, judges.
  for (const JunctionBook& b : junction_books()) {
    const MedialComplex mc = built(junction_book_complex(b));
    const ComplexLocator locator(mc);
    const std::vector<PointSource> sources = book_sources(b, locator);
    ExactBurning eb(mc);
    for (const PointSource& s : sources) eb.add_point_source(s.location, s.t0);
    eb.add_border_ignition();
    eb.run();
    const BtBracket bracket(mc, 0.05, sources);
    for (const JunctionBookPoint& p : b.checks) {
      const ComplexPoint x = locator.locate(junction_book_point(b, p));
      const Interval e = eb.burn_time(x), br = bracket.at(x);
      CAPTURE(b.name, p.page, p.x.get_d(), p.s.get_d(), e.lo, e.hi, br.lo, br.hi);
      CHECK(br.lo <= e.hi + kRounding);
      CHECK(e.lo <= br.hi + kRounding);
    }
  }
}

TEST_CASE("bt bracket: the exact engine inside it on seeded books with point sources near the spine", "[exact3][bracket]") {
  // Books of 3 or 4 pages (widths 1..4, every border igniting at 0) with one to three point
  // sources in the pages, at distances 1/2^k (k = 2..12) from the spine: fronts that reach
  // the spine in short dips under the pages' plane waves.
  std::mt19937 rng(22);
  for (int i = 0; i < 12; ++i) {
    BookOptions o;
    o.pages = 3 + i % 2;
    for (int j = 0; j < o.pages; ++j) o.widths.push_back(std::uniform_int_distribution<long>(1, 4)(rng));
    o.cells_per_unit = 1;
    const MedialComplex mc = built(book(o));
    const ComplexLocator locator(mc);
    const int height = book_height(o);
    std::vector<PointSource> sources;
    const int n = std::uniform_int_distribution<int>(1, 3)(rng);
    for (int k = 0; k < n; ++k) {
      const int page = std::uniform_int_distribution<int>(0, o.pages - 1)(rng);
      const auto dir = rational_unit_direction(2 * M_PI * page / o.pages);
      const mpq_class u(1, 1L << std::uniform_int_distribution<int>(2, 12)(rng));
      const mpq_class z(std::uniform_int_distribution<int>(8, 8 * height - 8)(rng), 8);
      const mpq_class t0(std::uniform_int_distribution<int>(0, 8 * height)(rng), 16);
      const ComplexPoint x = locator.locate({u * dir[0], u * dir[1], z});
      REQUIRE(x.snap_squared == 0);
      sources.push_back({x, t0});
    }
    ExactBurning eb(mc);
    for (const PointSource& s : sources) eb.add_point_source(s.location, s.t0);
    eb.add_border_ignition();
    eb.run();
    const BtBracket bracket(mc, 0.125, sources);
    for (const ComplexPoint& x : probes(mc, locator)) {
      const Interval e = eb.burn_time(x), br = bracket.at(x);
      CAPTURE(i, x.approx()[0], x.approx()[1], x.approx()[2], e.lo, e.hi, br.lo, br.hi);
      CHECK(br.lo <= e.hi + kRounding);
      CHECK(e.lo <= br.hi + kRounding);
    }
  }
}
