// Kinks, merges and quench points of the junction rule located and classified exactly
// (junction_points.h; docs/exact-engine.md). Closed forms derived by hand:
//  - board and fin truncated at E (synthetic_complexes.h): on N, at s (the point (s, s, 0)),
//    the back side arrives at s and the fin at sqrt2 (s - 1); N burns at the second, so the
//    kink is at s = 2 + sqrt2 with BT 2 + sqrt2 (4.2.1). Beyond it N burns at sqrt2 (s - 1),
//    rising towards the far end e = (E, E, 0), a star (its link has no cycle) that burns at
//    its first arrival, the back side's E, and sends fire back along N: E + sqrt2 (E - s).
//    The two meet head on where sqrt2 (s - 1) = E + sqrt2 (E - s), s = 1/2 + E (2 + sqrt2)/4:
//    E = 6 gives s = 7/2 + 3/2 sqrt2, BT = sqrt2 (s - 1) = 3 + 5/2 sqrt2 (E = 12: s = 13/2 +
//    3 sqrt2, BT = 6 + 11/2 sqrt2).
//  - a book of k pages of width w >= S/2 and height S (every border edge igniting at 0): the
//    spine burns at min(z, S - z, T) = min(z, S - z): the fronts from the bottom and the top
//    (each grazing the spine in every page) meet head on at z = S/2, BT = S/2.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "burn3/exact/junction_points.h"
#include "complex3/point_location.h"
#include "complex3/synthetic_complexes.h"
#include "number/sqrt_field.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

ExactSum q_plus_r_sqrt2(const mpq_class& q, const mpq_class& r) {
  ExactSum s = ExactSum::sqrt_of(2);
  s.scale(r);
  s += ExactSum::rational(q);
  s.simplify();
  return s;
}


// p's exact coordinates and BT equal the closed forms (proved where exact, else inside
// the certified error).
void check_point(const JunctionPoint& p, const std::array<ExactSum, 3>& x, const ExactSum& bt, bool exact_bt) {
  CAPTURE(to_string(p.kind), p.x[0], p.x[1], p.x[2], p.bt, p.error);
  REQUIRE(p.exact_x);
  for (int i = 0; i < 3; ++i) CHECK(exact_sign((*p.exact_x)[i] - x[i]) == 0);
  if (exact_bt) {
    REQUIRE(p.exact_bt);
    CHECK(exact_sign(*p.exact_bt - bt) == 0);
  }
  CHECK(p.error < 1e-9);
  for (int i = 0; i < 3; ++i) CHECK(std::abs(p.x[i] - x[i].to_double()) <= p.error + 1e-15);
  CHECK(std::abs(p.bt - bt.to_double()) <= p.error + 1e-15);
}

ExactSum q(const mpq_class& v) { return ExactSum::rational(v); }

}  // namespace

TEST_CASE("board and fin: the kink at 2 + sqrt2 and the quench at 7/2 + 3/2 sqrt2, exactly", "[exact3][junction]") {
  BoardFinOptions o;
  o.extent = 6;
  for (int g : {1, 2}) {
    o.cells_per_unit = g;
    BorderBurn b(board_fin(o));
    CAPTURE(g);
    CHECK(b.points.unclassified == 0);
    CHECK(b.points.merges.empty());
    REQUIRE(b.points.kinks.size() == 1);
    REQUIRE(b.points.quenches.size() == 1);
    const ExactSum k = q_plus_r_sqrt2(2, 1);
    check_point(b.points.kinks[0], {k, k, q(0)}, k, true);
    const ExactSum s = q_plus_r_sqrt2(mpq_class(7, 2), mpq_class(3, 2));
    // BT there is exact when the realising window is (g = 1: the fin's plane wave); with
    // g = 2 the front side's copy realises it, known as an enclosure.
    check_point(b.points.quenches[0], {s, s, q(0)}, q_plus_r_sqrt2(3, mpq_class(5, 2)), g == 1);
  }
}

