// filtered_predicates3.cpp -- interval filter, then exact rationals (see header).
#include "geometry3/filtered_predicates3.h"

#include <cfloat>
#include <climits>
#include <cmath>

namespace grassfire {
namespace {

IntervalPoint3 minus(const IntervalPoint3& a, const IntervalPoint3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Interval idot(const IntervalPoint3& a, const IntervalPoint3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
IntervalPoint3 icross(const IntervalPoint3& a, const IntervalPoint3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Is the canonical rational q exactly a normal double (at most 53 significant bits, a
// power-of-two denominator, |q| in [DBL_MIN, DBL_MAX])? Then get_d returns q itself.
bool is_normal_double(const mpq_class& q, double d) {
  if (sgn(q) == 0) return true;
  if (mpz_popcount(q.get_den_mpz_t()) != 1) return false;
  const mpz_srcptr num = q.get_num_mpz_t();
  const std::size_t bits = mpz_sizeinbase(num, 2) - mpz_scan1(num, 0);
  return bits <= 53 && std::fabs(d) >= DBL_MIN && std::isfinite(d);
}

// x = m 2^e with |m| < 2^53 (x a finite double); e = INT_MAX for x = 0.
void split_double(double x, std::int64_t& m, int& e) {
  if (x == 0) {
    m = 0, e = INT_MAX;
    return;
  }
  int k = 0;
  const double f = std::frexp(x, &k);
  m = static_cast<std::int64_t>(std::ldexp(f, 53));
  e = k - 53;
}

int bit_length(unsigned __int128 s) {
  const auto high = static_cast<std::uint64_t>(s >> 64), low = static_cast<std::uint64_t>(s);
  if (high) return 128 - __builtin_clzll(high);
  return low ? 64 - __builtin_clzll(low) : 0;
}

// The squared distance of two points with double coordinates (given as point intervals),
// truncated to a double as
// mpq_class::get_d truncates, in 128-bit integers when the six coordinates lie within 2^9
// of one another in exponent; false when they do not or the result is not a normal double.
bool truncated_squared_distance(const IntervalPoint3& a, const IntervalPoint3& b, double& out) {
  std::int64_t m[6];
  int e[6], low = INT_MAX;
  const double c[6] = {a[0].lo, a[1].lo, a[2].lo, b[0].lo, b[1].lo, b[2].lo};
  for (int i = 0; i < 6; ++i) {
    split_double(c[i], m[i], e[i]);
    low = std::min(low, e[i]);
  }
  if (low == INT_MAX) return false;
  std::int64_t scaled[6];
  for (int i = 0; i < 6; ++i) {
    if (m[i] != 0 && e[i] - low > 9) return false;
    scaled[i] = m[i] == 0 ? 0 : m[i] * (std::int64_t{1} << (e[i] - low));  // |.| < 2^62
  }
  unsigned __int128 sum = 0;
  for (int i = 0; i < 3; ++i) {
    const std::int64_t d = scaled[3 + i] - scaled[i];  // |d| < 2^63
    const auto u = static_cast<unsigned __int128>(d < 0 ? -static_cast<__int128>(d) : static_cast<__int128>(d));
    sum += u * u;  // < 2^126 each, < 2^128 in all
  }
  if (sum == 0) return false;
  const int length = bit_length(sum), shift = length > 53 ? length - 53 : 0;
  const long exponent = static_cast<long>(length) - 1 + 2L * low;  // of the leading bit
  if (exponent < -1022 || exponent > 1023) return false;
  out = std::ldexp(static_cast<double>(static_cast<std::uint64_t>(sum >> shift)), shift + 2 * low);
  return true;
}

}  // namespace

CoordinateEnclosure enclose_coordinate(const mpq_class& q) {
  CoordinateEnclosure e;
  const double d = q.get_d();  // truncated: q lies within one ulp of d
  if (!std::isfinite(d) || std::fabs(d) > 0x1p200) return e;
  e.usable = true;
  e.is_double = is_normal_double(q, d);
  e.value = e.is_double ? Interval(d) : Interval(round_down(d), round_up(d));
  return e;
}

FilteredPoints::FilteredPoints(std::size_t n, const std::function<const ExactPoint3&(std::size_t)>& points)
    : exact_(n), box_(n), usable_(n), double_(n) {
  for (std::size_t i = 0; i < n; ++i) {
    const ExactPoint3& p = points(i);
    exact_[i] = &p;
    const CoordinateEnclosure c[3] = {enclose_coordinate(p.x), enclose_coordinate(p.y), enclose_coordinate(p.z)};
    box_[i] = {c[0].value, c[1].value, c[2].value};
    usable_[i] = c[0].usable && c[1].usable && c[2].usable;
    double_[i] = c[0].is_double && c[1].is_double && c[2].is_double;
  }
}

FilteredPoints::FilteredPoints(const std::vector<ExactPoint3>& points)
    : FilteredPoints(points.size(), [&](std::size_t i) -> const ExactPoint3& { return points[i]; }) {}

int FilteredPoints::compare_lex(std::uint32_t i, std::uint32_t j) const {
  const ExactPoint3 &p = *exact_[i], &q = *exact_[j];
  const mpq_class* pc[3] = {&p.x, &p.y, &p.z};
  const mpq_class* qc[3] = {&q.x, &q.y, &q.z};
  const bool filter = usable_[i] && usable_[j];
  bool exact_used = false;
  int result = 0;
  for (int k = 0; k < 3 && result == 0; ++k) {
    const Interval &a = box_[i][k], &b = box_[j][k];
    if (filter && a.hi < b.lo) result = -1;
    else if (filter && a.lo > b.hi) result = 1;
    else if (filter && a.is_point() && b.is_point() && a.lo == b.lo) continue;
    else {
      exact_used = true;
      const int c = cmp(*pc[k], *qc[k]);
      result = c < 0 ? -1 : c > 0 ? 1 : 0;
    }
  }
  ++(exact_used ? counts_.exact : counts_.filtered);
  return result;
}

bool FilteredPoints::collinear(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
  if (usable_[a] && usable_[b] && usable_[c]) {
    const IntervalPoint3 n = icross(minus(box_[b], box_[a]), minus(box_[c], box_[a]));
    for (const Interval& x : n)
      if (x.lo > 0 || x.hi < 0) {
        ++counts_.filtered;
        return false;
      }
  }
  ++counts_.exact;
  return grassfire::collinear(*exact_[a], *exact_[b], *exact_[c]);
}

int FilteredPoints::orientation(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
  const auto exact = [&] { return grassfire::orientation(*exact_[a], *exact_[b], *exact_[c], *exact_[d]); };
  if (!(usable_[a] && usable_[b] && usable_[c] && usable_[d])) return sign(Interval(-1, 1), exact);
  const IntervalPoint3 u = minus(box_[b], box_[a]), v = minus(box_[c], box_[a]), w = minus(box_[d], box_[a]);
  return sign(idot(icross(u, v), w), exact);
}

double FilteredPoints::distance(std::uint32_t a, std::uint32_t b) const {
  double d2 = 0;
  if (double_[a] && double_[b] && truncated_squared_distance(box_[a], box_[b], d2)) {
    ++counts_.filtered;
    return std::sqrt(d2);
  }
  ++counts_.exact;
  return std::sqrt(squared_distance(*exact_[a], *exact_[b]).get_d());
}

FilteredEdgeOrder::FilteredEdgeOrder(const FilteredPoints& points, std::uint32_t a, std::uint32_t b)
    : p_(points), a_(a), b_(b), usable_(points.usable(a) && points.usable(b)), d_(minus(points.box(b), points.box(a))) {}

int FilteredEdgeOrder::det_sign(std::uint32_t r, std::uint32_t s) const {
  if (r == s) return 0;  // det(d, r, r) vanishes identically
  const auto exact = [&] {
    const ExactPoint3& a = p_.exact(a_);
    return sgn(dot(p_.exact(b_) - a, cross(p_.exact(r) - a, p_.exact(s) - a)));
  };
  if (!(usable_ && p_.usable(r) && p_.usable(s))) return p_.sign(Interval(-1, 1), exact);
  const IntervalPoint3& a = p_.box(a_);
  return p_.sign(idot(d_, icross(minus(p_.box(r), a), minus(p_.box(s), a))), exact);
}

int FilteredEdgeOrder::projected_dot_sign(std::uint32_t r, std::uint32_t s) const {
  if (r == s) return self_projected_sign(r);
  const auto exact = [&] {
    const ExactPoint3& a = p_.exact(a_);
    const ExactPoint3 d = p_.exact(b_) - a, ra = p_.exact(r) - a, sa = p_.exact(s) - a;
    return sgn(mpq_class(dot(d, d) * dot(ra, sa) - dot(ra, d) * dot(sa, d)));
  };
  if (!(usable_ && p_.usable(r) && p_.usable(s))) return p_.sign(Interval(-1, 1), exact);
  const IntervalPoint3& a = p_.box(a_);
  const IntervalPoint3 ra = minus(p_.box(r), a), sa = minus(p_.box(s), a);
  return p_.sign(idot(d_, d_) * idot(ra, sa) - idot(ra, d_) * idot(sa, d_), exact);
}

// |d|^2 |r|^2 - (r . d)^2 = |d x r|^2 (Lagrange): positive iff d x r has a nonzero component.
int FilteredEdgeOrder::self_projected_sign(std::uint32_t r) const {
  const auto exact = [&] {
    const ExactPoint3& a = p_.exact(a_);
    return is_zero(cross(p_.exact(b_) - a, p_.exact(r) - a)) ? 0 : 1;
  };
  if (!(usable_ && p_.usable(r))) return p_.sign(Interval(-1, 1), exact);
  const IntervalPoint3 c = icross(d_, minus(p_.box(r), p_.box(a_)));
  for (const Interval& x : c)
    if (x.lo > 0 || x.hi < 0) return p_.sign(Interval(1), exact);
  return p_.sign(Interval(-1, 1), exact);
}

// 0 for angles in [0, pi) from ref, 1 for [pi, 2 pi) (EdgeAngularOrder::half), given
// det = det_sign(ref, u).
int FilteredEdgeOrder::half(std::uint32_t ref, std::uint32_t u, int det) const {
  if (det != 0) return det > 0 ? 0 : 1;
  return projected_dot_sign(ref, u) > 0 ? 0 : 1;
}

int FilteredEdgeOrder::compare(std::uint32_t ref, std::uint32_t u, std::uint32_t w) const {
  const int du = det_sign(ref, u), dw = det_sign(ref, w);
  const int hu = half(ref, u, du), hw = half(ref, w, dw);
  if (hu != hw) return hu < hw ? -1 : 1;
  // det(u, w), reusing det(ref, .) when u or w is ref (det is antisymmetric).
  const int s = u == ref ? dw : w == ref ? -du : det_sign(u, w);
  return s > 0 ? -1 : s < 0 ? 1 : 0;
}

FilteredPlane::FilteredPlane(const FilteredPoints& points, std::uint32_t a, std::uint32_t b, std::uint32_t c)
    : p_(points), v_{a, b, c}, usable_(points.usable(a) && points.usable(b) && points.usable(c)) {
  if (usable_) u_ = minus(points.box(b), points.box(a)), w_ = minus(points.box(c), points.box(a));
}

int FilteredPlane::side(std::uint32_t p) const {
  if (p == v_[0] || p == v_[1] || p == v_[2]) return 0;
  const auto exact = [&] {
    if (!exact_ready_) {
      const ExactPoint3& a = p_.exact(v_[0]);
      normal_ = cross(p_.exact(v_[1]) - a, p_.exact(v_[2]) - a);
      offset_ = dot(normal_, a);
      exact_ready_ = true;
    }
    const int c = cmp(dot(normal_, p_.exact(p)), offset_);
    return c < 0 ? -1 : c > 0 ? 1 : 0;
  };
  if (!(usable_ && p_.usable(p))) return p_.sign(Interval(-1, 1), exact);
  return p_.sign(idot(icross(u_, w_), minus(p_.box(p), p_.box(v_[0]))), exact);
}

}  // namespace grassfire
