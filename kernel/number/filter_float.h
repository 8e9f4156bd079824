// filter_float.h -- a double interval that encloses what a RoundedFloat (rounded_float.h)
// computation of the same program would produce, and refuses to decide what it cannot.
//
// Computes: +, -, *, /, sqrt on closed intervals of doubles with directed rounding that is
// exact where the double operation is exact (error-free transformations: TwoSum, Dekker's
// TwoProduct), so integers and other exact values stay points. Comparisons return the
// answer only when the intervals decide it; otherwise they throw FilterUndecided.
// Why it encloses the RoundedFloat value: round-to-nearest at P >= 53 bits is monotone and
// leaves every double fixed, so if x op y lies in [lo, hi] for all x, y in the operand
// intervals, then round_P(x op y) does too (induction over the program: conversions from
// integers enclose round_P of the integer, every operation encloses round_P of its result).
// So a decision taken here is the decision the RoundedFloat run takes, and a run of generic
// code that completes without FilterUndecided takes exactly the RoundedFloat run's branches.
// Contract: generic code (Boost.Polygon's predicates) decides only through comparisons;
// the caller catches FilterUndecided and reruns the whole computation with RoundedFloat.
// Outside the range where the transformations are exact (|x| > 2^995, results below
// 2^-969) bounds are widened by a relative 2^-51 plus 2^-1022 (interval.h); overflow gives
// infinite bounds, NaN never decides.
// Complexity: O(1) per operation (~20 flops for a product).
#pragma once

#include <gmp.h>

#include <boost/multiprecision/gmp.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "number/interval.h"

namespace grassfire {

struct FilterUndecided {};

namespace filter_detail {

inline double next_up(double x) {
  if (x != x || x == std::numeric_limits<double>::infinity()) return x;
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  b = x > 0 ? b + 1 : b - 1;
  std::memcpy(&x, &b, sizeof b);
  return x;
}
inline double next_down(double x) { return -next_up(-x); }

// Is the product / sum of these finite doubles inside the range where the error-free
// transformations are exact?
inline bool safe_product(double a, double b, double p) {
  const double fa = std::fabs(a), fb = std::fabs(b), fp = std::fabs(p);
  return fa < 0x1p995 && fb < 0x1p995 && fp < 0x1p1000 && (p == 0 ? (a == 0 || b == 0) : fp > 0x1p-969);
}

// The exact a * b = p + e (Dekker; no FMA contraction: the kernel builds with
// -ffp-contract=off).
inline void two_product(double a, double b, double& p, double& e) {
  p = a * b;
  constexpr double split = 134217729.0;  // 2^27 + 1
  const double ca = split * a, ah = ca - (ca - a), al = a - ah;
  const double cb = split * b, bh = cb - (cb - b), bl = b - bh;
  e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

// Rounded-down and rounded-up bounds of r = RN(exact) given the sign of exact - r
// (err_sign); for unknown error (err_known false) one ulp or more either side.
inline void bound(double r, int err_sign, bool err_known, double& lo, double& hi) {
  if (!std::isfinite(r)) {
    lo = r == std::numeric_limits<double>::infinity() ? std::numeric_limits<double>::max() : r;
    hi = r == -std::numeric_limits<double>::infinity() ? -std::numeric_limits<double>::max() : r;
    return;
  }
  if (!err_known) {
    lo = round_down(r);
    hi = round_up(r);
    return;
  }
  lo = err_sign < 0 ? next_down(r) : r;
  hi = err_sign > 0 ? next_up(r) : r;
}

inline int sign(double x) { return (x > 0) - (x < 0); }

inline void add(double a, double b, double& lo, double& hi) {
  const double s = a + b;
  if (!std::isfinite(s) || std::fabs(a) > 0x1p1020 || std::fabs(b) > 0x1p1020) {
    bound(s, 0, std::isfinite(s) ? false : true, lo, hi);
    return;
  }
  const double bb = s - a, e = (a - (s - bb)) + (b - bb);
  bound(s, sign(e), true, lo, hi);
}

inline void mul(double a, double b, double& lo, double& hi) {
  double p, e;
  two_product(a, b, p, e);
  if (!std::isfinite(p)) return bound(p, 0, true, lo, hi);
  bound(p, sign(e), safe_product(a, b, p), lo, hi);
}

inline void div(double a, double b, double& lo, double& hi) {
  const double q = a / b;
  if (!std::isfinite(q)) return bound(q, 0, true, lo, hi);
  double p, e;
  two_product(q, b, p, e);
  const bool known = safe_product(q, b, p) && std::fabs(a) > 0x1p-960 && std::fabs(a) < 0x1p1000;
  // a / b - q = (a - q b) / b, and a - q b = (a - p) - e exactly here.
  bound(q, known ? sign((a - p) - e) * sign(b) : 0, known || a == 0, lo, hi);
}

inline void root(double x, double& lo, double& hi) {
  const double s = std::sqrt(x);
  double p, e;
  two_product(s, s, p, e);
  const bool known = x == 0 || (x > 0x1p-960 && x < 0x1p1000);
  bound(s, known ? sign((x - p) - e) : 0, known, lo, hi);
}

}  // namespace filter_detail

class FilterFloat {
 public:
  FilterFloat() = default;
  FilterFloat(double x) : lo_(x), hi_(x) {}
  template <class T, std::enable_if_t<(std::is_integral_v<T> && sizeof(T) <= sizeof(long)) || std::is_enum_v<T>, int> = 0>
  FilterFloat(T x) : FilterFloat(static_cast<__int128>(x)) {}
  FilterFloat(__int128 x) {
    const double d = static_cast<double>(x);  // round to nearest, |x| < 2^127
    if (std::fabs(d) >= 0x1p127) {
      filter_detail::bound(d, 0, false, lo_, hi_);
      return;
    }
    const __int128 back = static_cast<__int128>(d);
    filter_detail::bound(d, back < x ? 1 : back > x ? -1 : 0, true, lo_, hi_);
  }
  explicit FilterFloat(mpz_srcptr z) {
    const double d = mpz_get_d(z);  // truncated towards zero (infinite beyond the range)
    if (!std::isfinite(d)) {
      filter_detail::bound(d, 0, true, lo_, hi_);
      return;
    }
    const int c = mpz_cmp_d(z, d);
    filter_detail::bound(d, c, true, lo_, hi_);
  }
  template <boost::multiprecision::expression_template_option E>
  FilterFloat(const boost::multiprecision::number<boost::multiprecision::gmp_int, E>& z)
      : FilterFloat(z.backend().data()) {}

