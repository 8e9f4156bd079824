// interval.h -- closed intervals of doubles with outward rounding.
//
// Computes: enclosures [lo, hi] of real values; every operation returns an interval
// that contains the exact result of the operation applied to any points of its operands.
// Contract: operands are finite or +infinity (an infinite burn time); NaN never enters
// (readers reject it). Rounding: each bound is computed in round-to-nearest and then
// moved outwards by at least one ulp (round_down/round_up below), which is valid because a
// correctly rounded IEEE operation errs by at most half an ulp. No FPU mode is changed, so this
// type mixes freely with code that relies on round-to-nearest.
// Complexity: O(1) per operation.
// Section: docs/design.md 3 (the interval filter in front of every exact fallback).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace grassfire {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;

  constexpr Interval() = default;
  constexpr Interval(double point) : lo(point), hi(point) {}  // NOLINT: exact doubles convert
  constexpr Interval(double l, double h) : lo(l), hi(h) {}

  static Interval infinity() {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, inf};
  }
  bool is_point() const { return lo == hi; }
  bool is_infinite() const { return lo == std::numeric_limits<double>::infinity(); }
  double mid() const { return is_infinite() ? lo : lo + 0.5 * (hi - lo); }
  // Half the width, rounded up: |mid() - x| <= radius() for every x inside.
  double radius() const {
    if (is_infinite()) return 0.0;
    const double r = 0.5 * (hi - lo);
    return r + (std::fabs(r) * 0x1p-51 + 0x1p-1022);
  }
  bool contains(double x) const { return lo <= x && x <= hi; }
};

// Outward rounding of a round-to-nearest result r: the exact value lies within half an
// ulp of r, and |r| * 2^-51 + 2^-1022 >= ulp(r), so r minus that amount rounds to at most
// r - ulp(r) (rounding is monotone). Cheaper than std::nextafter, one ulp or two looser.
// 2^-1022 is the smallest normal double: a subnormal constant would cost a slow path.
// Infinities pass through unchanged.
inline double round_down(double r) {
  if (!(r - r == 0.0)) return r;
  return r - (std::fabs(r) * 0x1p-51 + 0x1p-1022);
}
inline double round_up(double r) {
  if (!(r - r == 0.0)) return r;
  return r + (std::fabs(r) * 0x1p-51 + 0x1p-1022);
}

inline Interval operator+(const Interval& a, const Interval& b) {
  return {round_down(a.lo + b.lo), round_up(a.hi + b.hi)};
}
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
inline Interval operator-(const Interval& a, const Interval& b) { return a + (-b); }
inline Interval operator*(const Interval& a, const Interval& b) {
  if (a.lo >= 0 && b.lo >= 0) return {round_down(a.lo * b.lo), round_up(a.hi * b.hi)};
  const double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
  return {round_down(std::min(std::min(p0, p1), std::min(p2, p3))),
          round_up(std::max(std::max(p0, p1), std::max(p2, p3)))};
}
// Division by an interval that does not contain zero.
inline Interval operator/(const Interval& a, const Interval& b) {
  const double p0 = a.lo / b.lo, p1 = a.lo / b.hi, p2 = a.hi / b.lo, p3 = a.hi / b.hi;
  return {round_down(std::min(std::min(p0, p1), std::min(p2, p3))),
          round_up(std::max(std::max(p0, p1), std::max(p2, p3)))};
}
inline Interval& operator+=(Interval& a, const Interval& b) { return a = a + b; }
inline Interval& operator-=(Interval& a, const Interval& b) { return a = a - b; }
// Square root of the non-negative part of an interval.
inline Interval sqrt(const Interval& a) {
  const double lo = a.lo <= 0.0 ? 0.0 : std::max(0.0, round_down(std::sqrt(a.lo)));
  const double hi = a.hi <= 0.0 ? 0.0 : round_up(std::sqrt(a.hi));
  return {lo, hi};
}
inline Interval square(const Interval& a) {
  if (a.lo >= 0) return {round_down(a.lo * a.lo), round_up(a.hi * a.hi)};
  if (a.hi <= 0) return {round_down(a.hi * a.hi), round_up(a.lo * a.lo)};
  const double m = std::max(-a.lo, a.hi);
  return {0.0, round_up(m * m)};
}
inline Interval half(const Interval& a) { return {round_down(a.lo * 0.5), round_up(a.hi * 0.5)}; }
inline Interval hull(const Interval& a, const Interval& b) {
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

// Certified sign of an interval: +1 / -1 when the interval excludes zero, 0 when it is
// the point zero, and `undecided` (2) otherwise.
constexpr int kUndecided = 2;
// |a| and min(a, b) as intervals: exact on the end points (no rounding needed).
inline Interval abs_of(const Interval& a) {
  if (a.lo >= 0) return a;
  if (a.hi <= 0) return -a;
  return {0.0, std::fmax(-a.lo, a.hi)};
}
inline Interval min_of(const Interval& a, const Interval& b) { return {std::fmin(a.lo, b.lo), std::fmin(a.hi, b.hi)}; }
inline int certified_sign(const Interval& a) {
  if (a.lo > 0) return 1;
  if (a.hi < 0) return -1;
  if (a.lo == 0 && a.hi == 0) return 0;
  return kUndecided;
}

inline std::ostream& operator<<(std::ostream& os, const Interval& a) {
  return os << '[' << a.lo << ", " << a.hi << ']';
}

}  // namespace grassfire
