// boost_mp_traits.h -- coordinate type traits that run Boost.Polygon's Voronoi builder on
// integer coordinates of any size (the mp binary policy of polygon_axis.h: every finite
// double polygon; 2.1.1, docs/design.md 3). Included by segment_voronoi_boost_mp.cpp only.
//
// Boost's predicates rest on three assumptions about the traits (see boost_wide_traits.h):
// (a) input coordinates convert to fpt_type exactly; (b) orientation tests and the integer
// parts of circle events are exact integer arithmetic; (c) fpt_type is a binary float with
// correctly rounded +, -, *, /, sqrt, so that robust_fpt's relative-error bookkeeping (in
// ulps of fpt_type) holds, and ulp_cmp_type counts ulps of that type. Boost's default meets
// them for int32 input in double: 21 guard bits. These traits meet them for integer input
// of B bits (after translation to the frame's centre) with fpt_type an MPFR float of fixed
// precision P >= B + kGuardBits (kGuardBits = 64, more than the default's 21 and the wide
// traits' 51), every conversion one correct rounding (MPFR_RNDN), and exact integers:
//   Tier128: input __int128 (B <= 126), 256-bit checked integers for the products of two
//            coordinates, dynamic cpp_int for the circle events, P = 201 bits (60 digits).
//   Tier128Filter: Tier128's integers, double-interval enclosures (number/filter_float.h) of
//            its floats (robust_fpt's error bookkeeping: boost_filter_robust_fpt.h);
//            FilterPredicates hands every decision they leave open to Tier128's
//            predicates on the same sites, so the run takes Tier128's branches.
//   TierGmp<D>: every integer a GMP integer, P = the precision of D decimal digits
//            (D = 200: 667 bits, B <= 600; D = 700: 2328 bits, B <= 2260, which holds every
//            pair of finite doubles: 2^1024 down to 2^-1074 spans 2098 bits).
// The ulp comparison counts ulps of the larger magnitude (a superset of Boost's "within k
// ulps": more ties go to the exact evaluation, never fewer).
// Complexity: O(1) MPFR operations per predicate, each O(P) at these sizes (the fixed
// precisions keep the limbs on the stack, no allocation).
#pragma once

#include <boost/multiprecision/cpp_int.hpp>
#include <boost/multiprecision/gmp.hpp>
#include <boost/polygon/voronoi_builder.hpp>
#include <gmp.h>
#include <mpfr.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "medial2/polygon/boost_filter_robust_fpt.h"
#include "number/filter_float.h"
#include "number/rounded_float.h"

