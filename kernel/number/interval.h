// interval.h -- closed intervals of doubles with outward rounding.
//
// Computes: enclosures [lo, hi] of real values; every operation returns an interval
// that contains the exact result of the operation applied to any points of its operands.
// Contract: operands are finite or +infinity (an infinite burn time); NaN never enters
// (readers reject it). Rounding: each bound is computed in round-to-nearest and then
// moved one ulp outwards with std::nextafter, which is valid because a correctly
// rounded IEEE operation errs by at most half an ulp. No FPU mode is changed, so this
// type mixes freely with code that relies on round-to-nearest.
// Complexity: O(1) per operation.
// Section: DESIGN.md 3 (the interval filter in front of every exact fallback).
#pragma once

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
    return std::nextafter(0.5 * (hi - lo), std::numeric_limits<double>::infinity()) +
           std::numeric_limits<double>::denorm_min();
  }
  bool contains(double x) const { return lo <= x && x <= hi; }
};

inline double round_down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }
inline double round_up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

inline Interval operator+(const Interval& a, const Interval& b) {
  const double lo = a.lo + b.lo, hi = a.hi + b.hi;
  return {std::isinf(lo) ? lo : round_down(lo), std::isinf(hi) ? hi : round_up(hi)};
}
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
inline Interval operator-(const Interval& a, const Interval& b) { return a + (-b); }
inline Interval operator*(const Interval& a, const Interval& b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  double lo = p[0], hi = p[0];
  for (double v : p) {
    lo = std::fmin(lo, v);
    hi = std::fmax(hi, v);
  }
  return {round_down(lo), round_up(hi)};
}
// Division by an interval that does not contain zero.
inline Interval operator/(const Interval& a, const Interval& b) {
  const double p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  double lo = p[0], hi = p[0];
  for (double v : p) {
    lo = std::fmin(lo, v);
    hi = std::fmax(hi, v);
  }
  return {round_down(lo), round_up(hi)};
}
inline Interval& operator+=(Interval& a, const Interval& b) { return a = a + b; }
inline Interval& operator-=(Interval& a, const Interval& b) { return a = a - b; }
// Square root of the non-negative part of an interval.
inline Interval sqrt(const Interval& a) {
  const double lo = a.lo <= 0.0 ? 0.0 : std::fmax(0.0, round_down(std::sqrt(a.lo)));
  const double hi = a.hi <= 0.0 ? 0.0 : round_up(std::sqrt(a.hi));
  return {lo, hi};
}
inline Interval square(const Interval& a) {
  if (a.lo >= 0) return {round_down(a.lo * a.lo), round_up(a.hi * a.hi)};
  if (a.hi <= 0) return {round_down(a.hi * a.hi), round_up(a.lo * a.lo)};
  const double m = std::fmax(-a.lo, a.hi);
  return {0.0, round_up(m * m)};
}
inline Interval half(const Interval& a) { return {round_down(a.lo * 0.5), round_up(a.hi * 0.5)}; }
inline Interval hull(const Interval& a, const Interval& b) {
  return {std::fmin(a.lo, b.lo), std::fmax(a.hi, b.hi)};
}

// Certified sign of an interval: +1 / -1 when the interval excludes zero, 0 when it is
// the point zero, and `undecided` (2) otherwise.
constexpr int kUndecided = 2;
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
