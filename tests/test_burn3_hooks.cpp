// The mutation hook of the discrete baseline (DiscreteBurningOptions::rule_override), which
// the proof checks use to show that their rows detect a broken rule: the identity override
// changes nothing, and a junction rule at the first arrival does what it says.
#include <catch2/catch.hpp>

#include <cmath>

#include "burn3/discrete/discrete_burning.h"
#include "complex3/synthetic_complexes.h"
#include "test_complex3_support.h"

using namespace grassfire;

using testing::built;

namespace {

class SameRule : public BurnRuleOverride {
 public:
  bool burns(const LinkArrivals& a) const override { return a.rule; }
};

class FirstArrival : public BurnRuleOverride {
 public:
  bool burns(const LinkArrivals& a) const override {
    return a.junction ? a.sectors_arrived + a.poles_arrived >= 1 : a.rule;
  }
};

}  // namespace

TEST_CASE("rule override: the identity override gives the same BT bit for bit", "[burn3]") {
  const SameRule same;
  for (const RawComplex& raw : {board_fin({6, 1}), box_medial_axis(4, 3, 1, 2), tetrahedron_with_flap()}) {
    const MedialComplex mc = built(raw);
    DiscreteBurningOptions o;
    o.spacing = 0.25;
    const DiscreteBurning plain = burn_discrete(mc, o);
    o.rule_override = &same;
    const DiscreteBurning hooked = burn_discrete(mc, o);
    CHECK(plain.vertex_bt == hooked.vertex_bt);
    CHECK(plain.steiner_bt == hooked.steiner_bt);
  }
}

TEST_CASE("rule override: a book's spine burning at its first arrival burns at the narrowest page", "[burn3]") {
  // Pages of widths 1, 2, 3 on a spine of height 8 (every border ignites at f = 0): the
  // spine's middle burns at T = 2, the (k-1)-th width; at its first arrival it burns at 1.
  const BookOptions o{3, {1, 2, 3}, 8, 2};
  const MedialComplex mc = built(book(o));
  const FirstArrival first;
  DiscreteBurningOptions opt;
  opt.spacing = 0.125;
  const DiscreteBurning plain = burn_discrete(mc, opt);
  opt.rule_override = &first;
  const DiscreteBurning mutated = burn_discrete(mc, opt);
  std::size_t spine = 0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const Vec3d& p = mc.vertex(v).approx;
    if (p[0] != 0 || p[1] != 0 || p[2] < 3 || p[2] > 5) continue;  // the spine's middle
    ++spine;
    CHECK(plain.vertex_bt[v] == Approx(2.0).margin(1e-9));
    CHECK(mutated.vertex_bt[v] == Approx(1.0).margin(1e-9));
  }
  CHECK(spine >= 4);
}
