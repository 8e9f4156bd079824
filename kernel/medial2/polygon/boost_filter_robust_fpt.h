// boost_filter_robust_fpt.h -- Boost.Polygon's robust_fpt (a value with its relative error
// in ulps) on FilterFloat enclosures (number/filter_float.h), for the filter stage of the
// mp traits (boost_mp_traits.h; 2.1.1, docs/design.md 3). Included by boost_mp_traits.h only.
//
// Computes: what Boost's generic robust_fpt computes, operation for operation, except the
// relative error of a sum of opposite signs, |(a re_a -+ b re_b) / (a +- b)|, when the
// enclosure of the divisor a +- b contains 0 (cancellation below the double intervals'
// resolution, which Boost's lazy circle events meet once or twice per segment on dense
// curves: the centre's c_x / c_y / lower_x sums). The generic code divides by an interval
// around 0 (undecided: a fallback to MPFR). Here, when the numerator's enclosure is
// positive, the error is enclosed by [num.lo / max|divisor|, +inf]: MPFR's divisor lies in
// the enclosure, so its quotient's magnitude is at least that (rounding is monotone), and a
// zero divisor gives an infinite error; MPFR's |temp| + 1 is in the result. So the one use
// Boost makes of it, `ulp() > ULPS` (recompute exactly), is decided when num.lo / max > 64,
// and the value's own enclosure is unchanged.
// Contract: the same interface and results (as enclosures) as boost::polygon::detail::
// robust_fpt<T>; FilterUndecided where neither rule decides. Complexity: O(1).
#pragma once

#include <boost/polygon/detail/voronoi_robust_fpt.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "number/filter_float.h"

namespace boost::polygon::detail {

// Boost's get_sqrt on FilterFloat (FilterFloat's own sqrt, found by argument lookup).
inline grassfire::FilterFloat filter_root(const grassfire::FilterFloat& x) { return sqrt(x); }

template <>
class robust_fpt<grassfire::FilterFloat> {
 public:
  using floating_point_type = grassfire::FilterFloat;
  using relative_error_type = grassfire::FilterFloat;
  enum { ROUNDING_ERROR = 1 };

  robust_fpt() : fpv_(0.0), re_(0.0) {}
  explicit robust_fpt(floating_point_type fpv) : fpv_(fpv), re_(0.0) {}
  robust_fpt(floating_point_type fpv, relative_error_type error) : fpv_(fpv), re_(error) {}

  floating_point_type fpv() const { return fpv_; }
  relative_error_type re() const { return re_; }
  relative_error_type ulp() const { return re_; }
  bool has_pos_value() const { return is_pos(fpv_); }
  bool has_neg_value() const { return is_neg(fpv_); }
  bool has_zero_value() const { return is_zero(fpv_); }
  robust_fpt operator-() const { return robust_fpt(-fpv_, re_); }

  robust_fpt& operator+=(const robust_fpt& that) { return *this = *this + that; }
  robust_fpt& operator-=(const robust_fpt& that) { return *this = *this - that; }
  robust_fpt& operator*=(const robust_fpt& that) {
    re_ += that.re_ + ROUNDING_ERROR;
    fpv_ *= that.fpv_;
    return *this;
  }
  robust_fpt& operator/=(const robust_fpt& that) {
    re_ += that.re_ + ROUNDING_ERROR;
    fpv_ /= that.fpv_;
    return *this;
  }
  robust_fpt operator+(const robust_fpt& that) const {
    const floating_point_type fpv = fpv_ + that.fpv_;
    if ((!is_neg(fpv_) && !is_neg(that.fpv_)) || (!is_pos(fpv_) && !is_pos(that.fpv_)))
      return robust_fpt(fpv, (std::max)(re_, that.re_) + ROUNDING_ERROR);
    return robust_fpt(fpv, cancellation(fpv_ * re_ - that.fpv_ * that.re_, fpv) + ROUNDING_ERROR);
  }
  robust_fpt operator-(const robust_fpt& that) const {
    const floating_point_type fpv = fpv_ - that.fpv_;
    if ((!is_neg(fpv_) && !is_pos(that.fpv_)) || (!is_pos(fpv_) && !is_neg(that.fpv_)))
      return robust_fpt(fpv, (std::max)(re_, that.re_) + ROUNDING_ERROR);
    return robust_fpt(fpv, cancellation(fpv_ * re_ + that.fpv_ * that.re_, fpv) + ROUNDING_ERROR);
  }
  robust_fpt operator*(const robust_fpt& that) const {
    return robust_fpt(fpv_ * that.fpv_, re_ + that.re_ + ROUNDING_ERROR);
  }
  robust_fpt operator/(const robust_fpt& that) const {
    return robust_fpt(fpv_ / that.fpv_, re_ + that.re_ + ROUNDING_ERROR);
  }
  robust_fpt sqrt() const {
    return robust_fpt(filter_root(fpv_), re_ * static_cast<relative_error_type>(0.5) + ROUNDING_ERROR);
  }

 private:
  // |num / div| as the generic code computes it (temp = num / div; if (is_neg(temp))
  // temp = -temp), or, when div's enclosure contains 0 and num's is positive, the
  // enclosure [num.lo / max|div|, +inf] of MPFR's |temp| (see the header).
  static floating_point_type cancellation(const floating_point_type& num, const floating_point_type& div) {
    if (div.lo() > 0 || div.hi() < 0) {
      floating_point_type temp = num / div;
      if (is_neg(temp)) temp = -temp;
      return temp;
    }
    if (!(num.lo() > 0)) throw grassfire::FilterUndecided{};
    const double m = std::max(-div.lo(), div.hi());  // > 0 unless div is the point 0
    if (!(m > 0)) return floating_point_type::enclosing(std::numeric_limits<double>::max(), std::numeric_limits<double>::infinity());
    const double low = grassfire::round_down(num.lo() / m);
    return floating_point_type::enclosing(low, std::numeric_limits<double>::infinity());
  }

  floating_point_type fpv_;
  relative_error_type re_;
};

}  // namespace boost::polygon::detail
