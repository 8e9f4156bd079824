// ball.h -- rigorous real ball arithmetic (a thin value type over Arb's arb_t).
//
// Computes: enclosures mid +- rad of real values; every operation returns a ball that
// contains the exact result for all points of its operands (Arb's guarantee, including
// sqrt and asinh). Used where a value is algebraic of higher degree or transcendental
// (Voronoi vertices of segments, parabolic arc lengths: docs/exactness.md) and the double
// Interval filter is too wide: the same formula is evaluated at more bits.
// Contract: operands of sqrt are >= 0 somewhere in the ball (the result encloses the
// root of the non-negative part, like Interval's sqrt); division by a ball containing
// zero gives an infinite ball (never a wrong one).
// Precision: the working precision in bits is per thread (BallPrecision guard).
// Complexity: O(M(p)) per operation at p bits.
// Why Arb: rigorous ball arithmetic with correctly bounded elementary functions (asinh),
// well maintained (Debian libflint-arb-dev); writing our own would add risk, not value.
#pragma once

#include <arb.h>
#include <gmpxx.h>
#include <mpfr.h>

#include "number/interval.h"

namespace grassfire {

// Sets the working precision of Ball operations on this thread for its lifetime.
class BallPrecision {
 public:
  explicit BallPrecision(long bits);
  ~BallPrecision();
  BallPrecision(const BallPrecision&) = delete;
  BallPrecision& operator=(const BallPrecision&) = delete;
  static long bits();

 private:
  long saved_;
};

class Ball {
 public:
  Ball() { arb_init(v_); }
  Ball(double exact) {  // NOLINT: every double converts exactly
    arb_init(v_);
    arb_set_d(v_, exact);
  }
  Ball(const Ball& o) {
    arb_init(v_);
    arb_set(v_, o.v_);
  }
  Ball& operator=(const Ball& o) {
    arb_set(v_, o.v_);
    return *this;
  }
  ~Ball() { arb_clear(v_); }
  static Ball from_interval(const Interval& i);

  arb_srcptr get() const { return v_; }
  arb_ptr get() { return v_; }

  friend Ball operator+(const Ball& a, const Ball& b);
  friend Ball operator-(const Ball& a, const Ball& b);
  friend Ball operator-(const Ball& a);
  friend Ball operator*(const Ball& a, const Ball& b);
  friend Ball operator/(const Ball& a, const Ball& b);
  Ball& operator+=(const Ball& o) { return *this = *this + o; }
  Ball& operator-=(const Ball& o) { return *this = *this - o; }

  // Certified sign: +1 / -1 when the ball excludes zero, 0 when it is exactly zero,
  // kUndecided otherwise.
  int sign() const;
  // Outward-rounded double enclosure.
  Interval to_interval() const;
  // lo <= value <= hi, each rounded outwards at its own precision.
  void to_mpfr(mpfr_ptr lo, mpfr_ptr hi) const;
  // Number of accurate relative bits (Arb's estimate; for choosing precision only).
  long accuracy_bits() const { return arb_rel_accuracy_bits(v_); }

 private:
  arb_t v_;
};

// A rational as a ball at the current precision (an enclosure of q, exact when q is dyadic
// and fits).
Ball ball_of(const mpq_class& q);
// A ball that holds min(a, b) for every a in x and b in y (Arb's arb_min).
Ball min(const Ball& x, const Ball& y);
// A ball that holds both x and y (Arb's arb_union).
Ball hull(const Ball& x, const Ball& y);
Ball sqrt(const Ball& a);
Ball asinh(const Ball& a);
// The common part of two enclosures of the same value (both valid, so the result is).
Ball intersect(const Ball& a, const Ball& b);
Interval intersect(const Interval& a, const Interval& b);

}  // namespace grassfire