namespace grassfire::boost_mp {

namespace mp = boost::multiprecision;

constexpr int kGuardBits = 64;

template <unsigned Digits10>
using Float = RoundedFloat<Digits10>;
using Gmp = mp::number<mp::gmp_int, mp::et_off>;
using Int256 = mp::number<mp::cpp_int_backend<256, 256, mp::signed_magnitude, mp::checked, void>, mp::et_off>;
using UInt256 = mp::number<mp::cpp_int_backend<256, 256, mp::unsigned_magnitude, mp::checked, void>, mp::et_off>;

// The precision of Float<D> in bits.
template <unsigned D>
inline long precision_bits() {
  return Float<D>::precision();
}

// Ulps of the larger magnitude between a and b (MPFR has no subnormals: values of opposite
// signs, or a zero and a non-zero, are farther apart than any max_ulps).
template <class F>
struct UlpComparison {
  enum Result { LESS = -1, EQUAL = 0, MORE = 1 };
  Result operator()(const F& a, const F& b, unsigned int max_ulps) const {
    mpfr_srcptr x = a.data(), y = b.data();
    const int c = mpfr_cmp(x, y);
    if (c == 0) return EQUAL;
    const Result apart = c < 0 ? LESS : MORE;
    if (mpfr_sgn(x) * mpfr_sgn(y) <= 0) return apart;
    const mpfr_exp_t ex = mpfr_get_exp(x), ey = mpfr_get_exp(y);
    if (ex - ey > 1 || ey - ex > 1) return apart;  // at least 2^(P-1) ulps apart
    F d;
    mpfr_sub(d.data(), x, y, MPFR_RNDZ);  // |d| rounded down: EQUAL never lost
    mpfr_abs(d.data(), d.data(), MPFR_RNDN);
    const mpfr_exp_t e = (ex > ey ? ex : ey) - static_cast<mpfr_exp_t>(mpfr_get_prec(x));
    return mpfr_cmp_ui_2exp(d.data(), max_ulps, e) <= 0 ? EQUAL : apart;
  }
};

// Integers and doubles to F, each with one correct rounding (exact when they fit P bits).
template <class F>
struct ToFloat {
  F operator()(const F& x) const { return x; }
  // A RoundedFloat value as an enclosing FilterFloat (F = FilterFloat).
  template <unsigned D, class G = F, std::enable_if_t<std::is_same_v<G, FilterFloat>, int> = 0>
  F operator()(const RoundedFloat<D>& x) const {
    return FilterFloat::enclosing(mpfr_get_d(x.data(), MPFR_RNDD), mpfr_get_d(x.data(), MPFR_RNDU));
  }
  F operator()(double x) const { return F(x); }
  F operator()(__int128 x) const { return F(x); }
  F operator()(const Gmp& x) const { return F(x); }
  // cpp_int (fixed or dynamic): its limbs read as a GMP integer without a copy.
  template <unsigned A, unsigned B, mp::cpp_integer_type S, mp::cpp_int_check_type C, class Al>
  F operator()(const mp::number<mp::cpp_int_backend<A, B, S, C, Al>, mp::et_off>& x) const {
    static_assert(sizeof(mp::limb_type) == sizeof(mp_limb_t), "cpp_int limbs are GMP limbs");
    const auto& b = x.backend();
    std::size_t n = b.size();
    const mp::limb_type* l = b.limbs();
    while (n > 0 && l[n - 1] == 0) --n;
    F r;
    if (n == 0) return r;
    mpz_t z;
    mpz_roinit_n(z, reinterpret_cast<const mp_limb_t*>(l), static_cast<mp_size_t>(b.sign() ? -static_cast<long>(n) : static_cast<long>(n)));
    return F(static_cast<mpz_srcptr>(z));
  }
};

// Boost's coordinate type traits from their parts (conversions by ToFloat).
template <class Int, class Int2, class UInt2, class Big, class Fpt, class Efpt, class Ulp>
struct Traits {
  using int_type = Int;
  using int_x2_type = Int2;
  using uint_x2_type = UInt2;
  using big_int_type = Big;
  using fpt_type = Fpt;
  using efpt_type = Efpt;
  using ulp_cmp_type = Ulp;
  using to_fpt_converter_type = ToFloat<Fpt>;
  using to_efpt_converter_type = ToFloat<Efpt>;
};

// The ulp comparison of UlpComparison<F> decided on FilterFloat enclosures of F's values
// (filter_float.h): LESS / MORE when the enclosures lie farther apart than any max_ulps
// ulps of F can reach, F's own answer on exact points, FilterUndecided otherwise.
template <class F>
struct FilterUlpComparison : UlpComparison<F> {
  using Result = typename UlpComparison<F>::Result;
  Result operator()(const FilterFloat& a, const FilterFloat& b, unsigned int max_ulps) const {
    if (a.lo() == a.hi() && b.lo() == b.hi()) return UlpComparison<F>()(F(a.lo()), F(b.lo()), max_ulps);
    const double m = std::fmax(std::fmax(std::fabs(a.lo()), std::fabs(a.hi())), std::fmax(std::fabs(b.lo()), std::fabs(b.hi())));
    int e = 0;
    std::frexp(m, &e);
    // max_ulps ulps of F at magnitudes up to 2^e, rounded up to a double.
    const double reach = std::ldexp(static_cast<double>(max_ulps), e + 1 - static_cast<int>(F::precision()));
    if (round_down(b.lo() - a.hi()) > reach) return UlpComparison<F>::LESS;
    if (round_down(a.lo() - b.hi()) > reach) return UlpComparison<F>::MORE;
    throw FilterUndecided{};
  }
};

// The filter stage of Tier128: the same integers, FilterFloat enclosures of Tier128's
// floats (FilterPredicates decides what they leave open). The square-root expressions of
// exact circle events (efpt), whose big integers exceed a double's exponent range, run in
// Tier128's float; their results enter as enclosures (ToFloat).
struct Tier128Filter
    : Traits<__int128, Int256, UInt256, mp::number<mp::cpp_int_backend<>, mp::et_off>, FilterFloat, Float<60>,
             FilterUlpComparison<Float<60>>> {};

// Input below 2^126 in magnitude.
struct Tier128 : Traits<__int128, Int256, UInt256, mp::number<mp::cpp_int_backend<>, mp::et_off>, Float<60>, Float<60>,
                        UlpComparison<Float<60>>> {
  using F = Float<60>;
  static constexpr int kInputBits = 126;
};

template <unsigned D>
struct TierGmp : Traits<Gmp, Gmp, Gmp, Gmp, Float<D>, Float<D>, UlpComparison<Float<D>>> {};

// Boost's predicates for Tier128Filter, except that a decision the filter leaves undecided
// is taken by Tier128's own predicate: node comparisons on the same sites (the site types
// are equal); circle events formed by Tier128 on the same sites, their values kept as
// enclosures of Tier128's; event comparisons on Tier128's circles, recomputed from the
// sites each circle was formed from (CircleOrigins). So every decision is the one a Tier128
// run takes. FilterUndecided still escapes when a circle's origin is not unique (two
// triples with bit-identical enclosures and different Tier128 circles): the caller reruns
// the construction with Tier128. `fallbacks` counts the decisions taken by Tier128.
inline thread_local std::uint64_t fallbacks = 0;

// Verification mode (tests): when `verify` is set, every decision the filter stage takes
// itself is also taken by Tier128 (event comparisons on circles need circle_origins), and
// every circle it forms must enclose Tier128's; `verified` counts the decisions checked,
// `verify_mismatches` those where the filter's answer or enclosure is not Tier128's.
inline thread_local bool verify = false;
inline thread_local std::uint64_t verified = 0, verify_mismatches = 0;
inline void check(bool agrees) {
  ++verified;
  verify_mismatches += !agrees;
}

using Site128 = boost::polygon::detail::site_event<__int128>;
using FilterCircle = boost::polygon::detail::circle_event<FilterFloat>;
using ExactCircle = boost::polygon::detail::circle_event<Tier128::fpt_type>;

// The sites every circle event of the filter stage was formed from, by the tag of its
// lower_x (1, 2, ...).
class CircleOrigins {
 public:
  std::uint32_t add(const Site128& a, const Site128& b, const Site128& d) {
    sites_.push_back({a, b, d});
    return static_cast<std::uint32_t>(sites_.size());
  }
  // Tier128's circle for c, or FilterUndecided when c has no origin.
  ExactCircle exact(const FilterCircle& c) const;

