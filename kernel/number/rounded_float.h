// rounded_float.h -- a binary float of fixed precision with correctly rounded arithmetic
// (MPFR, round to nearest), usable where generic code expects a built-in floating type.
//
// Computes: +, -, *, / and sqrt, each correctly rounded to the precision of D decimal
// digits (MPFR's: D = 60 gives 200 bits); comparisons are exact. Integers and enumerators
// (long, __int128, GMP integers) convert implicitly, rounded once (exactly when they fit
// the precision), doubles exactly; the limbs are stored inline
// (no allocation). Used as Boost.Polygon's fpt_type in the mp traits (medial2/
// boost_mp_traits.h), whose robust_fpt error bookkeeping counts ulps of this type.
// Contract: the exponent stays within MPFR's default range (+-2^30): no overflow for
// anything computed from finite doubles in a fixed number of operations.
// Complexity: one MPFR operation per arithmetic operator, O(P) limbs at these sizes.
#pragma once

#include <boost/multiprecision/gmp.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <mpfr.h>

#include <type_traits>

namespace grassfire {

template <unsigned D>
class RoundedFloat {
 public:
  using Number = boost::multiprecision::number<
      boost::multiprecision::mpfr_float_backend<D, boost::multiprecision::allocate_stack>,
      boost::multiprecision::et_off>;

  RoundedFloat() = default;
  RoundedFloat(double x) { mpfr_set_d(data(), x, MPFR_RNDN); }
  template <class T, std::enable_if_t<(std::is_integral_v<T> && sizeof(T) <= sizeof(long)) || std::is_enum_v<T>, int> = 0>
  RoundedFloat(T x) {
    mpfr_set_si(data(), static_cast<long>(x), MPFR_RNDN);
  }
  // Exact when |x| < 2^P (P >= 128 for D >= 40).
  RoundedFloat(__int128 x) {
    const bool neg = x < 0;
    const unsigned __int128 u = neg ? -static_cast<unsigned __int128>(x) : static_cast<unsigned __int128>(x);
    mpfr_set_ui(data(), static_cast<unsigned long>(u >> 64), MPFR_RNDN);
    mpfr_mul_2ui(data(), data(), 64, MPFR_RNDN);
    mpfr_add_ui(data(), data(), static_cast<unsigned long>(u & 0xffffffffffffffffu), MPFR_RNDN);
    if (neg) mpfr_neg(data(), data(), MPFR_RNDN);
  }
  // A GMP integer, rounded once.
  explicit RoundedFloat(mpz_srcptr z) { mpfr_set_z(data(), z, MPFR_RNDN); }
  template <boost::multiprecision::expression_template_option E>
  RoundedFloat(const boost::multiprecision::number<boost::multiprecision::gmp_int, E>& z)
      : RoundedFloat(z.backend().data()) {}

  mpfr_ptr data() { return v_.backend().data(); }
  mpfr_srcptr data() const { return v_.backend().data(); }
  static long precision() { return static_cast<long>(mpfr_get_prec(RoundedFloat().data())); }
  explicit operator double() const { return mpfr_get_d(data(), MPFR_RNDN); }

  friend RoundedFloat operator+(const RoundedFloat& a, const RoundedFloat& b) {
    RoundedFloat r;
    mpfr_add(r.data(), a.data(), b.data(), MPFR_RNDN);
    return r;
  }
  friend RoundedFloat operator-(const RoundedFloat& a, const RoundedFloat& b) {
    RoundedFloat r;
    mpfr_sub(r.data(), a.data(), b.data(), MPFR_RNDN);
    return r;
  }
  friend RoundedFloat operator*(const RoundedFloat& a, const RoundedFloat& b) {
    RoundedFloat r;
    mpfr_mul(r.data(), a.data(), b.data(), MPFR_RNDN);
    return r;
  }
  friend RoundedFloat operator/(const RoundedFloat& a, const RoundedFloat& b) {
    RoundedFloat r;
    mpfr_div(r.data(), a.data(), b.data(), MPFR_RNDN);
    return r;
  }
  RoundedFloat operator-() const {
    RoundedFloat r;
    mpfr_neg(r.data(), data(), MPFR_RNDN);
    return r;
  }
  RoundedFloat& operator+=(const RoundedFloat& b) { return *this = *this + b; }
  RoundedFloat& operator-=(const RoundedFloat& b) { return *this = *this - b; }
  RoundedFloat& operator*=(const RoundedFloat& b) { return *this = *this * b; }
  RoundedFloat& operator/=(const RoundedFloat& b) { return *this = *this / b; }

  friend bool operator<(const RoundedFloat& a, const RoundedFloat& b) { return mpfr_less_p(a.data(), b.data()); }
  friend bool operator>(const RoundedFloat& a, const RoundedFloat& b) { return mpfr_greater_p(a.data(), b.data()); }
  friend bool operator<=(const RoundedFloat& a, const RoundedFloat& b) { return mpfr_lessequal_p(a.data(), b.data()); }
  friend bool operator>=(const RoundedFloat& a, const RoundedFloat& b) { return mpfr_greaterequal_p(a.data(), b.data()); }
  friend bool operator==(const RoundedFloat& a, const RoundedFloat& b) { return mpfr_equal_p(a.data(), b.data()); }
  friend bool operator!=(const RoundedFloat& a, const RoundedFloat& b) { return !mpfr_equal_p(a.data(), b.data()); }

  friend RoundedFloat sqrt(const RoundedFloat& a) {
    RoundedFloat r;
    mpfr_sqrt(r.data(), a.data(), MPFR_RNDN);
    return r;
  }

 private:
  Number v_;
};

}  // namespace grassfire
