// The exact engine on slivers: triangles with an edge of about 1e-17 among coordinates of
// order 1 (tripod-s2.ma's axis has one, vertices 15, 75, 129 within 3e-17 of each other).
// The double stage must never compute NaN or garbage there: its frames and crossings come
// from the exact data where the enclosures of the vertices do not separate them, and any
// value it cannot bound has an infinite error (the filter fails, the next stage decides).
// Before that, a sliver's frame divided by an interval holding 0: NaN images, NaN queue
// keys, and vertex 129 of tripod-s2.ma never burned (the discrete baseline: 0.307846).
// References: a closed form (a folded square with a sliver bump on its fold: BT = the
// distance in the unfolded square, up to the bump's 1e-17), and on tripod-s2.ma the
// discrete baseline (an upper bound whose gap shrinks in h) and 1-Lipschitz continuity
// across the sliver.
#include <catch2/catch.hpp>

#include <cmath>

#include "burn3/exact/exact_burning.h"
#include "burn3/exact/unfolding.h"
#include "io/complex_ma.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using testing::built;

namespace {

mpq_class q(long n, long d = 1) { return make_rational(n, d); }

// Every corner image and every crossing of the double stage is finite and tight.
void check_double_stage(const MedialComplex& mc, const Unfolding& u) {
  double worst_corner = 0.0, worst_rotation = 0.0;
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const DiscPoint& c = u.corner(t, i);
      CHECK(std::isfinite(c.x));
      CHECK(std::isfinite(c.y));
      worst_corner = std::max(worst_corner, c.r);
      const std::uint32_t e = mc.triangle(t).e[i];
      if (mc.edge(e).stratum != EdgeStratum::Manifold) continue;
      const auto& ts = mc.edge_triangles(e);
      const RigidMotion2& m = u.crossing(e, t, ts[0] == t ? ts[1] : ts[0]);
      CHECK(std::isfinite(m.r00));
      CHECK(std::isfinite(m.t1));
      CHECK(std::isfinite(m.rot_error));
      worst_rotation = std::max({worst_rotation, m.rot_error, m.trans_error});
    }
  }
  INFO("worst corner radius " << std::scientific << worst_corner << ", worst crossing error " << worst_rotation);
  CHECK(worst_corner < 1e-12);
  CHECK(worst_rotation < 1e-10);
}

}  // namespace