 private:
  std::vector<std::array<Site128, 3>> sites_;
};
inline thread_local CircleOrigins* circle_origins = nullptr;

struct FilterPredicates : boost::polygon::detail::voronoi_predicates<Tier128Filter> {
  using Filter = boost::polygon::detail::voronoi_predicates<Tier128Filter>;
  using Exact = boost::polygon::detail::voronoi_predicates<Tier128>;

  template <class Node>
  class node_comparison_predicate {
   public:
    bool operator()(const Node& a, const Node& b) const {
      bool r;
      try {
        r = filter_(a, b);
      } catch (const FilterUndecided&) {
        ++fallbacks;
        return exact_(a, b);
      }
      if (verify) check(r == exact_(a, b));
      return r;
    }

   private:
    typename Filter::template node_comparison_predicate<Node> filter_;
    typename Exact::template node_comparison_predicate<Node> exact_;
  };

  template <class Site, class Circle>
  class circle_formation_predicate {
   public:
    bool operator()(const Site& s1, const Site& s2, const Site& s3, Circle& circle) {
      try {
        const int corner = corner_index(s1, s2, s3);
        bool formed;
        if (corner != 0) {
          formed = corner_exists(s1, s2, s3, corner);
          if (formed) circle = corner_circle(corner == 1 ? s1 : corner == 2 ? s2 : s3);
        } else {
          formed = filter_(s1, s2, s3, circle);
        }
        if (verify) verify_formation(s1, s2, s3, formed, circle);
        if (!formed) return false;
      } catch (const FilterUndecided&) {
        ++fallbacks;
        ExactCircle c;
        if (!exact_(s1, s2, s3, c)) return false;
        circle.x(enclose(c.x())).y(enclose(c.y())).lower_x(enclose(c.lower_x()));
      }
      if (circle_origins) circle.lower_x(circle.lower_x().tagged(circle_origins->add(s1, s2, s3)));
      return true;
    }