TEST_CASE("books: the spine's fronts from the bottom and the top quench at S/2", "[exact3][junction]") {
  BorderBurn b(book(BookOptions{3, {4, 4, 4}, 5, 1}));
  CHECK(b.points.unclassified == 0);
  CHECK(b.points.kinks.empty());
  CHECK(b.points.merges.empty());
  REQUIRE(b.points.quenches.size() == 1);
  check_point(b.points.quenches[0], {q(0), q(0), q(mpq_class(5, 2))}, q(mpq_class(5, 2)), true);
  // book:3 and the Y: the corners of min(z, S - z, T) lie at vertices (z = T, S - T), so no
  // edge switches inside.
  for (const BookOptions& o : {BookOptions{3, {}, 0, 2}, y_junction_options(2)}) {
    BorderBurn c(book(o));
    CHECK(c.points.unclassified == 0);
    CHECK(c.points.kinks.size() + c.points.merges.size() + c.points.quenches.size() == 0);
  }
}

// Three pages of width 4 and height 10, no border ignition; point sources on the bottom
// border: page 0 at distance 1 from the spine at time 0, page 1 at distance 1 at time 1/2,
// page 2 at distance 3 at time 0. At height z the pages arrive at d0 = sqrt(1 + z^2),
// d1 = 1/2 + sqrt(1 + z^2), d2 = sqrt(9 + z^2); the spine's bottom end (a star) burns at
// its first arrival, 1, and its top end at sqrt 101, each sending fire along the spine. d0
// is always first, so the spine burns at A = min(1 + z, d1, d2, sqrt101 + 10 - z):
//  - 1 + z = d1 at z = 3/4 (BT 7/4), slopes 1 then 3/5: the front along the curve is
//    overtaken by page 1's, running the same way (a merge);
//  - d1 = d2 at z^2 = 945/16, z = 3/4 sqrt105 (BT 33/4), slopes z/(31/4) then z/(33/4): page
//    2's front takes over from page 1's (a merge);
//  - d2 meets the top end's fire head on at z = (c^2 - 9) / (2c), c = 10 + sqrt101 (a quench).
TEST_CASE("book with point sources: two merges and a quench on the spine", "[exact3][junction]") {
  const MedialComplex mc = built(book(BookOptions{3, {4, 4, 4}, 10, 1}));
  ExactBurning eb(mc);
  const ComplexLocator where(mc);
  const std::array<std::pair<long, mpq_class>, 3> sources = {{{1, 0}, {1, mpq_class(1, 2)}, {3, 0}}};
  for (int j = 0; j < 3; ++j) {
    const auto d = rational_unit_direction(2 * M_PI * j / 3);
    const ExactPoint3 p{sources[j].first * d[0], sources[j].first * d[1], 0};
    eb.add_point_source(where.locate(p), sources[j].second);
  }
  eb.run();
  const JunctionPoints j = junction_points(eb);
  CHECK(j.unclassified == 0);
  CHECK(j.kinks.empty());
  REQUIRE(j.merges.size() == 2);
  REQUIRE(j.quenches.size() == 1);
  std::vector<JunctionPoint> merges = j.merges;
  std::sort(merges.begin(), merges.end(), [](const auto& a, const auto& b) { return a.x[2] < b.x[2]; });
  check_point(merges[0], {q(0), q(0), q(mpq_class(3, 4))}, q(mpq_class(7, 4)), true);
  ExactSum z = ExactSum::sqrt_of(105);
  z.scale(mpq_class(3, 4));
  z.simplify();
  check_point(merges[1], {q(0), q(0), z}, q(mpq_class(33, 4)), true);
  const double c = 10 + std::sqrt(101.0), zq = (c * c - 9) / (2 * c);
  const JunctionPoint& p = j.quenches[0];
  CHECK(std::abs(p.x[2] - zq) <= p.error + 1e-12);
  CHECK(std::abs(p.bt - (c - zq)) <= p.error + 1e-12);
  CHECK(std::abs(p.x[0]) + std::abs(p.x[1]) <= p.error);
}
