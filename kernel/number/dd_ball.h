// dd_ball.h -- rigorous balls with a double-double centre (about 106 bits).
//
// Computes: enclosures mid +- rad of real values, where mid = hi + lo is a double-double
// (an unevaluated sum of two doubles) and rad a double. Every operation returns a ball that
// contains the exact result for all points of its operands. The stage between double
// intervals and Arb: Voronoi circles of segment sites on integer polygons lose up to 45
// of the 53 bits of a double interval to cancellation (measured on the benchmark's wavy
// polygon: most PPS circles keep 10-15 bits), which then sent a quarter of a million
// atoms to Arb; in double-double the same formulas keep 60 bits and more, at a few times
// the cost of a double interval instead of a hundred.
// Error bounds: the centre operations are the double-word algorithms analysed by Joldes,
// Muller and Popescu ("Tight and rigorous error bounds for basic building blocks of
// double-word arithmetic", ACM TOMS 2017): relative error at most 3u^2 (addition, their
// AccurateDWPlusDW), 7u^2 (multiplication with Dekker's product, DWTimesDW1 without FMA)
// and 15u^2 (division, DWDivDW2), u = 2^-53; the square root (one Newton step on the
// double root, with an exact residual) errs by less than 4u^2. Each result's radius gets
// |mid| 2^-96 >= 128 u^2 |mid| on top of the propagated radii, and every double operation
// on radii is rounded upwards (round_up of interval.h), so the ball is rigorous.
// Contract: finite operands of magnitude below 2^900 and above 2^-900 or zero (Dekker's
// splitting and the error terms must neither overflow nor underflow); rounding to
// nearest, no FMA contraction (-ffp-contract=off). Division by a ball containing zero and
// the square root of a ball reaching below zero give the whole line / the root of the
// non-negative part, never a wrong ball.
// Complexity: O(1), about 10-30 floating-point operations per operation.
#pragma once

#include <cmath>
#include <limits>

#include "number/interval.h"
#include "number/long_interval.h"

namespace grassfire {

class DDBall {
 public:
  DDBall() = default;
  DDBall(double exact) : hi_(exact) {}  // NOLINT: every double converts exactly

  static DDBall whole() {
    DDBall b;
    b.rad_ = std::numeric_limits<double>::infinity();
    return b;
  }
  bool is_finite() const { return rad_ < std::numeric_limits<double>::infinity(); }
  double mid() const { return hi_; }
  double radius() const { return rad_; }
  // +1 / -1 when the ball excludes zero, 0 when it is exactly zero, kUndecided otherwise.
  int sign() const {
    if (!is_finite()) return kUndecided;
    if (hi_ == 0 && lo_ == 0 && rad_ == 0) return 0;
    const Interval i = to_interval();
    return i.lo > 0 ? 1 : i.hi < 0 ? -1 : kUndecided;
  }
  // The outward-rounded double enclosure.
  Interval to_interval() const {
    if (!is_finite()) return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return {round_down(hi_ + round_down(lo_ - rad_)), round_up(hi_ + round_up(lo_ + rad_))};
  }
  // The outward-rounded x87 enclosure (64-bit significands: the 80-bit stage of
  // burn-time comparisons, burn2/burn_times.h).
  LongInterval to_long_interval() const {
    if (!is_finite()) return {-std::numeric_limits<long double>::infinity(), std::numeric_limits<long double>::infinity()};
    const long double h = hi_;
    return {round_down(h + static_cast<long double>(round_down(lo_ - rad_))),
            round_up(h + static_cast<long double>(round_up(lo_ + rad_)))};
  }
  // rad <= |mid| 2^-bits.
  bool accurate_to(int bits) const { return is_finite() && rad_ <= std::ldexp(std::fabs(hi_), -bits); }