   private:
    // A corner triple: one point site P and two segment sites that both end at P, neither
    // vertical nor the two parallel (1, 2, 3: which site is P; 0: not a corner triple).
    // The circle tangent to both segments' lines through P is the point P itself (radius
    // 0), which Boost's lazy pss evaluates as t = -b / a^2 with b an exact zero computed
    // from rounded square roots: the filter cannot decide the sign of t (which Tier128's
    // rounding noise decides), once per polygon vertex.
    static int corner_index(const Site& s1, const Site& s2, const Site& s3) {
      const int points = !s1.is_segment() + !s2.is_segment() + !s3.is_segment();
      if (points != 1) return 0;
      const int k = !s1.is_segment() ? 1 : !s2.is_segment() ? 2 : 3;
      const Site& p = k == 1 ? s1 : k == 2 ? s2 : s3;
      const Site& a = k == 1 ? s2 : s1;
      const Site& b = k == 3 ? s2 : s3;
      const auto ends_at = [&p](const Site& s) { return s.point0() == p.point0() || s.point1() == p.point0(); };
      if (!ends_at(a) || !ends_at(b) || a.x0() == a.x1() || b.x0() == b.x1() || p.x0() == 0 || p.y0() == 0) return 0;
      const Int256 cross = Int256(a.x1() - a.x0()) * Int256(b.y1() - b.y0()) - Int256(a.y1() - a.y0()) * Int256(b.x1() - b.x0());
      return cross == 0 ? 0 : k;
    }
    // Boost's existence test for the corner triple, on the rotation its formation uses.
    bool corner_exists(const Site& s1, const Site& s2, const Site& s3, int corner) {
      if (corner == 1) return exists_.pss(s1, s2, s3, 1);
      if (corner == 2) return exists_.pss(s2, s1, s3, 2);
      return exists_.pss(s3, s1, s2, 3);
    }
    // Encloses Tier128's circle for a corner triple: Boost's error bookkeeping (assumption
    // (c)) puts Tier128's lazy or exactly recomputed values within 64 ulps of 201 bits
    // (relative 2^-194) of the exact circle (P.x, P.y, lower_x = P.x); two double ulps
    // either side of P's non-zero integer coordinates are wider than that (a zero
    // coordinate, whose relative bound says nothing, is left to the general path).
    static Circle corner_circle(const Site& p) {
      const auto widen = [](const FilterFloat& v) {
        return FilterFloat::enclosing(filter_detail::next_down(filter_detail::next_down(v.lo())),
                                      filter_detail::next_up(filter_detail::next_up(v.hi())));
      };
      const FilterFloat x = widen(FilterFloat(p.x0())), y = widen(FilterFloat(p.y0()));
      return Circle(x, y, x);
    }
    // Verification mode: Tier128 forms the same circle, inside the filter's enclosures.
    void verify_formation(const Site& s1, const Site& s2, const Site& s3, bool formed, const Circle& circle) {
      ExactCircle c;
      const bool exact = exact_(s1, s2, s3, c);
      const auto in = [](const FilterFloat& e, const Tier128::fpt_type& v) {
        return mpfr_cmp_d(v.data(), e.lo()) >= 0 && mpfr_cmp_d(v.data(), e.hi()) <= 0;
      };
      check(exact == formed && (!formed || (in(circle.x(), c.x()) && in(circle.y(), c.y()) && in(circle.lower_x(), c.lower_x()))));
    }
    static FilterFloat enclose(const Tier128::fpt_type& v) {
      return FilterFloat::enclosing(mpfr_get_d(v.data(), MPFR_RNDD), mpfr_get_d(v.data(), MPFR_RNDU));
    }
    typename Filter::template circle_formation_predicate<Site, Circle> filter_;
    typename Filter::template circle_existence_predicate<Site> exists_;
    typename Exact::template circle_formation_predicate<Site, ExactCircle> exact_;
  };