TEST_CASE("a folded square with a 1e-17 sliver bump on its fold burns at the unfolded distance", "[exact3][sliver]") {
  // The square [0, 1] x [-1, 1] folded along y = 0: (x, t) -> (x, t, 0) for t <= 0 and
  // (x, 3t/5, 4t/5) for t >= 0. On the fold, P = (1/2, 0, 0) and Q = P + (d, 0, 0); the bump
  // vertex S = P + (d/2, d, d) lies on neither sheet's plane, so the triangles PQS, PSB0,
  // SQB1 and SB1B0 are each their own frame, PQS with all three edges of about d.
  const mpq_class d = q(1, 100'000'000) * q(1, 1'000'000'000);  // 1e-17
  RawComplex raw;
  raw.source = "folded square with a sliver";
  const auto B = [](const mpq_class& x, const mpq_class& t) { return ExactPoint3{x, q(3, 5) * t, q(4, 5) * t}; };
  raw.vertices = {{q(0), q(0), q(0)},       {q(1, 2), q(0), q(0)},   {q(1, 2) + d, q(0), q(0)},
                  {q(1), q(0), q(0)},       {q(0), q(-1), q(0)},     {q(1), q(-1), q(0)},
                  B(q(0), q(1)),            B(q(1), q(1)),           {q(1, 2) + d / 2, d, d}};
  enum { F0, P, Q, F1, A0, A1, B0, B1, S };
  raw.triangles = {{A0, P, F0}, {A0, A1, P}, {A1, Q, P}, {A1, F1, Q},  // sheet z = 0 (a sliver A1 Q P)
                   {F0, P, B0}, {P, S, B0},  {P, Q, S},  {S, Q, B1}, {Q, F1, B1}, {S, B1, B0}};
  raw.radius_squared.assign(raw.vertices.size(), q(0));
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{F0, A0}, {A0, A1}, {A1, F1}, {F1, B1}, {B1, B0}, {B0, F0}})
    raw.border_rules.push_back({{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)}, IgnitionRule::Never, {}});
  const MedialComplex mc = built(raw);
  REQUIRE(mc.count(EdgeStratum::Singular) == 0);

  ExactBurning eb(mc);
  check_double_stage(mc, eb.unfolding());
  // The source (3/8, -3/4) of the sheet z = 0, inside triangle A0 A1 P.
  const ExactPoint3 source{q(3, 8), q(-3, 4), q(0)};
  eb.add_point_source(1, source, q(0));
  eb.run();
  CHECK(eb.certification().uncertified == 0);
  // Unfolded coordinates (x, t) of each vertex (S: the bump, within 2d of (1/2, 0)).
  const std::vector<std::array<double, 2>> unfolded = {{0, 0},    {0.5, 0}, {0.5, 0}, {1, 0}, {0, -1},
                                                       {1, -1},   {0, 1},   {1, 1},   {0.5, 0}};
  const std::vector<Interval> bt = eb.vertex_burn_times();
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const double expected = std::hypot(unfolded[v][0] - 0.375, unfolded[v][1] + 0.75);
    CAPTURE(v, bt[v].lo, bt[v].hi, expected);
    CHECK(bt[v].hi - bt[v].lo < 1e-12);
    CHECK(bt[v].lo <= expected + 1e-15);
    CHECK(expected <= bt[v].hi + 1e-15);
  }
  // Points of the far sheet whose paths pass the bump: in triangle S B1 B0 (tilted by the
  // bump, so given by exact barycentric weights), unfolded to within 1e-17 of the weights
  // applied to (1/2, 0), (1, 1), (0, 1); the first lies on the ray from the source through P.
  std::uint32_t top = kNoIndex;
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    if (corner_of(mc.triangle(t), S) >= 0 && corner_of(mc.triangle(t), B0) >= 0 && corner_of(mc.triangle(t), B1) >= 0) top = t;
  }
  REQUIRE(top != kNoIndex);
  for (const auto& w : std::vector<std::array<mpq_class, 3>>{{q(3, 4), q(1, 6), q(1, 12)}, {q(1, 2), q(1, 4), q(1, 4)},
                                                             {q(1, 8), q(3, 4), q(1, 8)}}) {
    const auto& vs = raw.vertices;
    const ExactPoint3 p{w[0] * vs[S].x + w[1] * vs[B1].x + w[2] * vs[B0].x, w[0] * vs[S].y + w[1] * vs[B1].y + w[2] * vs[B0].y,
                        w[0] * vs[S].z + w[1] * vs[B1].z + w[2] * vs[B0].z};
    const double ux = 0.5 * w[0].get_d() + w[1].get_d(), ut = w[1].get_d() + w[2].get_d();
    const double expected = std::hypot(ux - 0.375, ut + 0.75);
    const Interval b = eb.burn_time(top, p);
    CAPTURE(ux, ut, b.lo, b.hi, expected);
    CHECK(b.hi - b.lo < 1e-12);
    CHECK(b.lo <= expected + 1e-15);
    CHECK(expected <= b.hi + 1e-15);
  }
}

TEST_CASE("tripod-s2.ma's sliver: every vertex burns, continuous across it, below the baseline converging in h",
          "[exact3][sliver]") {
  const MedialComplex mc = built(read_ma(std::string(GF_PROJECT_DATA) + "/ma/real/tripod-s2.ma"));
  ExactBurning eb(mc);
  check_double_stage(mc, eb.unfolding());
  eb.add_border_ignition();
  eb.run();
  const std::vector<Interval> bt = eb.vertex_burn_times();
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    CAPTURE(v);
    REQUIRE(!bt[v].is_infinite());
    CHECK(bt[v].hi - bt[v].lo < 1e-10);
  }
  // Vertices 15, 75, 129 lie within 3e-17 of each other: BT is 1-Lipschitz.
  for (const auto& [a, b] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{{129, 15}, {129, 75}, {15, 75}}) {
    CAPTURE(a, b, bt[a].lo, bt[b].lo);
    CHECK(std::fabs(bt[a].mid() - bt[b].mid()) <= 1e-12);
  }
  double previous = 1e9;
  for (const double h : {0.01, 0.005, 0.0025}) {
    const double worst = testing::baseline_gap(mc, bt, h);
    CAPTURE(h, worst);
    CHECK(worst < previous);
    CHECK(worst <= h);
    previous = worst;
  }
}
