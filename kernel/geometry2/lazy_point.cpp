// lazy_point.cpp -- see lazy_point.h.
#include "geometry2/lazy_point.h"

#include <cmath>

#include "number/exact_sum.h"
#include "number/long_interval.h"

namespace grassfire {

namespace {

// Circumcentre relative to a: with u = b - a, v = c - a and D = 2 (u x v),
// centre = a + ( (v.y |u|^2 - u.y |v|^2) / D, (u.x |v|^2 - v.x |u|^2) / D ).
template <class T, class Point>
void circumcenter_formula(const Point& a, const Point& b, const Point& c, T& x, T& y, T& d) {
  const T ux = T(b.x) - T(a.x), uy = T(b.y) - T(a.y);
  const T vx = T(c.x) - T(a.x), vy = T(c.y) - T(a.y);
  const T uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
  d = T(2) * (ux * vy - uy * vx);
  x = vy * uu - uy * vv;
  y = ux * vv - vx * uu;
}

int sign_of(const mpq_class& q) { return sgn(q); }

}  // namespace

IntervalPoint2 enclose(const ExactPoint2& p) { return {grassfire::enclose(p.x), grassfire::enclose(p.y)}; }

ExactPoint2 exact_circumcenter(const Point2& a, const Point2& b, const Point2& c) {
  struct Q {
    mpq_class x, y;
  };
  const Q qa{a.x, a.y}, qb{b.x, b.y}, qc{c.x, c.y};
  mpq_class x, y, d;
  circumcenter_formula<mpq_class>(qa, qb, qc, x, y, d);
  return {qa.x + x / d, qa.y + y / d};
}

namespace {

// Knuth's TwoSum: s + e == a + b exactly (round to nearest, no contraction).
template <class F>
void two_sum(F a, F b, F& s, F& e) {
  s = a + b;
  const F bv = s - a, av = s - bv;
  e = (a - av) + (b - bv);
}

// Dekker's TwoProduct without FMA: p + e == a * b exactly (barring overflow); the
// splitter is 2^ceil(m/2) + 1 for an m-bit significand.
template <class F>
void two_product(F a, F b, F& p, F& e) {
  const F split = sizeof(F) == sizeof(double) ? F(134217729.0) : F(4294967297.0L);  // 2^27+1, 2^32+1
  p = a * b;
  const F ta = split * a, ah = ta - (ta - a), al = a - ah;
  const F tb = split * b, bh = tb - (tb - b), bl = b - bh;
  e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

// The enclosing interval type of a floating type.
template <class F>
struct IntervalOf;
template <>
struct IntervalOf<double> {
  using type = Interval;
  static constexpr double u = 0x1p-53;
};
template <>
struct IntervalOf<long double> {
  using type = LongInterval;
  static constexpr long double u = 0x1p-64L;
};

template <class F>
struct CircleOf {
  typename IntervalOf<F>::type x, y, radius;
  bool ok;
};

// a / b for b of one sign: the two quotients that bound the result, by the
// signs, instead of the min and max of all four. The same endpoints: rounding to nearest
// is monotone, so the smallest rounded quotient is the rounded smallest one (signed zeros
// aside, which the outward rounding maps alike).
template <class I>
inline __attribute__((always_inline)) I divide_by_signed(const I& a, const I& b) {
  if (!(b.lo > 0) && !(b.hi < 0)) return a / b;  // not of one sign after all: the general division
  // The divisors are selected without branches (the signs of a vary from call to call).
  if (b.lo > 0) return {round_down(a.lo / (a.lo >= 0 ? b.hi : b.lo)), round_up(a.hi / (a.hi >= 0 ? b.lo : b.hi))};
  return {round_down(a.hi / (a.hi >= 0 ? b.hi : b.lo)), round_up(a.lo / (a.lo >= 0 ? b.lo : b.hi))};
}

// The semi-static circumcircle of the header comment of interval_circle, in F.
template <class F>
CircleOf<F> circle_in(const Point2& a, const Point2& b, const Point2& c) {
  using I = typename IntervalOf<F>::type;
  constexpr F u = IntervalOf<F>::u;
  const auto sq = [](const Point2& p, const Point2& q) { return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y); };
  const double ab = sq(a, b), bc = sq(b, c), ca = sq(c, a);
  const Point2 *o = &c, *p = &a, *q = &b;  // o opposite ab
  if (bc >= ab && bc >= ca) {
    o = &a;
    p = &b;
    q = &c;
  } else if (ca >= ab && ca >= bc) {
    o = &b;
    p = &c;
    q = &a;
  }
  F us[2], ue[2], vs[2], ve[2];
  two_sum<F>(p->x, -F(o->x), us[0], ue[0]);
  two_sum<F>(p->y, -F(o->y), us[1], ue[1]);
  two_sum<F>(q->x, -F(o->x), vs[0], ve[0]);
  two_sum<F>(q->y, -F(o->y), vs[1], ve[1]);
  F p1, e1, p2, e2;
  two_product<F>(us[0], vs[1], p1, e1);
  two_product<F>(us[1], vs[0], p2, e2);
  const F first_order = (us[0] * ve[1] + ue[0] * vs[1]) - (us[1] * ve[0] + ue[1] * vs[0]);
  const F d = 2 * (((p1 - p2) + (e1 - e2)) + first_order);
  const F S = 2 * (std::fabs(p1) + std::fabs(p2));
  const F uu = us[0] * us[0] + us[1] * us[1], vv = vs[0] * vs[0] + vs[1] * vs[1];
  const F nx = vs[1] * uu - us[1] * vv, ny = us[0] * vv - vs[0] * uu;
  const F mx = std::fabs(vs[1]) * uu + std::fabs(us[1]) * vv, my = std::fabs(us[0]) * vv + std::fabs(vs[0]) * uu;
  const F bd = std::fabs(d) * (8 * u) + S * (64 * u * u);
  const bool in_range = S > F(0x1p-600) && S < F(0x1p600) && mx + my < F(0x1p900);
  if (!in_range || !(std::fabs(d) > bd)) return {{}, {}, {}, false};
  const I di{round_down(d - bd), round_up(d + bd)};
  const F bx = mx * (32 * u), by = my * (32 * u);
  const I ox = divide_by_signed(I{round_down(nx - bx), round_up(nx + bx)}, di);
  const I oy = divide_by_signed(I{round_down(ny - by), round_up(ny + by)}, di);
  const I oxx{F(o->x), F(o->x)}, oyy{F(o->y), F(o->y)};
  return {oxx + ox, oyy + oy, sqrt(square(ox) + square(oy)), true};
}

}  // namespace

// The circumcircle's centre and radius from the vertex o opposite the longest side (the
// two vectors from it are the shortest sides, which keeps rounding errors relative to the
// triangle's size). u = p - o and v = q - o are exact pairs (leading part + rounding
// error), and the centre's offset from o is (N_x, N_y) / D with
//   D = 2 (u_x v_y - u_y v_x),  N_x = v_y |u|^2 - u_y |v|^2,  N_y = u_x |v|^2 - v_x |u|^2.
// Semi-static error bounds, for unit roundoff u (2^-53 for double, 2^-64 for x87 long
// double; underflow and overflow excluded by the range check):
//  - D: the leading products are exact (TwoProduct); the first-order terms in the
//    rounding errors of u and v are added; the rest is below 16 u^2 S with
//    S = |u_x v_y| + |u_y v_x|, and the roundings add at most 3 u |D|; we use
//    8 u |D| + 64 u^2 S.
//  - N_x, N_y: each monomial (cubic in u, v) carries at most 7 relative errors of size u
//    (3 from the inputs, 4 roundings), so the error is below 7.01 u M with
//    M = |v_y| |u|^2 + |u_y| |v|^2 (resp.); we use 32 u M.
// The final division and translation are done in interval arithmetic. A nearly
// degenerate or extreme triangle falls back to the exact circumcentre.
Circle interval_circle(const Point2& a, const Point2& b, const Point2& c) {
  const CircleOf<double> k = circle_in<double>(a, b, c);
  if (k.ok) return {{k.x, k.y}, k.radius};
  const ExactPoint2 x = exact_circumcenter(a, b, c);
  const mpq_class dx = x.x - mpq_class(a.x), dy = x.y - mpq_class(a.y);
  return {enclose(x), sqrt(grassfire::enclose(mpq_class(dx * dx + dy * dy)))};
}

bool long_circle(const Point2& a, const Point2& b, const Point2& c, LongInterval& x, LongInterval& y,
                 LongInterval& radius) {
  const CircleOf<long double> k = circle_in<long double>(a, b, c);
  x = k.x;
  y = k.y;
  radius = k.radius;
  return k.ok;
}

IntervalPoint2 interval_circumcenter(const Point2& a, const Point2& b, const Point2& c) {
  return interval_circle(a, b, c).center;
}

LazyPoint LazyPoint::input(const Point2& p) {
  LazyPoint l;
  l.a_ = p;
  l.approx_ = {Interval(p.x), Interval(p.y)};
  return l;
}

LazyPoint LazyPoint::circumcenter(const Point2& a, const Point2& b, const Point2& c) {
  return circumcenter(a, b, c, interval_circumcenter(a, b, c));
}

LazyPoint LazyPoint::circumcenter(const Point2& a, const Point2& b, const Point2& c, const IntervalPoint2& approx) {
  LazyPoint l;
  l.is_circumcenter_ = true;
  l.a_ = a;
  l.b_ = b;
  l.c_ = c;
  l.approx_ = approx;
  return l;
}

ExactPoint2 LazyPoint::exact() const {
  if (!is_circumcenter_) return {mpq_class(a_.x), mpq_class(a_.y)};
  return exact_circumcenter(a_, b_, c_);
}

mpq_class LazyPoint::squared_distance(const Point2& p) const {
  const ExactPoint2 e = exact();
  const mpq_class dx = e.x - mpq_class(p.x), dy = e.y - mpq_class(p.y);
  return dx * dx + dy * dy;
}

int orientation(const LazyPoint& p, const LazyPoint& q, const LazyPoint& r, OrientationStats* counters) {
  const IntervalPoint2 &a = p.approx(), &b = q.approx(), &c = r.approx();
  const Interval det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const int s = certified_sign(det);
  if (s != kUndecided) {
    if (counters) ++counters->filtered;
    return s;
  }
  if (counters) ++counters->exact;
  const ExactPoint2 ea = p.exact(), eb = q.exact(), ec = r.exact();
  return sign_of((eb.x - ea.x) * (ec.y - ea.y) - (eb.y - ea.y) * (ec.x - ea.x));
}

}  // namespace grassfire
