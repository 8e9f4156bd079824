// ball.cpp -- see ball.h.
#include "number/ball.h"

#include <algorithm>
#include <limits>

namespace grassfire {

namespace {
thread_local long t_ball_bits = 128;
}

BallPrecision::BallPrecision(long bits) : saved_(t_ball_bits) { t_ball_bits = bits; }
BallPrecision::~BallPrecision() { t_ball_bits = saved_; }
long BallPrecision::bits() { return t_ball_bits; }

Ball Ball::from_interval(const Interval& i) {
  Ball r;
  arf_t lo, hi;
  arf_init(lo);
  arf_init(hi);
  arf_set_d(lo, i.lo);
  arf_set_d(hi, i.hi);
  arb_set_interval_arf(r.v_, lo, hi, 2 * 53 + 8);
  arf_clear(lo);
  arf_clear(hi);
  return r;
}

Ball operator+(const Ball& a, const Ball& b) {
  Ball r;
  arb_add(r.v_, a.v_, b.v_, t_ball_bits);
  return r;
}
Ball operator-(const Ball& a, const Ball& b) {
  Ball r;
  arb_sub(r.v_, a.v_, b.v_, t_ball_bits);
  return r;
}
Ball operator-(const Ball& a) {
  Ball r;
  arb_neg(r.v_, a.v_);
  return r;
}
Ball operator*(const Ball& a, const Ball& b) {
  Ball r;
  arb_mul(r.v_, a.v_, b.v_, t_ball_bits);
  return r;
}
Ball operator/(const Ball& a, const Ball& b) {
  Ball r;
  arb_div(r.v_, a.v_, b.v_, t_ball_bits);
  return r;
}

Ball ball_of(const mpq_class& q) {
  const long bits = BallPrecision::bits();
  mpfr_t lo, hi;
  mpfr_init2(lo, bits);
  mpfr_init2(hi, bits);
  mpfr_set_q(lo, q.get_mpq_t(), MPFR_RNDD);
  mpfr_set_q(hi, q.get_mpq_t(), MPFR_RNDU);
  Ball b;
  arb_set_interval_mpfr(b.get(), lo, hi, bits);
  mpfr_clear(lo);
  mpfr_clear(hi);
  return b;
}

Ball min(const Ball& x, const Ball& y) {
  Ball z;
  arb_min(z.get(), x.get(), y.get(), BallPrecision::bits());
  return z;
}

Ball hull(const Ball& x, const Ball& y) {
  Ball z;
  arb_union(z.get(), x.get(), y.get(), BallPrecision::bits());
  return z;
}

Ball sqrt(const Ball& a) {
  Ball r;
  arb_sqrtpos(r.get(), a.get(), t_ball_bits);
  return r;
}

Ball asinh(const Ball& a) {
  Ball r;
  arb_asinh(r.get(), a.get(), t_ball_bits);
  return r;
}

Ball intersect(const Ball& a, const Ball& b) {
  Ball r;
  if (!arb_intersection(r.get(), a.get(), b.get(), t_ball_bits)) return a;  // cannot happen for valid enclosures
  return r;
}

Interval intersect(const Interval& a, const Interval& b) {
  return {std::fmax(a.lo, b.lo), std::fmin(a.hi, b.hi)};
}

int Ball::sign() const {
  if (arb_is_zero(v_)) return 0;
  if (arb_is_positive(v_)) return 1;
  if (arb_is_negative(v_)) return -1;
  return kUndecided;
}

Interval Ball::to_interval() const {
  if (!arb_is_finite(v_)) {
    const double inf = std::numeric_limits<double>::infinity();
    return {-inf, inf};
  }
  arf_t lo, hi;
  arf_init(lo);
  arf_init(hi);
  arb_get_lbound_arf(lo, v_, 64);
  arb_get_ubound_arf(hi, v_, 64);
  const Interval r{arf_get_d(lo, ARF_RND_FLOOR), arf_get_d(hi, ARF_RND_CEIL)};
  arf_clear(lo);
  arf_clear(hi);
  return r;
}

void Ball::to_mpfr(mpfr_ptr lo, mpfr_ptr hi) const {
  arf_t l, h;
  arf_init(l);
  arf_init(h);
  const long bits = std::max<long>(mpfr_get_prec(lo), mpfr_get_prec(hi)) + 16;
  arb_get_lbound_arf(l, v_, bits);
  arb_get_ubound_arf(h, v_, bits);
  arf_get_mpfr(lo, l, MPFR_RNDD);
  arf_get_mpfr(hi, h, MPFR_RNDU);
  arf_clear(l);
  arf_clear(h);
}

}  // namespace grassfire
