// closest_point3.cpp -- see closest_point3.h.
#include "geometry3/closest_point3.h"

namespace grassfire {
namespace {

IntervalPoint3 minus(const IntervalPoint3& a, const IntervalPoint3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Interval dot(const IntervalPoint3& a, const IntervalPoint3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The certified sign of x, or nothing (throws the query back to the caller's bounds).
struct Undecided {};
int sign_of(const Interval& x) {
  const int s = certified_sign(x);
  if (s == kUndecided) throw Undecided{};
  return s;
}

// |p - (a + v ab + w ac)|^2 with p - a = ap.
Interval squared_distance_at(const IntervalPoint3& ap, const IntervalPoint3& ab, const IntervalPoint3& ac,
                             const Interval& v, const Interval& w) {
  Interval sum(0.0);
  for (int i = 0; i < 3; ++i) sum += square(ap[i] - v * ab[i] - w * ac[i]);
  return sum;
}

// The exact branch structure of closest_weights, with its weights (v, w of b and c) enclosed.
std::array<Interval, 2> enclosed_weights(const IntervalPoint3& a, const IntervalPoint3& b, const IntervalPoint3& c,
                                         const IntervalPoint3& p) {
  const IntervalPoint3 ab = minus(b, a), ac = minus(c, a), ap = minus(p, a);
  const Interval d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (sign_of(d1) <= 0 && sign_of(d2) <= 0) return {Interval(0.0), Interval(0.0)};
  const IntervalPoint3 bp = minus(p, b);
  const Interval d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (sign_of(d3) >= 0 && sign_of(d4 - d3) <= 0) return {Interval(1.0), Interval(0.0)};
  const Interval vc = d1 * d4 - d3 * d2;
  if (sign_of(vc) <= 0 && sign_of(d1) >= 0 && sign_of(d3) <= 0) return {d1 / (d1 - d3), Interval(0.0)};
  const IntervalPoint3 cp = minus(p, c);
  const Interval d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (sign_of(d6) >= 0 && sign_of(d5 - d6) <= 0) return {Interval(0.0), Interval(1.0)};
  const Interval vb = d5 * d2 - d1 * d6;
  if (sign_of(vb) <= 0 && sign_of(d2) >= 0 && sign_of(d6) <= 0) return {Interval(0.0), d2 / (d2 - d6)};
  const Interval va = d3 * d6 - d5 * d4;
  if (sign_of(va) <= 0 && sign_of(d4 - d3) >= 0 && sign_of(d5 - d6) >= 0) {
    const Interval w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {Interval(1.0) - w, w};
  }
  const Interval denom = va + vb + vc;
  if (sign_of(denom) == 0) throw Undecided{};
  return {vb / denom, vc / denom};
}

}  // namespace

std::array<mpq_class, 3> closest_weights_reference(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c,
                                                   const ExactPoint3& p) {
  const ExactPoint3 ab = b - a, ac = c - a, ap = p - a;
  const mpq_class d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (sgn(d1) <= 0 && sgn(d2) <= 0) return {1, 0, 0};
  const ExactPoint3 bp = p - b;
  const mpq_class d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (sgn(d3) >= 0 && d4 <= d3) return {0, 1, 0};
  const mpq_class vc = d1 * d4 - d3 * d2;
  if (sgn(vc) <= 0 && sgn(d1) >= 0 && sgn(d3) <= 0) {
    const mpq_class v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const ExactPoint3 cp = p - c;
  const mpq_class d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (sgn(d6) >= 0 && d5 <= d6) return {0, 0, 1};
  const mpq_class vb = d5 * d2 - d1 * d6;
  if (sgn(vb) <= 0 && sgn(d2) >= 0 && sgn(d6) <= 0) {
    const mpq_class w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const mpq_class va = d3 * d6 - d5 * d4;
  if (sgn(va) <= 0 && sgn(d4 - d3) >= 0 && sgn(d5 - d6) >= 0) {
    const mpq_class w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const mpq_class denom = va + vb + vc;
  const mpq_class v = vb / denom, w = vc / denom;
  return {1 - v - w, v, w};
}

// The same region tests on the points scaled by a common denominator L of their twelve
// coordinates: integers, so no gcd per operation. Every d_i scales by L^2 and every v_i by
// L^4, which changes no sign and no ratio, so the weights are those of the reference.
std::array<mpq_class, 3> closest_weights(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c,
                                         const ExactPoint3& p) {
  const std::array<const ExactPoint3*, 4> pts = {&a, &b, &c, &p};
  mpz_class scale = 1;
  for (const ExactPoint3* x : pts)
    for (const mpq_class* q : {&x->x, &x->y, &x->z}) mpz_lcm(scale.get_mpz_t(), scale.get_mpz_t(), q->get_den_mpz_t());
  std::array<std::array<mpz_class, 3>, 4> z;  // a, b, c, p times scale
  for (int i = 0; i < 4; ++i) {
    int k = 0;
    for (const mpq_class* q : {&pts[i]->x, &pts[i]->y, &pts[i]->z}) {
      mpz_divexact(z[i][k].get_mpz_t(), scale.get_mpz_t(), q->get_den_mpz_t());
      z[i][k] *= q->get_num();
      ++k;
    }
  }
  const auto diff_dot = [&](int u0, int u1, int w0, int w1) {  // (z[u1] - z[u0]) . (z[w1] - z[w0])
    mpz_class sum = 0;
    for (int k = 0; k < 3; ++k) sum += (z[u1][k] - z[u0][k]) * (z[w1][k] - z[w0][k]);
    return sum;
  };
  const auto ratio = [](const mpz_class& num, const mpz_class& den) {
    mpq_class r(num, den);
    r.canonicalize();
    return r;
  };
  const mpz_class d1 = diff_dot(0, 1, 0, 3), d2 = diff_dot(0, 2, 0, 3);
  if (sgn(d1) <= 0 && sgn(d2) <= 0) return {1, 0, 0};
  const mpz_class d3 = diff_dot(0, 1, 1, 3), d4 = diff_dot(0, 2, 1, 3);
  if (sgn(d3) >= 0 && d4 <= d3) return {0, 1, 0};
  const mpz_class vc = d1 * d4 - d3 * d2;
  if (sgn(vc) <= 0 && sgn(d1) >= 0 && sgn(d3) <= 0) {
    const mpq_class v = ratio(d1, d1 - d3);
    return {1 - v, v, 0};
  }
  const mpz_class d5 = diff_dot(0, 1, 2, 3), d6 = diff_dot(0, 2, 2, 3);
  if (sgn(d6) >= 0 && d5 <= d6) return {0, 0, 1};
  const mpz_class vb = d5 * d2 - d1 * d6;
  if (sgn(vb) <= 0 && sgn(d2) >= 0 && sgn(d6) <= 0) {
    const mpq_class w = ratio(d2, d2 - d6);
    return {1 - w, 0, w};
  }
  const mpz_class va = d3 * d6 - d5 * d4;
  if (sgn(va) <= 0 && sgn(d4 - d3) >= 0 && sgn(d5 - d6) >= 0) {
    const mpq_class w = ratio(d4 - d3, (d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const mpz_class denom = va + vb + vc;
  const mpq_class v = ratio(vb, denom), w = ratio(vc, denom);
  return {1 - v - w, v, w};
}

std::optional<Interval> closest_squared_distance(const IntervalPoint3& a, const IntervalPoint3& b,
                                                 const IntervalPoint3& c, const IntervalPoint3& p) {
  try {
    const auto [v, w] = enclosed_weights(a, b, c, p);
    return squared_distance_at(minus(p, a), minus(b, a), minus(c, a), v, w);
  } catch (const Undecided&) {
    return std::nullopt;
  }
}

std::optional<Interval> closest_squared_distance(const IntervalPoint3& a, const IntervalPoint3& b,
                                                 const IntervalPoint3& p) {
  const IntervalPoint3 d = minus(b, a), ap = minus(p, a);
  const Interval num = dot(ap, d), den = dot(d, d);
  const int below = certified_sign(num), above = certified_sign(num - den);
  if (below == kUndecided || above == kUndecided || certified_sign(den) != 1) return std::nullopt;
  const Interval s = below <= 0 ? Interval(0.0) : above >= 0 ? Interval(1.0) : num / den;
  const IntervalPoint3 zero{Interval(0.0), Interval(0.0), Interval(0.0)};
  return squared_distance_at(ap, d, zero, s, Interval(0.0));
}

}  // namespace grassfire
