// Exact burning engine, metamorphic checks (docs/exact-engine.md): rational rotations
// (Pythagorean), translations and scalings change BT exactly as they should; reordering
// vertices and triangles changes nothing.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "burn3/exact/exact_burning.h"
#include "complex3/synthetic_complexes.h"
#include "number/sqrt_field.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

TEST_CASE("rational rigid motions and scalings scale BT exactly (planar sheet with a hole)", "[exact3]") {
  const RawComplex raw = grid_sheet(4, 3, 1, {{1, 1}}, IgnitionRule::Linear);
  const mpq_class s(3, 2);
  const ExactPoint3 t{mpq_class(1, 3), -2, mpq_class(5, 7)};
  const MedialComplex a = built(raw), b = built(moved(raw, s, t));
  ExactBurning ea(a), eb(b);
  ea.add_border_ignition(), eb.add_border_ignition();
  ea.add_point_source(0, triangle_point(a, 0, mpq_class(1, 3), mpq_class(1, 3)), mpq_class(1, 2));
  eb.add_point_source(0, motion(triangle_point(a, 0, mpq_class(1, 3), mpq_class(1, 3)), s, t), mpq_class(3, 4));
  ea.run(), eb.run();
  std::mt19937 rng(23);
  for (std::uint32_t k = 0; k < a.triangle_count(); ++k)
    for (const ExactPoint3& x : sample_triangle(a, k, 3, rng)) {
      const auto va = ea.exact_burn_time(k, x), vb = eb.exact_burn_time(k, motion(x, s, t));
      REQUIRE(va);
      REQUIRE(vb);
      ExactSum scaled = *va;
      scaled.scale(s);
      CHECK(exact_sign(*vb - scaled) == 0);
    }
}

TEST_CASE("rigid motions and reordering leave BT unchanged on curved surfaces", "[exact3]") {
  std::mt19937 rng(29);
  for (const RawComplex& raw : {octahedron_surface(), tetrahedron_with_flap(), pinched_double_cone(5)}) {
    const MedialComplex a = built(raw);
    std::vector<std::uint32_t> tperm;
    const RawComplex shuffled_raw = shuffled(raw, rng, &tperm);
    const MedialComplex b = built(moved(raw, 2, {1, 2, 3})), c = built(shuffled_raw);
    ExactBurning ea(a), eb(b), ec(c);
    const ExactPoint3 p = triangle_point(a, 0, mpq_class(1, 5), mpq_class(2, 5));
    ea.add_point_source(0, p, 0), eb.add_point_source(0, motion(p, 2, {1, 2, 3}), 0), ec.add_point_source(tperm[0], p, 0);
    ea.add_border_ignition(), eb.add_border_ignition(), ec.add_border_ignition();
    ea.run(), eb.run(), ec.run();
    for (std::uint32_t k = 0; k < a.triangle_count(); ++k)
      for (const ExactPoint3& x : sample_triangle(a, k, 3, rng)) {
        const Interval ia = ea.burn_time(k, x), ib = eb.burn_time(k, motion(x, 2, {1, 2, 3})), ic = ec.burn_time(tperm[k], x);
        CAPTURE(raw.source, k, ia.lo, ib.lo, ic.lo);
        CHECK(std::abs(2 * ia.mid() - ib.mid()) <= 1e-11);
        CHECK(std::abs(ia.mid() - ic.mid()) <= 1e-11);
      }
    CHECK(ea.certification().uncertified == 0);
  }
}
