// parabolic_arc.cpp -- see parabolic_arc.h.
#include "number/parabolic_arc.h"

#include <cmath>
#include <limits>
#include <string>

#include "number/mpfr_bounds.h"

namespace grassfire {

namespace {

// ln 2 lies between the double nearest to it (which is below it) and the next double.
const Interval kLn2{0x1.62e42fefa39efp-1, 0x1.62e42fefa39f0p-1};

// atanh(t) for 0 <= t <= 0.2: sum_{j < 14} t^(2j+1)/(2j+1), plus the remainder
// 0 <= R <= t^29 / (29 (1 - t^2)), which is below 2^-70 t for t <= 0.2.
Interval atanh_small(const Interval& t) {
  const Interval t2 = square(t);
  Interval sum = 0.0;
  Interval power = t;
  for (int j = 0; j < 14; ++j) {
    // power / Interval(c) for the point c = 2j + 1 > 0, with two of its four quotients:
    // correctly rounded division by c > 0 is monotone, so power.lo / c is the least.
    const double c = 2.0 * j + 1.0;
    sum += Interval{round_down(power.lo / c), round_up(power.hi / c)};
    power = power * t2;
  }
  const Interval remainder = power / (Interval(29.0) * (Interval(1.0) - t2));
  return {sum.lo, (sum + remainder).hi};
}

// log(x) for a double x > 0, as x = m 2^k with m in [sqrt(1/2), sqrt(2)):
// log x = k ln2 + 2 atanh((m - 1) / (m + 1)), |t| <= 0.1716.
Interval log_point(double x) {
  int k = 0;
  double m = std::frexp(x, &k);  // m in [0.5, 1), exact
  if (m < 0x1.6a09e667f3bcdp-1) {
    m *= 2.0;  // exact
    --k;
  }
  const Interval t = (Interval(m) - Interval(1.0)) / (Interval(m) + Interval(1.0));
  Interval a;
  if (t.lo >= 0) {
    a = atanh_small(t);
  } else {
    const Interval neg = atanh_small(-t);
    a = -neg;
  }
  return Interval(static_cast<double>(k)) * kLn2 + Interval(2.0) * a;
}

// asinh(x) for a double x >= 0: log1p(x + x^2 / (1 + sqrt(1 + x^2))), which keeps the
// relative accuracy for small x.
Interval asinh_nonnegative(double x) {
  if (x == 0) return 0.0;
  const Interval xi(x);
  const Interval x2 = square(xi);
  const Interval w = xi + x2 / (Interval(1.0) + sqrt(Interval(1.0) + x2));
  return log1p_enclosure(w);
}

}  // namespace

Interval log1p_enclosure(const Interval& w) {
  // Small w: log1p(w) = 2 atanh(w / (2 + w)), monotone in w, t <= 0.2 for w <= 0.5.
  if (w.hi <= 0.5) {
    const Interval t = w / (Interval(2.0) + w);
    return Interval(2.0) * atanh_small({std::fmax(0.0, t.lo), t.hi});
  }
  const Interval one_plus = Interval(1.0) + w;
  return {log_point(one_plus.lo).lo, log_point(one_plus.hi).hi};
}

Interval asinh_enclosure(const Interval& z) {
  // asinh is increasing and odd.
  auto lower = [](double x) { return x >= 0 ? asinh_nonnegative(x).lo : -asinh_nonnegative(-x).hi; };
  auto upper = [](double x) { return x >= 0 ? asinh_nonnegative(x).hi : -asinh_nonnegative(-x).lo; };
  return {lower(z.lo), upper(z.hi)};
}

Interval parabola_arc_primitive(const Interval& xi, const Interval& p) {
  const Interval z = xi / p;
  return half(xi * sqrt(Interval(1.0) + square(z))) + half(p * asinh_enclosure(z));
}

Ball parabola_arc_primitive(const Ball& xi, const Ball& p) {
  const Ball z = xi / p;
  const Ball half_ball(0.5);
  return half_ball * xi * sqrt(Ball(1.0) + z * z) + half_ball * p * asinh(z);
}

namespace {

Ball ball_of_sum(const ExactSum& x, long bits) {
  MpfrBounds b(bits);
  x.enclose(b.lo, b.hi);
  Ball r;
  arb_set_interval_mpfr(r.get(), b.lo, b.hi, bits);
  return r;
}

// x = y exactly, certified (an uncertified zero of sign() is not a proof).
bool proved_equal(const ExactSum& x, const ExactSum& y) {
  NumberStats st;
  return sign(x - y, &st) == 0 && st.uncertified_zero == 0;
}

class ArcPrimitive : public CertifiedConstant {
 public:
  ArcPrimitive(ExactSum p, ExactSum xi)
      : p_(std::move(p)), xi_(std::move(xi)), id_("S[" + to_string(p_) + ";" + to_string(xi_) + "]") {}
  // In Arb at rising working precision until the ball is accurate to the bits asked for;
  // the last ball is kept (the burning asks for the same constants repeatedly).
  void enclose(mpfr_ptr lo, mpfr_ptr hi) const override {
    const long bits = mpfr_get_prec(lo);
    if (accuracy_ < bits) {
      for (long work = bits + 64;; work *= 2) {
        BallPrecision guard(work);
        value_ = parabola_arc_primitive(ball_of_sum(xi_, work), ball_of_sum(p_, work));
        accuracy_ = value_.accuracy_bits();
        if (accuracy_ >= bits || work > 16 * (bits + 64)) break;
      }
    }
    value_.to_mpfr(lo, hi);
  }
  std::string identity() const override { return id_; }
  std::optional<bool> equals(const CertifiedConstant& other) const override {
    const auto* o = dynamic_cast<const ArcPrimitive*>(&other);
    if (!o || !proved_equal(p_, o->p_) || !proved_equal(xi_, o->xi_)) return std::nullopt;
    return true;
  }

 private:
  ExactSum p_, xi_;
  std::string id_;
  mutable Ball value_;
  mutable long accuracy_ = -1;
};

}  // namespace

std::shared_ptr<const CertifiedConstant> arc_primitive_constant(ExactSum p, ExactSum xi) {
  p.simplify();
  xi.simplify();
  return std::make_shared<ArcPrimitive>(std::move(p), std::move(xi));
}

}  // namespace grassfire
