// Definition-level references for BT: the planar-sheet visibility-graph reference against
// the convex brute force, hand-computed values, rigid motions, and the discrete baseline.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "burn3/burn3_reference.h"
#include "burn3/discrete/discrete_burning.h"
#include "burn3/discrete/discrete_query.h"
#include "burn3/planar_sheet_reference.h"
#include "complex3/point_location.h"
#include "complex3/synthetic_complexes.h"
#include "number/exact_sum.h"
#include "test_complex3_support.h"
#include "test_sheets_support.h"

using namespace grassfire;
using testing::built;

namespace {

mpq_class q(long n, long d = 1) { return make_rational(n, d); }

// Contains the value, and certifies it to better than 1e-14.
void require_certified(const Interval& bt, double expected) {
  CAPTURE(bt.lo, bt.hi, expected);
  CHECK(bt.lo <= expected + 1e-15);
  CHECK(bt.hi >= expected - 1e-15);
  CHECK(bt.hi - bt.lo < 1e-14);
}

// The L [0,3]x[0,1] u [0,1]x[0,3] that burns from its far edge x = 3 only.
testing::GridSheet l_sheet(int g) {
  testing::GridSheet s{{"###", "#..", "#.."}, g};
  s.rule = [](const ExactPoint3& a, const ExactPoint3& b) {
    return BorderIgnition{{0, 0}, a.x == 3 && b.x == 3 ? IgnitionRule::Linear : IgnitionRule::Never, {}};
  };
  return s;
}

Interval bt_at(const PlanarSheetReference& ref, const ComplexLocator& locator, const mpq_class& x, const mpq_class& y) {
  const ComplexPoint p = locator.locate({x, y, 0});
  REQUIRE(sgn(p.snap_squared) == 0);
  return ref.burning_time(p);
}

}  // namespace

TEST_CASE("planar sheet reference: an L burns around its reflex corner (hand-computed)", "[burn3][reference]") {
  const MedialComplex mc = built(testing::grid_sheet(l_sheet(2)));
  const PlanarSheetReference ref(mc);
  const ComplexLocator locator(mc);
  REQUIRE(ref.nodes().size() == 1);
  CHECK(mc.vertex(ref.nodes()[0]).exact == ExactPoint3{1, 1, 0});
  require_certified(bt_at(ref, locator, q(1, 2), q(5, 2)), 2 + std::sqrt(10.0) / 2);  // around (1, 1)
  require_certified(bt_at(ref, locator, 0, 3), 2 + std::sqrt(5.0));
  require_certified(bt_at(ref, locator, 1, 1), 2);
  require_certified(bt_at(ref, locator, 2, q(1, 2)), 1);
  require_certified(bt_at(ref, locator, q(1, 2), q(1, 2)), q(5, 2).get_d());
  require_certified(bt_at(ref, locator, q(7, 10), q(3, 2)), 2 + std::hypot(0.3, 0.5));
  // Visibility: blocked by the missing square, grazing the reflex corner, along the border.
  auto at = [&](long x2, long y2) { return locator.locate({q(x2, 2), q(y2, 2), 0}); };
  CHECK_FALSE(ref.visible(at(1, 5), at(5, 1)));
  CHECK(ref.visible(at(1, 3), at(3, 1)));  // through (1, 1) exactly
  CHECK_FALSE(ref.visible(at(1, 4), at(4, 1)));
  CHECK(ref.visible(at(0, 6), at(0, 0)));  // along the border x = 0
  CHECK(ref.visible(at(2, 6), at(2, 2)));  // along the border x = 1 to the reflex corner
  CHECK(ref.visible(at(6, 0), at(6, 2)));
}

TEST_CASE("planar sheet reference: a square with a square hole (hand-computed)", "[burn3][reference]") {
  testing::GridSheet s{{"###", "#.#", "###"}, 1};
  s.rule = [](const ExactPoint3& a, const ExactPoint3& b) {
    const bool near = sgn(a.y) == 0 && sgn(b.y) == 0 && a.x <= 1 && b.x <= 1;
    return BorderIgnition{{0, 0}, near ? IgnitionRule::Linear : IgnitionRule::Never, {}};
  };
  const MedialComplex mc = built(testing::grid_sheet(s));
  const PlanarSheetReference ref(mc);
  const ComplexLocator locator(mc);
  CHECK(ref.nodes().size() == 4);  // the hole's corners
  require_certified(bt_at(ref, locator, q(5, 2), q(5, 2)), std::sqrt(2.0) + std::sqrt(10.0) / 2);  // around (2, 1)
  require_certified(bt_at(ref, locator, q(1, 2), q(5, 2)), 2.5);                                  // straight up
  require_certified(bt_at(ref, locator, q(3, 2), q(5, 2)), 2 + std::sqrt(0.5));                  // around (1, 2)
  require_certified(bt_at(ref, locator, 3, 0), 2);
}