  template <class Site, class Circle>
  class event_comparison_predicate {
   public:
    bool operator()(const Site& a, const Site& b) const { return filter_(a, b); }
    bool operator()(const Site& a, const Circle& c) const {
      bool r;
      try {
        r = filter_(a, c);
      } catch (const FilterUndecided&) {
        return exact_(a, exact(c));
      }
      if (verify && circle_origins) check(r == exact_(a, exact(c, false)));
      return r;
    }
    bool operator()(const Circle& c, const Site& a) const {
      bool r;
      try {
        r = filter_(c, a);
      } catch (const FilterUndecided&) {
        return exact_(exact(c), a);
      }
      if (verify && circle_origins) check(r == exact_(exact(c, false), a));
      return r;
    }
    bool operator()(const Circle& c, const Circle& d) const {
      bool r;
      try {
        r = filter_(c, d);
      } catch (const FilterUndecided&) {
        return exact_(exact(c), exact(d));
      }
      if (verify && circle_origins) check(r == exact_(exact(c, false), exact(d, false)));
      return r;
    }

   private:
    static ExactCircle exact(const Circle& c, bool count = true) {
      if (!circle_origins) throw FilterUndecided{};
      fallbacks += count;
      return circle_origins->exact(c);
    }
    typename Filter::template event_comparison_predicate<Site, Circle> filter_;
    typename Exact::template event_comparison_predicate<Site, ExactCircle> exact_;
  };
};

inline ExactCircle CircleOrigins::exact(const FilterCircle& c) const {
  const std::uint32_t t = c.lower_x().tag();
  if (t == 0 || t > sites_.size()) throw FilterUndecided{};
  const std::array<Site128, 3>& s = sites_[t - 1];
  typename FilterPredicates::Exact::template circle_formation_predicate<Site128, ExactCircle> form;
  ExactCircle out;
  if (!form(s[0], s[1], s[2], out)) throw FilterUndecided{};  // never: the filter formed it
  return out;
}

}  // namespace grassfire::boost_mp

namespace grassfire {
// Found by argument-dependent lookup from Boost's unqualified get_sqrt calls (more
// specialised than Boost's generic one, which calls std::sqrt).
template <unsigned D>
RoundedFloat<D> get_sqrt(const RoundedFloat<D>& x) {
  return sqrt(x);
}
inline FilterFloat get_sqrt(const FilterFloat& x) { return sqrt(x); }
}  // namespace grassfire