  // The interval [l, h] (l <= h): e.g. an enclosure of a RoundedFloat value.
  static FilterFloat enclosing(double l, double h) { return interval(l, h); }
  // A label that copies keep and arithmetic drops (0): e.g. which circle event a value is.
  std::uint32_t tag() const { return tag_; }
  FilterFloat tagged(std::uint32_t t) const {
    FilterFloat r = *this;
    r.tag_ = t;
    return r;
  }
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  explicit operator double() const { return lo_ + 0.5 * (hi_ - lo_); }

  friend FilterFloat operator+(const FilterFloat& a, const FilterFloat& b) {
    FilterFloat r;
    double t;
    filter_detail::add(a.lo_, b.lo_, r.lo_, t);
    filter_detail::add(a.hi_, b.hi_, t, r.hi_);
    return r;
  }
  FilterFloat operator-() const { return interval(-hi_, -lo_); }
  friend FilterFloat operator-(const FilterFloat& a, const FilterFloat& b) { return a + (-b); }
  friend FilterFloat operator*(const FilterFloat& a, const FilterFloat& b) {
    using filter_detail::mul;
    double l, h, t;
    if (a.lo_ >= 0 && b.lo_ >= 0) {
      mul(a.lo_, b.lo_, l, t), mul(a.hi_, b.hi_, t, h);
    } else if (a.hi_ <= 0 && b.hi_ <= 0) {
      mul(a.hi_, b.hi_, l, t), mul(a.lo_, b.lo_, t, h);
    } else if (a.lo_ >= 0 && b.hi_ <= 0) {
      mul(a.hi_, b.lo_, l, t), mul(a.lo_, b.hi_, t, h);
    } else if (a.hi_ <= 0 && b.lo_ >= 0) {
      mul(a.lo_, b.hi_, l, t), mul(a.hi_, b.lo_, t, h);
    } else {  // an operand straddles 0
      const double x[2] = {a.lo_, a.hi_}, y[2] = {b.lo_, b.hi_};
      l = std::numeric_limits<double>::infinity(), h = -l;
      for (double u : x)
        for (double v : y) {
          double pl, ph;
          mul(u, v, pl, ph);
          l = std::fmin(l, pl), h = std::fmax(h, ph);
        }
    }
    return interval(l, h);
  }
  friend FilterFloat operator/(const FilterFloat& a, const FilterFloat& b) {
    using filter_detail::div;
    if (!(b.lo_ > 0 || b.hi_ < 0)) throw FilterUndecided{};  // the divisor's sign is open
    double l, h, t;
    if (b.lo_ > 0) {
      div(a.lo_, a.lo_ >= 0 ? b.hi_ : b.lo_, l, t);
      div(a.hi_, a.hi_ >= 0 ? b.lo_ : b.hi_, t, h);
    } else {
      div(a.hi_, a.hi_ >= 0 ? b.hi_ : b.lo_, l, t);
      div(a.lo_, a.lo_ >= 0 ? b.lo_ : b.hi_, t, h);
    }
    return interval(l, h);
  }
  FilterFloat& operator+=(const FilterFloat& b) { return *this = *this + b; }
  FilterFloat& operator-=(const FilterFloat& b) { return *this = *this - b; }
  FilterFloat& operator*=(const FilterFloat& b) { return *this = *this * b; }
  FilterFloat& operator/=(const FilterFloat& b) { return *this = *this / b; }
  friend FilterFloat sqrt(const FilterFloat& a) {
    if (!(a.lo_ >= 0)) throw FilterUndecided{};
    double l, h, t;
    filter_detail::root(a.lo_, l, t);
    filter_detail::root(a.hi_, t, h);
    return interval(l, h);
  }

  friend bool operator<(const FilterFloat& a, const FilterFloat& b) {
    if (a.hi_ < b.lo_) return true;
    if (a.lo_ >= b.hi_) return false;
    throw FilterUndecided{};
  }
  friend bool operator>(const FilterFloat& a, const FilterFloat& b) { return b < a; }
  friend bool operator<=(const FilterFloat& a, const FilterFloat& b) { return !(b < a); }
  friend bool operator>=(const FilterFloat& a, const FilterFloat& b) { return !(a < b); }
  friend bool operator==(const FilterFloat& a, const FilterFloat& b) {
    if (a.hi_ < b.lo_ || b.hi_ < a.lo_) return false;
    if (a.lo_ == a.hi_ && b.lo_ == b.hi_) return true;  // equal points
    throw FilterUndecided{};
  }
  friend bool operator!=(const FilterFloat& a, const FilterFloat& b) { return !(a == b); }

 private:
  static FilterFloat interval(double l, double h) {
    FilterFloat r;
    r.lo_ = l;
    r.hi_ = h;
    return r;
  }
  double lo_ = 0, hi_ = 0;
  std::uint32_t tag_ = 0;
};

}  // namespace grassfire
