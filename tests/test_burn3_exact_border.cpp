// Exact burning engine: the border ignition rules (Linear with any slope, DistanceToPoint,
// Never) on planar convex sheets against the brute force over the border (docs/exact-engine.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "burn3/burn3_reference.h"
#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/exact_burning.h"
#include "complex3/synthetic_complexes.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

// A convex fan around the origin, rim on a circle of radius rho (rational points), with
// R^2 per rim vertex; `rules` assigns the rim edges' rules (Linear when absent).
struct Fan {
  RawComplex raw;
  std::vector<std::uint32_t> rim;
};

Fan convex_fan(int k, const mpq_class& rho, const std::vector<mpq_class>& r2, const mpq_class& centre_r2) {
  ComplexBuilder b("convex fan");
  Fan f;
  const std::uint32_t centre = b.vertex({0, 0, 0}, centre_r2);
  for (int j = 0; j < k; ++j) {
    const auto d = rational_unit_direction(2 * M_PI * j / k);
    f.rim.push_back(b.vertex({rho * d[0], rho * d[1], 0}, r2[j]));
  }
  for (int j = 0; j < k; ++j) b.triangle(centre, f.rim[j], f.rim[(j + 1) % k]);
  f.raw = b.take();
  return f;
}

// Compares the engine's enclosure with the brute force at vertices and random points.
void compare_with_brute_force(const MedialComplex& mc, std::mt19937& rng, double tolerance) {
  ExactBurning eb(mc);
  eb.add_border_ignition();
  eb.run();
  CHECK(eb.certification().uncertified == 0);
  double worst = 0.0, width = 0.0;
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
    for (const ExactPoint3& x : sample_triangle(mc, t, 8, rng)) {
      const Interval bt = eb.burn_time(t, x);
      const double ref = planar_convex_sheet_burning_time(mc, to_vec(x));
      worst = std::max(worst, std::max(bt.lo - ref, ref - bt.hi));
      width = std::max(width, bt.hi - bt.lo);
    }
  CAPTURE(mc.source(), worst, width);
  CHECK(worst <= tolerance);
  CHECK(width <= 1e-10);
  // The discrete baseline over-estimates: BT_discrete >= BT_exact at every vertex.
  const DiscreteBurning d = burn_discrete(mc, {0.25});
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) CHECK(d.vertex_bt[v] >= eb.vertex_burn_time(v).lo - 1e-9);
}

}  // namespace

TEST_CASE("Linear border ignition: plane waves and endpoint sources equal the brute force", "[exact3]") {
  std::mt19937 rng(11);
  for (int instance = 0; instance < 6; ++instance) {
    const int k = 5 + instance;
    std::uniform_int_distribution<int> rr(0, instance < 3 ? 3 : 9);  // later instances: slopes >= 1 too
    std::vector<mpq_class> r2;
    for (int j = 0; j < k; ++j) {
      const mpq_class r = rr(rng);
      r2.push_back(instance % 2 ? r * r : mpq_class(rr(rng)));  // rational R, or R = sqrt(integer)
    }
    Fan f = convex_fan(k, 6 + instance, r2, 4);
    f.raw.border_rules.push_back({{f.rim[0], f.rim[1]}, IgnitionRule::Never, {}});
    f.raw.source = "linear fan " + std::to_string(instance);
    const MedialComplex mc = built(f.raw);
    compare_with_brute_force(mc, rng, 1e-9);
  }
}

TEST_CASE("DistanceToPoint border ignition: the rotated point's window equals the brute force", "[exact3]") {
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> coord(-3, 3), height(1, 4);
  for (int instance = 0; instance < 5; ++instance) {
    const int k = 5 + instance;
    Fan f = convex_fan(k, 6, std::vector<mpq_class>(k, 0), 0);
    for (int j = 0; j < k; ++j) {
      // p beside the edge, off the plane (a medial ball's touching point), or on the edge's
      // line (h = 0) once.
      const auto& a = f.raw.vertices[f.rim[j]];
      const auto& b = f.raw.vertices[f.rim[(j + 1) % k]];
      ExactPoint3 p{(a.x + b.x) / 2 + coord(rng), (a.y + b.y) / 2 + coord(rng), mpq_class(height(rng))};
      if (instance == 0 && j == 0) p = {(a.x + 3 * b.x) / 4, (a.y + 3 * b.y) / 4, 0};
      f.raw.border_rules.push_back({{f.rim[j], f.rim[(j + 1) % k]}, IgnitionRule::DistanceToPoint, p});
    }
    if (instance == 2) f.raw.border_rules[1].rule = IgnitionRule::Never;
    f.raw.source = "distance fan " + std::to_string(instance);
    const MedialComplex mc = built(f.raw);
    compare_with_brute_force(mc, rng, 1e-9);
  }
}

TEST_CASE("a sheet that never ignites never burns", "[exact3]") {
  const MedialComplex mc = built(grid_sheet(2, 2, 1));
  ExactBurning eb(mc);
  eb.add_border_ignition();
  eb.run();
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) CHECK(eb.vertex_burn_time(v).is_infinite());
  CHECK(eb.propagation().stats().windows == 0);
}
