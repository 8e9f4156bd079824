// boost_wide_traits.h -- coordinate type traits that run Boost.Polygon's Voronoi builder on
// integer coordinates of up to 62 bits (the wide binary policy of polygon_axis.h; 2.1.1,
// docs/design.md 3). Included by segment_voronoi_boost.cpp only.
//
// Boost's predicates are built on three assumptions about the traits (its "Voronoi
// Predicates" and "advanced tutorial" pages): (a) input coordinates convert to fpt_type
// exactly; (b) orientation tests and the integer parts of circle events are exact integer
// arithmetic (int_x2_type, uint_x2_type, big_int_type wide enough never to overflow);
// (c) fpt_type / efpt_type are IEEE-like with correctly rounded +, -, *, /, sqrt, so that
// the relative-error bookkeeping of robust_fpt (in ulps) holds, and ulp_cmp_type counts
// ulps of that type. The default int32 traits meet them with double (53 bits: 21 guard
// bits beyond the input's 32). These traits meet them for |coordinate| < 2^62 with
// __float128 (113-bit significand: 51 guard bits beyond the input's 62, more than the
// default's 21), 128-bit native integers for int_x2_type and uint_x2_type (Boost forms
// products of two coordinates there, x0 y1 - y0 x1 for segment sites: below 2^125, and
// cross products of coordinate differences: below 2^127 unsigned), and 4096-bit
// fixed-width multiprecision integers for the exact parts of circle events (the int32
// default uses 2048 bits for 32-bit input). Boost's own extended_int is not used: its
// subtraction leaves a leading zero chunk when |a| >> 32 chunks and |b| have one chunk less
// and a - b is small, and later comparisons and conversions read such a value wrong (our
// test against CGAL failed on 48- to 62-bit frames with it, and with its 96-bit int_x2).
// Conversions from big integers round once (top 128 bits exact, then one IEEE rounding).
// Complexity: each predicate is O(1) like the default's, with software quadruple
// precision (measured: experiments/bench_polygon_axis.cpp, "offset" rows).
#pragma once

#include <boost/multiprecision/cpp_int.hpp>
#include <boost/polygon/voronoi_builder.hpp>
#include <quadmath.h>

#include <cstdint>
#include <cstring>

namespace grassfire::boost_wide {

using fpt128 = __float128;

// Inputs must satisfy |x| <= kMaxMagnitude (62 bits).
constexpr std::int64_t kMaxMagnitude = (std::int64_t(1) << 62) - 1;

// 2^e as a __float128, exactly (|e| within the normal exponent range).
inline fpt128 pow2(int e) {
  unsigned __int128 bits = static_cast<unsigned __int128>(e + 16383) << 112;
  fpt128 r;
  std::memcpy(&r, &bits, sizeof r);
  return r;
}

// Ulp distance of __float128 values, as Boost's ulp_comparison<double> does for double:
// the bit patterns mapped to a monotone unsigned scale.
struct UlpComparison {
  enum Result { LESS = -1, EQUAL = 0, MORE = 1 };
  Result operator()(fpt128 a, fpt128 b, unsigned int max_ulps) const {
    const unsigned __int128 sign = static_cast<unsigned __int128>(1) << 127;
    unsigned __int128 ia, ib;
    std::memcpy(&ia, &a, sizeof a);
    std::memcpy(&ib, &b, sizeof b);
    ia = ia < sign ? sign + ia : sign - (ia - sign);  // -0 and +0 both map to `sign`
    ib = ib < sign ? sign + ib : sign - (ib - sign);
    if (ia > ib) return ia - ib <= max_ulps ? EQUAL : MORE;
    return ib - ia <= max_ulps ? EQUAL : LESS;
  }
};

// Exact integers for the circle events: 4096-bit fixed-width (stack) integers, checked: an
// overflow throws std::overflow_error (never met: 2048 bits overflow on 53-bit frames of
// bench_polygon_axis, 4096 do not on 62-bit ones), on which the caller falls back to CGAL.
using BigInt = boost::multiprecision::number<
    boost::multiprecision::cpp_int_backend<4096, 4096, boost::multiprecision::signed_magnitude,
                                           boost::multiprecision::checked, void>,
    boost::multiprecision::et_off>;

// Integers to __float128: exact below 2^113, else one rounding of the top 128 bits.
struct ToFpt {
  template <typename T>
  fpt128 operator()(const T& that) const {
    return static_cast<fpt128>(that);
  }
  // The top 128 bits of |that| read from its limbs (no copy), then one IEEE rounding.
  fpt128 operator()(const BigInt& that) const {
    using u128 = unsigned __int128;
    const auto& b = that.backend();
    const auto* l = b.limbs();
    std::size_t n = b.size();
    while (n > 0 && l[n - 1] == 0) --n;
    if (n == 0) return 0;
    const int z = __builtin_clzll(l[n - 1]);
    const u128 hi = (static_cast<u128>(l[n - 1]) << 64) | (n >= 2 ? l[n - 2] : 0);
    const unsigned long long next = n >= 3 ? l[n - 3] : 0;
    const u128 top = z == 0 ? hi : (hi << z) | (next >> (64 - z));
    const fpt128 r = static_cast<fpt128>(top) * pow2(64 * (static_cast<int>(n) - 2) - z);
    return b.sign() ? -r : r;
  }
};

struct CtypeTraits {
  using int_type = std::int64_t;
  using int_x2_type = __int128;
  using uint_x2_type = unsigned __int128;
  using big_int_type = BigInt;
  using fpt_type = fpt128;
  using efpt_type = fpt128;
  using ulp_cmp_type = UlpComparison;
  using to_fpt_converter_type = ToFpt;
  using to_efpt_converter_type = ToFpt;
};

}  // namespace grassfire::boost_wide

namespace boost::polygon::detail {
// Boost's generic get_sqrt calls std::sqrt, which has no __float128 overload.
template <>
inline grassfire::boost_wide::fpt128 get_sqrt<grassfire::boost_wide::fpt128>(const grassfire::boost_wide::fpt128& x) {
  return sqrtq(x);
}
}  // namespace boost::polygon::detail