  friend DDBall operator+(const DDBall& a, const DDBall& b) {
    DDBall r;
    add(a.hi_, a.lo_, b.hi_, b.lo_, r.hi_, r.lo_);
    r.rad_ = r.finish(round_up(a.rad_ + b.rad_));
    return r;
  }
  friend DDBall operator-(const DDBall& a) {
    DDBall r = a;
    r.hi_ = -a.hi_;
    r.lo_ = -a.lo_;
    return r;
  }
  friend DDBall operator-(const DDBall& a, const DDBall& b) { return a + (-b); }
  friend DDBall operator*(const DDBall& a, const DDBall& b) {
    DDBall r;
    mul(a.hi_, a.lo_, b.hi_, b.lo_, r.hi_, r.lo_);
    // |xy - ab| <= |a| ry + |b| rx + rx ry, with |a| <= |a.hi| (1 + 2^-52).
    const double ma = round_up(std::fabs(a.hi_) * (1 + 0x1p-52)), mb = round_up(std::fabs(b.hi_) * (1 + 0x1p-52));
    const double spread = round_up(round_up(round_up(ma * b.rad_) + round_up(mb * a.rad_)) + round_up(a.rad_ * b.rad_));
    r.rad_ = r.finish(spread);
    return r;
  }
  friend DDBall operator/(const DDBall& a, const DDBall& b) {
    // |b| >= |b.hi| (1 - 2^-52) - rb must stay positive.
    const double mb = round_down(round_down(std::fabs(b.hi_) * (1 - 0x1p-52)) - b.rad_);
    if (!(mb > 0) || !a.is_finite()) return whole();
    DDBall r;
    div(a.hi_, a.lo_, b.hi_, b.lo_, r.hi_, r.lo_);
    // |x/y - a/b| <= (rx + |a/b| ry) / |y| for |x - a| <= rx, |y - b| <= ry.
    const double q = round_up(std::fabs(r.hi_) * (1 + 0x1p-50));
    r.rad_ = r.finish(round_up(round_up(a.rad_ + round_up(q * b.rad_)) / mb));
    return r;
  }
  friend DDBall sqrt(const DDBall& a) {
    if (!a.is_finite()) return whole();
    const double low = round_down(round_down(a.hi_ * (1 - 0x1p-52)) - a.rad_);
    DDBall r;
    if (!(low > 0)) {
      // The root of the non-negative part: [0, sqrt(a + ra)].
      const double top = round_up(std::sqrt(round_up(round_up(std::fabs(a.hi_) * (1 + 0x1p-52)) + a.rad_)));
      r.hi_ = 0.5 * top;
      r.rad_ = round_up(0.5 * top * (1 + 0x1p-50));
      return r;
    }
    dd_sqrt(a.hi_, a.lo_, r.hi_, r.lo_);
    // |sqrt x - sqrt a| = |x - a| / (sqrt x + sqrt a) <= ra / sqrt(a - ra).
    r.rad_ = r.finish(round_up(a.rad_ / round_down(std::sqrt(low))));
    return r;
  }
  // The ball with the smaller radius (both enclose the same value).
  friend DDBall intersect(const DDBall& a, const DDBall& b) { return a.rad_ <= b.rad_ ? a : b; }

 private:
  // rad = propagated spread plus the centre's rounding error, |mid| 2^-96.
  double finish(double spread) const {
    if (!(std::fabs(hi_) < 0x1p900) || !(spread < std::numeric_limits<double>::infinity()))
      return std::numeric_limits<double>::infinity();
    return round_up(spread + std::ldexp(std::fabs(hi_), -96) + 0x1p-1000);
  }
  static void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bv = s - a, av = s - bv;
    e = (a - av) + (b - bv);
  }
  static void fast_two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    e = b - (s - a);
  }
  static void two_prod(double a, double b, double& p, double& e) {
    constexpr double kSplit = 134217729.0;  // 2^27 + 1
    p = a * b;
    const double ta = kSplit * a, ah = ta - (ta - a), al = a - ah;
    const double tb = kSplit * b, bh = tb - (tb - b), bl = b - bh;
    e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
  }
  static void add(double ah, double al, double bh, double bl, double& rh, double& rl) {
    double s, e, t, f;
    two_sum(ah, bh, s, e);
    two_sum(al, bl, t, f);
    e += t;
    fast_two_sum(s, e, s, e);
    e += f;
    fast_two_sum(s, e, rh, rl);
  }
  static void mul(double ah, double al, double bh, double bl, double& rh, double& rl) {
    double p, e;
    two_prod(ah, bh, p, e);
    e += ah * bl + al * bh;
    fast_two_sum(p, e, rh, rl);
  }
  static void div(double ah, double al, double bh, double bl, double& rh, double& rl) {
    // DWDivDW2: q = ah / bh, r = a - q b exactly enough, then one correction.
    const double q = ah / bh;
    double p, pe;
    mul(bh, bl, q, 0.0, p, pe);
    double dh, dl;
    add(ah, al, -p, -pe, dh, dl);
    const double c = dh / bh;
    fast_two_sum(q, c, rh, rl);
  }
  static void dd_sqrt(double ah, double al, double& rh, double& rl) {
    const double x = std::sqrt(ah);
    double p, pe;
    two_prod(x, x, p, pe);
    double dh, dl;
    add(ah, al, -p, -pe, dh, dl);
    fast_two_sum(x, dh / (2 * x), rh, rl);
  }

  double hi_ = 0, lo_ = 0, rad_ = 0;
};

}  // namespace grassfire
