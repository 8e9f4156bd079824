// The exact engine on the closed-form three-page books (burn3/junction_books.h): fronts
// dipping under another along a singular edge for stretches from 1.5e-6 to 1.5e-2 long, one
// and several sources, two crossings 6e-7 apart, a tangent front, pages at near-degenerate
// dihedral angles, sources on and next to the singular edge. Each family's closed form is
// derived from Definition 9 in junction_books.h; the engine must agree to 1e-9 at every check
// point (its enclosure, widened by 1e-9, holds the closed form, and is no wider than 1e-9),
// or say the point is uncertified.
#include <catch2/catch.hpp>

#include <iomanip>
#include <sstream>

#include "burn3/exact/exact_burning.h"
#include "burn3/junction_books.h"
#include "complex3/point_location.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

// The engine run on a book: its sources and its border ignition.
struct BookBurn {
  MedialComplex mc;
  ComplexLocator locator;
  std::unique_ptr<ExactBurning> eb;
  explicit BookBurn(const JunctionBook& b, const ExactBurningOptions& o = {})
      : mc(built(junction_book_complex(b))), locator(mc) {
    eb = std::make_unique<ExactBurning>(mc, o);
    for (const JunctionBookSource& s : b.sources) {
      const JunctionBookPoint p{sgn(s.s) > 0 ? 'A' : 'N', s.x, s.s};
      const ComplexPoint x = locator.locate(junction_book_point(b, p));
      REQUIRE(x.snap_squared == 0);
      eb->add_point_source(x, s.t0);
    }
    eb->add_border_ignition();
    eb->run();
  }
  Interval at(const JunctionBook& b, const JunctionBookPoint& p) {
    const ComplexPoint x = locator.locate(junction_book_point(b, p));
    REQUIRE(x.snap_squared == 0);
    return eb->burn_time(x);
  }
};

void check_book(const JunctionBook& b) {
  BookBurn burn(b);
  const bool certified = burn.eb->certification().uncertified == 0;
  for (const JunctionBookPoint& p : b.checks) {
    const double expected = junction_book_burning_time(b, p);
    const Interval bt = burn.at(b, p);
    std::ostringstream where;
    where << std::setprecision(12) << b.name << ": page " << p.page << " at (" << p.x.get_d() << ", " << p.s.get_d()
          << ") closed form " << expected << ", engine [" << bt.lo << ", " << bt.hi << "]";
    INFO(where.str());
    if (certified) {
      CHECK(encloses(bt, expected, 1e-9));
      CHECK(bt.hi - bt.lo <= 1e-9);
    } else {
      CHECK(encloses(bt, expected));  // uncertified points: the bound must cover the truth
    }
  }
}

}  // namespace

TEST_CASE("junction books: the closed forms themselves (the docs' worked numbers)", "[exact3][junction][closed-form]") {
  const JunctionBook docs = junction_books().front();
  REQUIRE(docs.name == "docs book");
  CHECK(std::abs(junction_book_burning_time(docs, {'N', mpq_class(3, 10), 0}) - (0.5)) <= 1e-12);
  CHECK(std::abs(junction_book_burning_time(docs, {'C', mpq_class(3, 10), mpq_class(1, 100)}) - (0.51)) <= 1e-12);
  CHECK(std::abs(junction_book_burning_time(docs, {'B', mpq_class(3, 10), mpq_class(1, 10)}) - (0.4)) <= 1e-12);
  // Outside the dip (|x - 0.3| > 0.00112) N burns at the source's arrival.
  CHECK(std::abs(junction_book_spine_time(docs, 0.31) - (0.4985 + std::hypot(0.01, 0.001))) <= 1e-12);
  // Every book: BT_N is 1-Lipschitz and never above W (C arrives at W everywhere on N).
  // (x steps of 1e-3 are arclength steps of 1e-3 sqrt(1 + 4 bend^2) on a bent spine's far piece.)
  for (const JunctionBook& b : junction_books()) {
    const double step = 1e-3 * std::sqrt(1 + 4 * b.bend.get_d() * b.bend.get_d());
    for (int i = 0; i < 1000; ++i) {
      const double x = i / 1000.0, y = (i + 1) / 1000.0;
      CHECK(junction_book_spine_time(b, x) <= b.width_c.get_d());
      CHECK(std::abs(junction_book_spine_time(b, x) - junction_book_spine_time(b, y)) <= step + 1e-12);
    }
  }
}

TEST_CASE("junction books: the docs' six-triangle book", "[exact3][junction][closed-form]") {
  check_book(junction_books()[0]);
}

TEST_CASE("junction books: one front dipping under another, depths 1e-6 to 1e-2", "[exact3][junction][closed-form]") {
  for (const JunctionBook& b : junction_books())
    if (b.name.rfind("dip depth", 0) == 0) {
      SECTION(b.name) { check_book(b); }
    }
}

TEST_CASE("junction books: several dips, double crossings, tangency, near-degenerate angles, sources on N",
          "[exact3][junction][closed-form]") {
  for (const JunctionBook& b : junction_books())
    if (b.name != "docs book" && b.name.rfind("dip depth", 0) != 0) {
      SECTION(b.name) { check_book(b); }
    }
}

TEST_CASE("junction books: every engine mutant disagrees with the closed forms somewhere", "[exact3][junction][closed-form][mutants]") {
  // The closed-form families must be able to fail (STYLE.md, "How the most trusted projects
  // test their tests"): each mutant of burn3/exact/engine_mutant.h breaks the engine's own
  // junction decisions, and at least one check point of some book must then miss its closed
  // form by more than 1e-9 (or the engine must report it uncertified).
  // no_kink_emission and double_bending change nothing on these books (measured): the
  // first's kinks are covered by the fronts that make them, the second needs a curved fan.
  for (const EngineMutant m : {EngineMutant::kth_arrival, EngineMutant::first_arrival, EngineMutant::mirrored_rotation,
                               EngineMutant::sampled_crossings}) {
    int missed = 0;
    for (const JunctionBook& b : junction_books()) {
      ExactBurningOptions o;
      o.mutant = m;
      BookBurn burn(b, o);
      for (const JunctionBookPoint& p : b.checks)
        missed += !encloses(burn.at(b, p), junction_book_burning_time(b, p), 1e-9);
    }
    CAPTURE(engine_mutant_name(m), missed);
    CHECK(missed > 0);
  }
}
