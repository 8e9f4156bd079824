// Exact signs of sums of square roots of sums of square roots (number/root_separation.h):
// hand-built identities that no pairwise radicand test sees, near misses that only a high
// precision separates, and seeded random sums against MPFR at a precision far beyond the
// bound's.
#include <catch2/catch.hpp>

#include <random>

#include "number/mpfr_bounds.h"
#include "number/root_separation.h"
#include "number/sqrt_field.h"

using namespace grassfire;

namespace {

ExactSum rat(long n, long d = 1) { return ExactSum::rational(make_rational(n, d)); }
ExactSum root(long n) { return ExactSum::sqrt_of(n); }
// c sqrt(E) with E kept as written (no denesting, no normalisation).
ExactSum radical(const ExactSum& e, const mpq_class& c = 1) {
  ExactSum r = ExactSum::constant(sqrt_constant(e));
  return r.scale(c);
}

// The sign of x from MPFR at `bits` (kUndecided when that does not separate x from 0).
int mpfr_sign(const ExactSum& x, long bits) {
  MpfrBounds b(bits);
  x.enclose(b.lo, b.hi);
  return b.sign();
}

}  // namespace

TEST_CASE("root separation: identities between radicals of different square classes", "[number]") {
  // sqrt(2 - sqrt2) = (sqrt2 - 1) sqrt(2 + sqrt2): the radicands' ratio is a square in
  // Q(sqrt2), not in Q, so the two radicals are not merged as equal constants.
  const ExactSum a = radical(rat(2) + root(2)), b = radical(rat(2) - root(2));
  const ExactSum x = a + b - multiply_radical(a, root(2));  // sqrt(4 + 2 sqrt2) = sqrt2 sqrt(2 + sqrt2)
  const std::optional<SeparationBound> bound = separation_bound(x, kMaxSeparationBits);
  REQUIRE(bound);
  CHECK(bound->degree_log2 == 3);  // sqrt2 and two radicals
  CHECK(radical_sign(x, kMaxSeparationBits) == std::optional<int>(0));
  NumberStats st;
  CHECK(sign(x, &st) == 0);
  CHECK(st.uncertified_zero == 0);
  CHECK(st.separation_decided == 1);
  CHECK(st.exact_zero == 1);
  // Radicands that are rational multiples of one another: sqrt(8 + 4 sqrt2) = 2 sqrt(2 + sqrt2).
  const ExactSum y = radical(rat(8) + root(32)) - radical(rat(2) + root(2), 2);
  REQUIRE(separation_bound(y, kMaxSeparationBits));
  CHECK(separation_bound(y, kMaxSeparationBits)->degree_log2 == 2);
  CHECK(radical_sign(y, kMaxSeparationBits) == std::optional<int>(0));
}

TEST_CASE("root separation: near misses are separated, never called zero", "[number]") {
  // sqrt(2 + sqrt2) + sqrt(2 - sqrt2) - sqrt(4 + 2 sqrt2 + 10^-60) < 0, about -10^-61.
  mpq_class tiny = 1;
  for (int i = 0; i < 60; ++i) tiny /= 10;
  const ExactSum a = radical(rat(2) + root(2)), b = radical(rat(2) - root(2));
  const ExactSum c = radical(rat(4) + root(8) + ExactSum::rational(tiny));
  const ExactSum x = a + b - c;
  CHECK(mpfr_sign(x, 512) == -1);  // independent: plain MPFR at 512 bits
  CHECK(radical_sign(x, kMaxSeparationBits) == std::optional<int>(-1));
  CHECK(radical_sign(ExactSum() - x, kMaxSeparationBits) == std::optional<int>(1));
  // A constant that is not a radical: no answer.
  struct Pi : CertifiedConstant {
    void enclose(mpfr_ptr lo, mpfr_ptr hi) const override {
      mpfr_const_pi(lo, MPFR_RNDD);
      mpfr_const_pi(hi, MPFR_RNDU);
    }
    std::string identity() const override { return "pi"; }
  };
  CHECK_FALSE(radical_sign(x + ExactSum::constant(std::make_shared<Pi>()), kMaxSeparationBits));
}

TEST_CASE("root separation: seeded random sums agree with MPFR at 20000 bits", "[number]") {
  // sqrt(p + q + 2 sqrt(pq)) = sqrt(p) + sqrt(q), the radical written as a constant (not
  // denested, so only the bound can prove the zero), summed over one or two pairs (p, q);
  // every other trial adds 10^-(20 + trial) inside one radicand: a difference of about
  // 10^-(21 + trial), far below the double filter and beyond 512 bits for the late trials.
  std::mt19937 rng(11);
  std::uniform_int_distribution<long> value(2, 60), coef(1, 9);
  int zeros = 0, nonzeros = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const bool zero = trial % 2 == 0;
    ExactSum x;
    for (int i = 0; i <= trial % 2 + (trial / 2) % 2; ++i) {
      const long p = value(rng), q = value(rng), c = coef(rng) * (i % 2 ? -1 : 1);
      ExactSum e = rat(p + q) + root(p * q).scale(2);
      if (!zero && i == 0) {
        mpq_class tiny = 1;
        for (int k = 0; k < 20 + trial; ++k) tiny /= 10;
        e += ExactSum::rational(tiny);
      }
      x += radical(e, c) - (root(p) + root(q)).scale(c);
    }
    const std::optional<int> s = radical_sign(x, kMaxSeparationBits);
    REQUIRE(s);
    const int reference = mpfr_sign(x, 20000);
    INFO("trial " << trial << ": " << to_string(x));
    if (zero) {
      CHECK(*s == 0);
      CHECK(reference == kUndecided);  // 20000 bits do not separate an exact zero
      ++zeros;
    } else {
      REQUIRE(reference != kUndecided);
      CHECK(*s == reference);
      ++nonzeros;
    }
  }
  CHECK(zeros == 20);
  CHECK(nonzeros == 20);
}
