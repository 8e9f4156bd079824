// sampled_geometry.cpp -- see sampled_geometry.h.
#include "medial2/sampled/sampled_geometry.h"

#include "geometry2/lazy_point.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

namespace grassfire {

namespace {

// x = mantissa * 2^exponent with an integer mantissa (exact for every finite double).
void split(double x, mpz_class& mantissa, long& exponent) {
  if (x == 0.0) {
    mantissa = 0;
    exponent = LONG_MAX;
    return;
  }
  int e = 0;
  const double f = std::frexp(x, &e);  // x = f * 2^e, 0.5 <= |f| < 1
  mantissa = static_cast<long>(std::ldexp(f, 53));  // |value| < 2^53 fits a long
  exponent = static_cast<long>(e) - 53;
}

mpz_class scaled(const mpz_class& m, long e, long base) {
  if (m == 0) return 0;
  mpz_class r;
  mpz_mul_2exp(r.get_mpz_t(), m.get_mpz_t(), static_cast<mp_bitcnt_t>(e - base));
  return r;
}

// Encloses sqrt(num) / |den| * 2^scale into [lo, hi].
void enclose_root(const mpz_class& num, const mpz_class& den, long scale, mpfr_ptr lo, mpfr_ptr hi) {
  mpz_class d = abs(den);
  mpfr_set_z(lo, num.get_mpz_t(), MPFR_RNDD);
  mpfr_set_z(hi, num.get_mpz_t(), MPFR_RNDU);
  mpfr_sqrt(lo, lo, MPFR_RNDD);
  mpfr_sqrt(hi, hi, MPFR_RNDU);
  mpfr_div_z(lo, lo, d.get_mpz_t(), MPFR_RNDD);
  mpfr_div_z(hi, hi, d.get_mpz_t(), MPFR_RNDU);
  mpfr_mul_2si(lo, lo, scale, MPFR_RNDD);
  mpfr_mul_2si(hi, hi, scale, MPFR_RNDU);
}

ExactSum exact_root(const mpz_class& num, const mpz_class& den, long scale) {
  mpq_class r(num, den * den);
  r.canonicalize();
  if (scale >= 0)
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(2 * scale));
  else
    mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-2 * scale));
  return ExactSum::sqrt_of(r);
}

}  // namespace

IntegerCircumcenter integer_circumcenter(const Point2& a, const Point2& b, const Point2& c) {
  const double coords[6] = {a.x, a.y, b.x, b.y, c.x, c.y};
  mpz_class m[6];
  long e[6], base = LONG_MAX;
  for (int i = 0; i < 6; ++i) {
    split(coords[i], m[i], e[i]);
    base = std::min(base, e[i]);
  }
  if (base == LONG_MAX) base = 0;
  mpz_class v[6];
  for (int i = 0; i < 6; ++i) v[i] = scaled(m[i], e[i], base);
  const mpz_class ux = v[2] - v[0], uy = v[3] - v[1], wx = v[4] - v[0], wy = v[5] - v[1];
  const mpz_class uu = ux * ux + uy * uy, ww = wx * wx + wy * wy;
  IntegerCircumcenter r;
  r.d = 2 * (ux * wy - uy * wx);
  r.x = wy * uu - uy * ww;
  r.y = ux * ww - wx * uu;
  r.cx = v[0] * r.d + r.x;
  r.cy = v[1] * r.d + r.y;
  r.exponent = base;
  return r;
}

SampledVoronoiGeometry::SampledVoronoiGeometry(std::vector<Point2> samples,
                                               std::vector<std::array<std::uint32_t, 3>> node_triangles,
                                               std::vector<std::pair<std::uint32_t, std::uint32_t>> edge_ends)
    : samples_(std::move(samples)), triangles_(std::move(node_triangles)), ends_(std::move(edge_ends)) {}

const IntegerCircumcenter& SampledVoronoiGeometry::center(std::uint32_t node) const {
  auto it = centers_.find(node);
  if (it == centers_.end()) {
    const auto& t = triangles_[node];
    it = centers_.emplace(node, integer_circumcenter(samples_[t[0]], samples_[t[1]], samples_[t[2]])).first;
  }
  return it->second;
}

SampledVoronoiGeometry::SquaredLength SampledVoronoiGeometry::squared_radius(std::uint32_t node) const {
  const IntegerCircumcenter& c = center(node);
  return {c.x * c.x + c.y * c.y, c.d, c.exponent};
}

SampledVoronoiGeometry::SquaredLength SampledVoronoiGeometry::squared_length(std::uint32_t edge) const {
  const IntegerCircumcenter& p = center(ends_[edge].first);
  const IntegerCircumcenter& q = center(ends_[edge].second);
  const long base = std::min(p.exponent, q.exponent);
  const mpz_class pd = scaled(q.d, p.exponent, base), qd = scaled(p.d, q.exponent, base);
  // (cp / dp) 2^ep - (cq / dq) 2^eq = (cp dq 2^(ep-b) - cq dp 2^(eq-b)) / (dp dq) * 2^b
  const mpz_class nx = p.cx * pd - q.cx * qd, ny = p.cy * pd - q.cy * qd;
  return {nx * nx + ny * ny, p.d * q.d, base};
}

ExactSum SampledVoronoiGeometry::exact_radius(std::uint32_t node) const {
  const SquaredLength s = squared_radius(node);
  return exact_root(s.num, s.den, s.scale);
}

ExactSum SampledVoronoiGeometry::exact_length(std::uint32_t edge) const {
  const SquaredLength s = squared_length(edge);
  return exact_root(s.num, s.den, s.scale);
}

void SampledVoronoiGeometry::enclose_radius(std::uint32_t node, mpfr_ptr lo, mpfr_ptr hi) const {
  const SquaredLength s = squared_radius(node);
  enclose_root(s.num, s.den, s.scale, lo, hi);
}

void SampledVoronoiGeometry::enclose_length(std::uint32_t edge, mpfr_ptr lo, mpfr_ptr hi) const {
  const SquaredLength s = squared_length(edge);
  enclose_root(s.num, s.den, s.scale, lo, hi);
}

const SampledVoronoiGeometry::LongCircle& SampledVoronoiGeometry::long_circle_of(std::uint32_t node) const {
  LongCircle& c = long_circles_[node];
  if (c.state == 0) {
    const auto& t = triangles_[node];
    c.state = long_circle(samples_[t[0]], samples_[t[1]], samples_[t[2]], c.x, c.y, c.radius) ? 1 : 2;
  }
  return c;
}

LongInterval SampledVoronoiGeometry::enclose_radius_long(std::uint32_t node) const {
  const LongCircle& c = long_circle_of(node);
  return c.state == 1 ? c.radius : MedialGeometry::enclose_radius_long(node);
}

LongInterval SampledVoronoiGeometry::enclose_length_long(std::uint32_t edge) const {
  const LongCircle& a = long_circle_of(ends_[edge].first);
  const LongCircle& b = long_circle_of(ends_[edge].second);
  if (a.state != 1 || b.state != 1) return MedialGeometry::enclose_length_long(edge);
  return sqrt(square(a.x - b.x) + square(a.y - b.y));
}

std::string SampledVoronoiGeometry::description() const {
  return "Voronoi axis of " + std::to_string(samples_.size()) + " boundary samples";
}

}  // namespace grassfire
