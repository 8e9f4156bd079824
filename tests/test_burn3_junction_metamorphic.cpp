// Metamorphic checks of the junction rule (Definition 9 on singular curves; docs/exact-engine.md): on complexes with singular edges (books, the Y, the board and fin, the box's medial
// axis, seeded random books), BT is unchanged by renumbering vertices and triangles, by
// reordering the sheets around the singular edges (the triangles of each sheet moved as a
// block, sheets in reverse order), by a rational rotation (Pythagorean angles) with a
// rational translation, and scales exactly under a rational scaling: BT(s R x + t) =
// s BT(x) (zero radius: f = 0 scales too). Compared exactly (ExactSum, proved equal) where
// both values are exact, else as certified enclosures; the junction points (kinks, merges,
// quenches) keep their number and their BT (scaled).
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "burn3/exact/junction_points.h"
#include "complex3/synthetic_complexes.h"
#include "number/sqrt_field.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

// The triangles moved sheet by sheet (each sheet's triangles a block, the sheets in reverse
// order): the order of the sheets around every singular edge changes.
RawComplex sheets_reversed(const RawComplex& raw, std::vector<std::uint32_t>* new_triangle) {
  const MedialComplex mc = built(raw);
  REQUIRE(mc.triangle_count() == raw.triangles.size());
  RawComplex r = raw;
  r.triangles.clear();
  new_triangle->assign(raw.triangles.size(), kNoIndex);
  for (std::size_t i = mc.sheets().size(); i-- > 0;)
    for (std::uint32_t t : mc.sheets()[i].triangles) {
      (*new_triangle)[t] = static_cast<std::uint32_t>(r.triangles.size());
      r.triangles.push_back(raw.triangles[t]);
    }
  REQUIRE(r.triangles.size() == raw.triangles.size());
  return r;
}

std::vector<double> sorted_bt(const std::vector<JunctionPoint>& p) {
  std::vector<double> r;
  for (const JunctionPoint& x : p) r.push_back(x.bt);
  std::sort(r.begin(), r.end());
  return r;
}

// BT of b at the image of every sample point of a, against s times BT of a.
int compare(BorderBurn& a, BorderBurn& b, const std::vector<std::uint32_t>& new_triangle, const mpq_class& s,
            const ExactPoint3& t, bool move, std::mt19937& rng) {
  int exact_pairs = 0;
  for (std::uint32_t k = 0; k < a.mc.triangle_count(); ++k)
    for (const ExactPoint3& x : sample_triangle(a.mc, k, 2, rng)) {
      const ExactPoint3 y = move ? motion(x, s, t) : x;
      const std::uint32_t k2 = new_triangle[k];
      const auto ea = a.eb->exact_burn_time(k, x), eb = b.eb->exact_burn_time(k2, y);
      const Interval ia = a.eb->burn_time(k, x), ib = b.eb->burn_time(k2, y);
      CAPTURE(a.mc.source(), k, to_vec(x)[0], to_vec(x)[1], to_vec(x)[2], ia.lo, ia.hi, ib.lo, ib.hi);
      REQUIRE(ia.is_infinite() == ib.is_infinite());
      if (ia.is_infinite()) continue;
      if (ea && eb) {
        ExactSum scaled = *ea;
        scaled.scale(s);
        CHECK(exact_sign(*eb - scaled) == 0);
        ++exact_pairs;
      } else {
        const double sd = s.get_d();
        CHECK(std::abs(ib.mid() - sd * ia.mid()) <= 1e-9 * (1 + std::abs(ib.mid())) + (ib.hi - ib.lo) + sd * (ia.hi - ia.lo));
      }
    }
  // The junction points: as many of each kind, at the same (scaled) times.
  const double sd = s.get_d();
  const std::vector<JunctionPoint>* la[3] = {&a.points.kinks, &a.points.merges, &a.points.quenches};
  const std::vector<JunctionPoint>* lb[3] = {&b.points.kinks, &b.points.merges, &b.points.quenches};
  for (int i = 0; i < 3; ++i) {
    CAPTURE(a.mc.source(), i);
    REQUIRE(la[i]->size() == lb[i]->size());
    const std::vector<double> x = sorted_bt(*la[i]), y = sorted_bt(*lb[i]);
    for (std::size_t j = 0; j < x.size(); ++j) CHECK(std::abs(y[j] - sd * x[j]) <= 1e-9 * (1 + std::abs(y[j])));
  }
  CHECK(a.points.unclassified == b.points.unclassified);
  return exact_pairs;
}

std::vector<RawComplex> complexes_with_singular_edges() {
  BoardFinOptions bf;
  bf.extent = 6;
  std::vector<RawComplex> r = {book(BookOptions{3, {2, 3, 4}, 9, 1}), book(BookOptions{4, {1, 2, 2, 3}, 0, 1}),
                               y_junction(1), board_fin(bf), box_medial_axis(4, 3, 1, 1),
                               book(BookOptions{3, {4, 4, 4}, 5, 1})};
  std::mt19937 rng(41);  // random books: 3 to 5 pages, widths 1 to 4, height 3 to 9
  for (int i = 0; i < 3; ++i) {
    BookOptions o;
    o.pages = 3 + static_cast<int>(rng() % 3);
    for (int j = 0; j < o.pages; ++j) o.widths.push_back(1 + static_cast<long>(rng() % 4));
    o.height = 3 + static_cast<int>(rng() % 7);
    o.cells_per_unit = 1;
    r.push_back(book(o));
  }
  return r;
}

}  // namespace

TEST_CASE("junction rule: BT is invariant under renumbering and reordering sheets", "[exact3][junction][metamorphic]") {
  std::mt19937 rng(43);
  for (const RawComplex& raw : complexes_with_singular_edges()) {
    BorderBurn a(raw);
    REQUIRE(a.mc.count(EdgeStratum::Singular) > 0);
    CHECK(a.eb->certification().uncertified == 0);
    std::vector<std::uint32_t> tperm, vperm;
    BorderBurn b(shuffled(raw, rng, &tperm, &vperm));
    compare(a, b, tperm, 1, {}, false, rng);
    // Vertex values (singular curves included) follow their vertices.
    const std::vector<Interval> va = a.eb->vertex_burn_times(), vb = b.eb->vertex_burn_times();
    for (std::uint32_t v = 0; v < va.size(); ++v) {
      CAPTURE(raw.source, v, va[v].lo, vb[vperm[v]].lo);
      CHECK(std::abs(va[v].mid() - vb[vperm[v]].mid()) <= 1e-9 * (1 + std::abs(va[v].mid())));
    }
    std::vector<std::uint32_t> sperm;
    BorderBurn c(sheets_reversed(raw, &sperm));
    compare(a, c, sperm, 1, {}, false, rng);
  }
}

TEST_CASE("junction rule: BT moves with rational rigid motions and scales exactly", "[exact3][junction][metamorphic]") {
  std::mt19937 rng(47);
  int exact_pairs = 0;
  for (const RawComplex& raw : complexes_with_singular_edges()) {
    BorderBurn a(raw);
    std::vector<std::uint32_t> same(a.mc.triangle_count());
    for (std::uint32_t t = 0; t < same.size(); ++t) same[t] = t;
    const ExactPoint3 t{mpq_class(1, 3), -2, mpq_class(5, 7)};
    for (const mpq_class& s : {mpq_class(1), mpq_class(3, 2), mpq_class(2, 7)}) {
      BorderBurn b(moved(raw, s, t));
      exact_pairs += compare(a, b, same, s, t, true, rng);
    }
  }
  CHECK(exact_pairs > 500);  // the planar pages: compared as proved-equal ExactSums
}
