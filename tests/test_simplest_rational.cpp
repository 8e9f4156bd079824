// simplest_rational (128-bit continued fractions with an early stop) equals the GMP
// recursion simplest_rational_reference on seeded random intervals: around rationals of
// small and large denominators (found or refused by the bit limit), generic narrow and
// wide intervals, negative ones and ones holding 0 or an integer; and on hand cases.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "number/simplest_rational.h"

using namespace grassfire;

namespace {

void same(double lo, double hi, std::size_t bits) {
  INFO(lo << " " << hi << " bits " << bits);
  const auto fast = simplest_rational(lo, hi, bits);
  const auto ref = simplest_rational_reference(mpq_class(lo), mpq_class(hi), bits);
  REQUIRE(fast.has_value() == ref.has_value());
  if (fast) CHECK(*fast == *ref);
}

}  // namespace

TEST_CASE("simplest rational: hand cases", "[number]") {
  CHECK(*simplest_rational(0.3, 0.34, 8) == mpq_class(1, 3));
  CHECK(*simplest_rational(-0.34, -0.3, 8) == mpq_class(-1, 3));
  CHECK(*simplest_rational(-0.5, 0.25, 8) == 0);
  CHECK(*simplest_rational(2.9, 3.1, 8) == 3);
  CHECK(!simplest_rational(0.333333, 0.3333331, 4).has_value());  // 1/3 is outside; the simplest needs > 4 bits
}

TEST_CASE("simplest rational: fast equals the GMP recursion", "[number]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  std::size_t found = 0, refused = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::size_t bits = 1 + rng() % 40;
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
    double centre = scale * (unit(rng) - 0.5) * 8;
    if (i % 3 == 0) centre = static_cast<double>(static_cast<long>(rng() % 2000) - 1000) / static_cast<double>(1 + rng() % (1u << (rng() % 20)));
    const double width = std::fabs(centre) * std::ldexp(1.0, -static_cast<int>(rng() % 60)) + std::ldexp(1.0, -static_cast<int>(rng() % 80));
    const double lo = centre - width * unit(rng), hi = centre + width * unit(rng);
    same(lo, hi, bits);
    same(lo, lo, bits);
    const auto r = simplest_rational(lo, hi, bits);
    r ? ++found : ++refused;
  }
  CHECK(found > 1000);
  CHECK(refused > 1000);
}
