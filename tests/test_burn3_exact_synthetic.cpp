// Exact burning engine on the synthetic complexes with singular edges as walls (docs/exact-engine.md; ExactBurningOptions::singular_walls, `burn3d --singular-walls`): exact closed
// forms where the walls do not change BT, and per-side arrivals. The junction rule itself
// is tested in test_burn3_junction.cpp.
#include <catch2/catch.hpp>

#include <random>

#include "burn3/exact/exact_burning.h"
#include "complex3/synthetic_complexes.h"
#include "number/sqrt_field.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

ExactSum root(const mpq_class& q) {
  ExactSum s = ExactSum::sqrt_of(q);
  s.simplify();
  return s;
}

// Part 1 on the board and fin (N a wall), on the side of triangle t: the fin burns from F
// alone, sqrt2 (s - 1); the board from B: y where the straight drop to B misses N (the
// back side and x <= 1), else (the front side) around the end c = (1, 1) of N: |p - c| + 1,
// the shortest path avoiding the slit N. Points of N take the value of the side queried.
enum class BoardFinSide { Back, Front, Fin };

BoardFinSide side_of(const MedialComplex& mc, std::uint32_t t) {
  mpq_class x = 0, y = 0, z = 0;
  for (std::uint32_t v : mc.triangle(t).v) x += mc.vertex(v).exact.x, y += mc.vertex(v).exact.y, z += mc.vertex(v).exact.z;
  if (sgn(z) > 0) return BoardFinSide::Fin;
  return y > x && x > 3 ? BoardFinSide::Front : BoardFinSide::Back;  // centroid: x > 1 in units of 1/3
}

ExactBurningOptions walls() {
  ExactBurningOptions o;
  o.singular_walls = true;
  return o;
}

ExactSum board_fin_part1(BoardFinSide side, const ExactPoint3& p) {
  if (side == BoardFinSide::Fin) return root(2 * (p.x - 1) * (p.x - 1));
  if (side == BoardFinSide::Front && p.x > 1)
    return root((p.x - 1) * (p.x - 1) + (p.y - 1) * (p.y - 1)) + ExactSum::rational(1);
  return ExactSum::rational(p.y);
}

}  // namespace

TEST_CASE("board and fin with N as a wall: exact BT on board and fin, arrivals on N", "[exact3]") {
  BoardFinOptions o;
  o.extent = 5;
  const MedialComplex mc = built(board_fin(o));
  ExactBurning eb(mc, walls());
  eb.add_border_ignition();
  eb.run();
  CHECK(eb.certification().uncertified == 0);
  std::mt19937 rng(17);
  int front = 0;
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    const BoardFinSide side = side_of(mc, t);
    front += side == BoardFinSide::Front;
    for (const ExactPoint3& x : sample_triangle(mc, t, 3, rng)) {
      const auto e = eb.exact_burn_time(t, x);
      REQUIRE(e);
      const ExactSum expected = board_fin_part1(side, x);
      CAPTURE(x.x.get_d(), x.y.get_d(), x.z.get_d(), to_string(*e), to_string(expected));
      CHECK(exact_sign(*e - expected) == 0);
      // Where the wall changes nothing, part 1 gives the closed form of 4.2.1.
      if (side != BoardFinSide::Front && !(x.x == x.y && sgn(x.z) == 0))
        CHECK(std::abs(e->to_double() - board_fin_burning_time(to_vec(x))) < 1e-12);
    }
  }
  CHECK(front > 5);
  // The arrivals at N through its three sheet sides at the middle of each singular edge:
  // back s, front sqrt2 (s - 1) + 1, fin sqrt2 (s - 1) (4.2.1, before any junction rule).
  int walls = 0;
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    if (mc.edge(e).stratum != EdgeStratum::Singular) continue;
    ++walls;
    const ExactPoint3 &a = mc.vertex(mc.edge(e).v[0]).exact, &b = mc.vertex(mc.edge(e).v[1]).exact;
    const ExactPoint3 m{(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2};
    for (std::uint32_t t : mc.edge_triangles(e)) {
      const auto arrival = eb.exact_burn_time(t, m);
      REQUIRE(arrival);
      CHECK(exact_sign(*arrival - board_fin_part1(side_of(mc, t), m)) == 0);
    }
  }
  CHECK(walls == o.extent - 1);
}

TEST_CASE("book and Y with the spine as a wall: each page burns from its own border", "[exact3]") {
  for (const BookOptions& o : {y_junction_options(2), BookOptions{4, {1, 2, 2, 3}, 0, 1}}) {
    const MedialComplex mc = built(book(o));
    ExactBurning eb(mc, walls());
    eb.add_border_ignition();
    eb.run();
    CHECK(eb.certification().uncertified == 0);
    const mpq_class S = book_height(o);
    std::mt19937 rng(19);
    for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
      // The page: the widths identify it by the outer edge; u = distance from the spine.
      for (const ExactPoint3& x : sample_triangle(mc, t, 3, rng)) {
        const auto e = eb.exact_burn_time(t, x);
        REQUIRE(e);
        // Page j's outer edge is at u = w_j; the page's plane contains the z axis, so
        // u = |(x, y)| and w_j is the largest u of the triangle's page.
        const ExactSum u = root(x.x * x.x + x.y * x.y);
        const std::uint32_t sheet = mc.triangle(t).sheet;
        mpq_class w2 = 0;
        for (std::uint32_t t2 : mc.sheets()[sheet].triangles)
          for (std::uint32_t v : mc.triangle(t2).v) w2 = std::max(w2, mpq_class(mc.vertex(v).exact.x * mc.vertex(v).exact.x + mc.vertex(v).exact.y * mc.vertex(v).exact.y));
        // min(w - u, z, S - z), exactly
        ExactSum best = root(w2) - u;
        for (const mpq_class& c : {mpq_class(x.z), mpq_class(S - x.z)})
          if (exact_sign(ExactSum::rational(c) - best) < 0) best = ExactSum::rational(c);
        CHECK(exact_sign(*e - best) == 0);
      }
    }
  }
}
