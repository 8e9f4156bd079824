// long_interval.h -- closed intervals of x87 extended doubles (64-bit significands).
//
// The same outward-rounding scheme as number/interval.h, for `long double` on x86-64,
// where every operation is correctly rounded to 64 significant bits (unit roundoff
// u = 2^-64, checked by a static assertion on LDBL_MANT_DIG). Used as a second, tighter
// filter for burn-time comparisons, between the double intervals and MPFR.
#pragma once

#include <cfloat>
#include <cmath>

namespace grassfire {

static_assert(LDBL_MANT_DIG == 64, "long double must be the x87 extended format");

struct LongInterval {
  long double lo = 0, hi = 0;
};

// Outward rounding of a round-to-nearest result r: |r| 2^-62 + LDBL_MIN >= ulp(r). The
// smallest normal number, not the smallest subnormal, keeps x87 off its slow denormal path.
inline long double round_down(long double r) {
  if (!(r - r == 0.0L)) return r;
  return r - (std::fabs(r) * 0x1p-62L + LDBL_MIN);
}
inline long double round_up(long double r) {
  if (!(r - r == 0.0L)) return r;
  return r + (std::fabs(r) * 0x1p-62L + LDBL_MIN);
}
inline long double min4(long double a, long double b, long double c, long double d) {
  const long double ab = a < b ? a : b, cd = c < d ? c : d;
  return ab < cd ? ab : cd;
}
inline long double max4(long double a, long double b, long double c, long double d) {
  const long double ab = a > b ? a : b, cd = c > d ? c : d;
  return ab > cd ? ab : cd;
}

inline LongInterval operator+(const LongInterval& a, const LongInterval& b) {
  return {round_down(a.lo + b.lo), round_up(a.hi + b.hi)};
}
inline LongInterval operator-(const LongInterval& a, const LongInterval& b) {
  return {round_down(a.lo - b.hi), round_up(a.hi - b.lo)};
}
inline LongInterval operator*(const LongInterval& a, const LongInterval& b) {
  const long double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
  return {round_down(min4(p0, p1, p2, p3)), round_up(max4(p0, p1, p2, p3))};
}
// Division by an interval that does not contain zero.
inline LongInterval operator/(const LongInterval& a, const LongInterval& b) {
  const long double p0 = a.lo / b.lo, p1 = a.lo / b.hi, p2 = a.hi / b.lo, p3 = a.hi / b.hi;
  return {round_down(min4(p0, p1, p2, p3)), round_up(max4(p0, p1, p2, p3))};
}
inline LongInterval square(const LongInterval& a) {
  if (a.lo >= 0) return {round_down(a.lo * a.lo), round_up(a.hi * a.hi)};
  if (a.hi <= 0) return {round_down(a.hi * a.hi), round_up(a.lo * a.lo)};
  const long double m = -a.lo > a.hi ? -a.lo : a.hi;
  return {0.0L, round_up(m * m)};
}
inline LongInterval sqrt(const LongInterval& a) {
  const long double lo = a.lo <= 0 ? 0.0L : round_down(std::sqrt(a.lo));
  return {lo > 0 ? lo : 0.0L, a.hi <= 0 ? 0.0L : round_up(std::sqrt(a.hi))};
}

}  // namespace grassfire