TEST_CASE("planar sheet reference: rigid motions and scaling change BT as they should", "[burn3][reference]") {
  testing::GridSheet s = l_sheet(2);
  const MedialComplex flat = built(testing::grid_sheet(s));
  // (x, y) -> (3x/5, 4x/5, y) + (1, 2, 3): a rational isometry into another plane.
  s.place = [](const mpq_class& x, const mpq_class& y) { return ExactPoint3{q(3, 5) * x + 1, q(4, 5) * x + 2, y + 3}; };
  s.rule = [](const ExactPoint3& a, const ExactPoint3& b) {
    return BorderIgnition{{0, 0}, a.x == q(14, 5) && b.x == q(14, 5) ? IgnitionRule::Linear : IgnitionRule::Never, {}};
  };
  const MedialComplex moved = built(testing::grid_sheet(s));
  s.place = [](const mpq_class& x, const mpq_class& y) { return ExactPoint3{2 * x, 2 * y, 0}; };
  s.rule = [](const ExactPoint3& a, const ExactPoint3& b) {
    return BorderIgnition{{0, 0}, a.x == 6 && b.x == 6 ? IgnitionRule::Linear : IgnitionRule::Never, {}};
  };
  const MedialComplex scaled = built(testing::grid_sheet(s));
  const PlanarSheetReference a(flat), b(moved), c(scaled);
  const ComplexLocator la(flat), lb(moved), lc(scaled);
  std::mt19937 rng(3);
  std::uniform_int_distribution<long> u(0, 60), v(0, 20);
  for (int i = 0; i < 12; ++i) {
    mpq_class x = q(u(rng), 20), y = q(v(rng), 20);
    if (i % 2) std::swap(x, y);
    const Interval ba = a.burning_time(la.locate({x, y, 0}));
    const Interval bb = b.burning_time(lb.locate({q(3, 5) * x + 1, q(4, 5) * x + 2, y + 3}));
    const Interval bc = c.burning_time(lc.locate({2 * x, 2 * y, 0}));
    CAPTURE(x.get_d(), y.get_d(), ba.lo, bb.lo, bc.lo);
    CHECK(std::abs(ba.mid() - bb.mid()) < 1e-14);
    CHECK(std::abs(2 * ba.mid() - bc.mid()) < 1e-13);
  }
}

TEST_CASE("planar sheet reference: equals the convex brute force on random convex sheets", "[burn3][reference]") {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> coin(0, 9), r2(0, 16), tick(-20, 20);
  int compared = 0;
  for (int sheet = 0; sheet < 6; ++sheet) {
    RawComplex raw;
    raw.source = "convex sheet " + std::to_string(sheet);
    const int k = 5 + sheet;
    for (int i = 0; i < k; ++i) {  // rational points of a circle of radius 3, in the plane z = x/2 + y/3
      const auto d = rational_unit_direction(2 * M_PI * i / k + 0.1 * sheet);
      const mpq_class x = 3 * d[0], y = 3 * d[1];
      raw.vertices.push_back({x, y, x / 2 + y / 3});
      raw.radius_squared.push_back(q(r2(rng), 16));
    }
    for (int i = 1; i + 1 < k; ++i)
      raw.triangles.push_back({0, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)});
    for (int i = 0; i < k; ++i) {
      const int c = coin(rng);
      if (c < 6) continue;  // Linear
      BorderIgnition b{{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>((i + 1) % k)},
                       c < 8 ? IgnitionRule::DistanceToPoint : IgnitionRule::Never,
                       {q(tick(rng), 10), q(tick(rng), 10), q(tick(rng), 10)}};
      raw.border_rules.push_back(b);
    }
    const MedialComplex mc = built(raw);
    const PlanarSheetReference ref(mc);
    CHECK(ref.nodes().empty());
    for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
      for (int j = 0; j < 4; ++j) {
        std::array<mpq_class, 3> w = {q(1 + coin(rng), 1), q(1 + coin(rng), 1), q(coin(rng), 1)};
        const mpq_class sum = w[0] + w[1] + w[2];
        for (mpq_class& x : w) x /= sum;
        const ComplexPoint p = point_in_triangle(mc, t, w);
        const Interval bt = ref.burning_time(p);
        const double brute = planar_convex_sheet_burning_time(mc, p.approx());
        CAPTURE(sheet, t, bt.lo, bt.hi, brute);
        CHECK(bt.hi - bt.lo < 1e-13);
        CHECK(std::abs(bt.mid() - brute) < 1e-9);
        ++compared;
      }
  }
  CHECK(compared == 4 * (3 + 4 + 5 + 6 + 7 + 8));
}

TEST_CASE("planar sheet reference: the discrete baseline is an upper bound converging in h", "[burn3][reference]") {
  const MedialComplex mc = built(testing::grid_sheet(l_sheet(2)));
  const PlanarSheetReference ref(mc);
  const ComplexLocator locator(mc);
  std::vector<std::pair<ComplexPoint, Interval>> probes;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const ComplexPoint p = locator.locate(mc.vertex(v).exact);
    probes.emplace_back(p, ref.burning_time(p));
  }
  std::mt19937 rng(23);
  std::uniform_int_distribution<long> u(0, 300), v(0, 100);
  for (int i = 0; i < 40; ++i) {
    mpq_class x = q(u(rng), 100), y = q(v(rng), 100);
    if (i % 2) std::swap(x, y);
    const ComplexPoint p = locator.locate({x, y, 0});
    probes.emplace_back(p, ref.burning_time(p));
  }
  double previous = 1e9;
  for (double h : {0.2, 0.1, 0.05}) {
    const DiscreteBurning d = burn_discrete(mc, {h});
    double worst = 0;
    for (const auto& [p, bt] : probes) {
      const double discrete = discrete_burning_time_at(mc, d, {}, p);
      CHECK(discrete >= bt.lo - 1e-12);
      worst = std::max(worst, discrete - bt.lo);
    }
    CAPTURE(h, worst);
    CHECK(worst < previous);
    CHECK(worst <= 0.5 * h);  // measured 0.077, 0.035, 0.0068 at h = 0.2, 0.1, 0.05
    previous = worst;
  }
}
