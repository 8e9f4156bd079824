// Exact signs of sums of square roots (number/exact_sum.h).
#include <catch2/catch.hpp>

#include "number/exact_sum.h"

using namespace grassfire;

namespace {
ExactSum r(long n, long d = 1) { return ExactSum::rational(make_rational(n, d)); }
ExactSum s(long n, long d = 1) { return ExactSum::sqrt_of(make_rational(n, d)); }
ExactSum times(long k, ExactSum x) { return x.scale(mpq_class(k)); }
}  // namespace

TEST_CASE("square roots in one square class cancel exactly", "[number]") {
  NumberStats st;
  CHECK(sign(s(8) - times(2, s(2)), &st) == 0);
  CHECK(sign(s(1, 2) - s(2).scale(mpq_class(1, 2)), &st) == 0);
  CHECK(sign(s(9) - r(3), &st) == 0);
  CHECK(sign(s(12) + s(27) - times(5, s(3)), &st) == 0);
  CHECK(sign(s(50, 9) - s(2).scale(make_rational(5, 3)), &st) == 0);
  CHECK(st.exact_zero + st.filter_decided + st.mpfr_decided == 5);
  CHECK(st.exact_zero >= 3);
}

TEST_CASE("independent square roots never cancel", "[number]") {
  CHECK(sign(s(2) + s(3) - s(5)) == 1);
  CHECK(sign(s(2) + s(3) - s(10)) == -1);  // 3.146 < 3.162
  CHECK(sign(s(6) - s(2) - s(3)) == -1);
  CHECK(sign(r(0)) == 0);
}

TEST_CASE("near ties are separated by raising the precision", "[number]") {
  // sqrt(10^12 + 1) - 10^6 - 1/(2 * 10^6) = -1/(8 * 10^18) + ...  (a tiny negative number)
  NumberStats st;
  ExactSum x = s(1000000000001L) - r(1000000) - r(1, 2000000);
  CHECK(sign(x, &st) == -1);
  CHECK(st.filter_decided == 0);
  CHECK(st.mpfr_decided == 1);
  // A sum with 40 terms that cancels except for a difference of 2^-200.
  ExactSum y;
  for (long k = 2; k < 42; ++k) y += s(k) - s(k);
  y += ExactSum::rational(mpq_class(1) / mpq_class(mpz_class(1) << 200));
  CHECK(sign(y) == 1);
}

TEST_CASE("a nonzero sum that agrees with zero to 512 bits is still decided", "[number]") {
  // sqrt(a^2 + 1) - a - 1/(2a) with a = 2^300 is about -2^-903: below the 512-bit stage.
  mpz_class a = mpz_class(1) << 300;
  ExactSum x = ExactSum::sqrt_of(mpq_class(a * a + 1)) - ExactSum::rational(mpq_class(a)) -
               ExactSum::rational(mpq_class(1, 1) / mpq_class(2 * a));
  NumberStats st;
  CHECK(sign(x, &st) == -1);
  CHECK(st.max_bits_used > 512);
}

TEST_CASE("constants cancel by identity only", "[number]") {
  struct Pi : CertifiedConstant {
    void enclose(mpfr_ptr lo, mpfr_ptr hi) const override {
      mpfr_const_pi(lo, MPFR_RNDD);
      mpfr_const_pi(hi, MPFR_RNDU);
    }
    std::string identity() const override { return "pi"; }
  };
  auto pi = std::make_shared<Pi>();
  NumberStats st;
  CHECK(sign(ExactSum::constant(pi) - ExactSum::constant(pi), &st) == 0);
  CHECK(sign(ExactSum::constant(pi) - r(355, 113), &st) == -1);
  CHECK(st.uncertified_zero == 0);
}

TEST_CASE("to_string shows the terms", "[number]") {
  ExactSum x = r(3, 2) + s(2) - s(5).scale(mpq_class(1, 2));
  CHECK(to_string(x) == "3/2 + 1*sqrt(2) - 1/2*sqrt(5)");
}
