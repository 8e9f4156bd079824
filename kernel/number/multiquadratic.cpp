// multiquadratic.cpp -- see multiquadratic.h.
#include "number/multiquadratic.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "number/mpfr_bounds.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

// The primes below 1000, for stripping square factors from radicands.
const std::vector<unsigned long>& small_primes() {
  static const std::vector<unsigned long> primes = [] {
    std::vector<unsigned long> p;
    for (mpz_class q = 2; q < 1000; mpz_nextprime(q.get_mpz_t(), q.get_mpz_t())) p.push_back(q.get_ui());
    return p;
  }();
  return primes;
}

}  // namespace

ExactSum canonical_roots(const ExactSum& input) {
  ExactSum x = input;
  x.simplify();
  // c sqrt(n/d) = (c/d) sqrt(n d); then p^2 | m gives p sqrt(m / p^2).
  std::vector<SqrtTerm> terms;
  for (const SqrtTerm& t : x.sqrt_terms()) {
    mpz_class m = t.radicand.get_num() * t.radicand.get_den();
    mpq_class c = t.coef / mpq_class(t.radicand.get_den());
    for (unsigned long p : small_primes()) {
      const unsigned long p2 = p * p;
      while (mpz_divisible_ui_p(m.get_mpz_t(), p2)) {
        mpz_divexact_ui(m.get_mpz_t(), m.get_mpz_t(), p2);
        c *= p;
      }
    }
    terms.push_back({c, mpq_class(m)});
  }
  // Radicands still in one square class (large square factors): sqrt(b) = sqrt(ab)/a sqrt(a).
  for (std::size_t i = 0; i < terms.size(); ++i)
    for (std::size_t j = 0; j < terms.size(); ++j) {
      if (i == j || !(terms[i].radicand < terms[j].radicand)) continue;
      if (std::optional<mpq_class> q = rational_sqrt(terms[i].radicand * terms[j].radicand)) {
        terms[j].coef *= *q / terms[i].radicand;
        terms[j].radicand = terms[i].radicand;
      }
    }
  ExactSum r = ExactSum::rational(x.rational_part());
  for (const SqrtTerm& t : terms) r += ExactSum::sqrt_of(t.radicand).scale(t.coef);
  for (const ConstantTerm& t : x.constant_terms()) r += ExactSum::constant(t.value).scale(t.coef);
  r.simplify();
  return r;
}

mpq_class QuadraticBasis::product(std::uint32_t mask) const {
  mpq_class p = 1;
  for (std::size_t j = 0; j < g_.size(); ++j)
    if (mask & (1u << j)) p *= g_[j];
  return p;
}

QuadraticBasis::Root QuadraticBasis::adjoin(const mpq_class& s) {
  if (sgn(s) <= 0) throw std::invalid_argument("quadratic basis: radicand must be positive");
  // sqrt(s) = sqrt(s g_S) / sqrt(g_S) = (q / g_S) sqrt(g_S) when s g_S = q^2.
  for (std::uint32_t mask = 0; mask < (1u << g_.size()); ++mask) {
    const mpq_class gs = product(mask);
    if (std::optional<mpq_class> q = rational_sqrt(s * gs)) return {*q / gs, mask};
  }
  if (g_.size() == kMaxGenerators) throw std::length_error("quadratic basis: too many independent generators");
  g_.push_back(s);
  return {1, 1u << (g_.size() - 1)};
}

Multiquadratic::Multiquadratic(const QuadraticBasis& basis, const mpq_class& q)
    : basis_(&basis), c_(std::size_t{1} << basis.size()) {
  c_[0] = q;
}

Multiquadratic Multiquadratic::root(const QuadraticBasis& basis, const QuadraticBasis::Root& r) {
  Multiquadratic x(basis);
  x.c_[r.mask] = r.coef;
  return x;
}

namespace {
void widen(std::vector<mpq_class>& c, std::size_t size) {
  if (c.size() < size) c.resize(size);
}
}  // namespace

Multiquadratic& Multiquadratic::operator+=(const Multiquadratic& o) {
  widen(c_, o.c_.size());
  for (std::size_t m = 0; m < o.c_.size(); ++m) c_[m] += o.c_[m];
  return *this;
}

Multiquadratic& Multiquadratic::operator-=(const Multiquadratic& o) {
  widen(c_, o.c_.size());
  for (std::size_t m = 0; m < o.c_.size(); ++m) c_[m] -= o.c_[m];
  return *this;
}

Multiquadratic operator*(const Multiquadratic& a, const Multiquadratic& b) {
  Multiquadratic r(*a.basis_);
  widen(r.c_, std::max(a.c_.size(), b.c_.size()));
  for (std::uint32_t x = 0; x < a.c_.size(); ++x) {
    if (sgn(a.c_[x]) == 0) continue;
    for (std::uint32_t y = 0; y < b.c_.size(); ++y) {
      if (sgn(b.c_[y]) == 0) continue;
      // sqrt(g_X) sqrt(g_Y) = g_{X and Y} sqrt(g_{X xor Y})
      r.c_[x ^ y] += a.c_[x] * b.c_[y] * a.basis_->product(x & y);
    }
  }
  return r;
}

Multiquadratic Multiquadratic::conjugate(std::size_t j) const {
  Multiquadratic r = *this;
  for (std::uint32_t m = 0; m < r.c_.size(); ++m)
    if (m & (1u << j)) r.c_[m] = -r.c_[m];
  return r;
}

bool Multiquadratic::is_zero() const {
  for (const mpq_class& c : c_)
    if (sgn(c) != 0) return false;
  return true;
}

Multiquadratic Multiquadratic::inverse() const {
  Multiquadratic num(*basis_, 1), den = *this;
  for (std::size_t j = 0; j < basis_->size(); ++j) {
    const Multiquadratic conj = den.conjugate(j);
    num = num * conj;
    den = den * conj;
  }
  if (sgn(den.c_[0]) == 0) throw std::domain_error("multiquadratic: division by zero");
  for (mpq_class& c : num.c_) c /= den.c_[0];
  return num;
}

ExactSum Multiquadratic::to_exact_sum() const {
  ExactSum s = ExactSum::rational(c_[0]);
  for (std::uint32_t m = 1; m < c_.size(); ++m) {
    if (sgn(c_[m]) == 0) continue;
    ExactSum t = ExactSum::sqrt_of(basis_->product(m));
    s += t.scale(c_[m]);
  }
  return canonical_roots(s);
}

ExactSum root_of_sum(const ExactSum& x) {
  ExactSum s = canonical_roots(x);
  if (std::optional<ExactSum> r = sqrt_of_sum(s)) return *r;
  return ExactSum::constant(sqrt_constant(std::move(s)));
}

// ---- RadicalTable, RadicalNumber ----

namespace {

// The symmetric difference of two keys (the radicals left after sqrt(s)^2 = s) and the
// product of the radicands they share.
RadicalKey multiply_keys(const RadicalKey& a, const RadicalKey& b, const RadicalTable& t, mpq_class* factor) {
  RadicalKey out;
  int i = 0, j = 0;
  auto push = [&](std::uint32_t id) {
    if (out.n == RadicalKey::kMaxRadicals) throw std::length_error("RadicalNumber: too many radicals in one term");
    out.id[out.n++] = id;
  };
  while (i < a.n || j < b.n) {
    if (j == b.n || (i < a.n && a.id[i] < b.id[j])) {
      push(a.id[i++]);
    } else if (i == a.n || b.id[j] < a.id[i]) {
      push(b.id[j++]);
    } else {
      *factor *= t.radicand(a.id[i]);
      ++i;
      ++j;
    }
  }
  return out;
}

}  // namespace

std::uint32_t RadicalTable::add(const mpq_class& s) {
  if (sgn(s) <= 0) throw std::invalid_argument("RadicalTable: radicand must be positive");
  radicand_.push_back(s);
  root_.push_back(sqrt(enclose(s)));
  return static_cast<std::uint32_t>(radicand_.size() - 1);
}

bool operator<(const RadicalKey& a, const RadicalKey& b) {
  if (a.n != b.n) return a.n < b.n;
  return std::lexicographical_compare(a.id.begin(), a.id.begin() + a.n, b.id.begin(), b.id.begin() + b.n);
}

bool operator==(const RadicalKey& a, const RadicalKey& b) {
  return a.n == b.n && std::equal(a.id.begin(), a.id.begin() + a.n, b.id.begin());
}

RadicalNumber::RadicalNumber(const mpq_class& q) {
  if (sgn(q) != 0) terms_.push_back({RadicalKey{}, q});
}

RadicalNumber RadicalNumber::root(const RadicalTable& table, std::uint32_t r, const mpq_class& c) {
  RadicalNumber x;
  x.table_ = &table;
  if (sgn(c) == 0) return x;
  RadicalKey k;
  k.n = 1;
  k.id[0] = r;
  x.terms_.push_back({k, c});
  return x;
}

void RadicalNumber::normalize() {
  std::sort(terms_.begin(), terms_.end(), [](const Term& a, const Term& b) { return a.key < b.key; });
  std::size_t out = 0;
  for (std::size_t i = 0; i < terms_.size();) {
    Term t = std::move(terms_[i]);
    std::size_t j = i + 1;
    for (; j < terms_.size() && terms_[j].key == t.key; ++j) t.coef += terms_[j].coef;
    if (sgn(t.coef) != 0) terms_[out++] = std::move(t);
    i = j;
  }
  terms_.resize(out);
}

RadicalNumber& RadicalNumber::operator+=(const RadicalNumber& o) {
  if (!table_) table_ = o.table_;
  terms_.insert(terms_.end(), o.terms_.begin(), o.terms_.end());
  normalize();
  return *this;
}

RadicalNumber& RadicalNumber::operator-=(const RadicalNumber& o) {
  if (!table_) table_ = o.table_;
  for (const Term& t : o.terms_) terms_.push_back({t.key, -t.coef});
  normalize();
  return *this;
}

RadicalNumber& RadicalNumber::operator*=(const mpq_class& f) {
  if (sgn(f) == 0) {
    terms_.clear();
    return *this;
  }
  for (Term& t : terms_) t.coef *= f;
  return *this;
}

RadicalNumber operator*(const RadicalNumber& a, const RadicalNumber& b) {
  RadicalNumber out;
  out.table_ = a.table_ ? a.table_ : b.table_;
  out.terms_.reserve(a.terms_.size() * b.terms_.size());
  for (const auto& s : a.terms_)
    for (const auto& t : b.terms_) {
      mpq_class factor = s.coef * t.coef;
      RadicalKey k = (s.key.n == 0) ? t.key
                     : (t.key.n == 0) ? s.key
                                      : multiply_keys(s.key, t.key, *out.table_, &factor);
      out.terms_.push_back({k, std::move(factor)});
    }
  out.normalize();
  return out;
}

bool RadicalNumber::rational_value(mpq_class* q) const {
  // simplify() moves square radicands into the rational part; the rest of a sum of
  // square roots is zero exactly when the value is that rational (linear independence
  // of square classes, see exact_sum.h).
  ExactSum s = to_exact_sum();
  s.simplify();
  const mpq_class r = s.rational_part();
  if (!is_zero_sqrt_part(s - ExactSum::rational(r))) return false;
  *q = r;
  return true;
}

ExactSum RadicalNumber::to_exact_sum() const {
  ExactSum s;
  for (const Term& t : terms_) {
    if (t.key.n == 0) {
      s += ExactSum::rational(t.coef);
      continue;
    }
    mpq_class radicand = table_->radicand(t.key.id[0]);
    for (int i = 1; i < t.key.n; ++i) radicand *= table_->radicand(t.key.id[i]);
    s += ExactSum::sqrt_of(radicand).scale(t.coef);
  }
  return s;
}

Interval RadicalNumber::approx() const {
  Interval sum(0.0);
  for (const Term& t : terms_) {
    Interval term = grassfire::enclose(t.coef);
    for (int i = 0; i < t.key.n; ++i) term = term * table_->root(t.key.id[i]);
    sum += term;
  }
  return sum;
}

void RadicalNumber::enclose(mpfr_ptr lo, mpfr_ptr hi) const { to_exact_sum().enclose(lo, hi); }

int sign(const RadicalNumber& x, NumberStats* stats) {
  const Interval a = x.approx();
  if (a.lo > 0) {
    if (stats) ++stats->filter_decided;
    return 1;
  }
  if (a.hi < 0) {
    if (stats) ++stats->filter_decided;
    return -1;
  }
  if (x.is_zero_form()) {
    if (stats) ++stats->filter_decided;
    return 0;
  }
  return sign(x.to_exact_sum(), stats);
}

int sign_plus_root(const RadicalNumber& a, const RadicalNumber& b, const RadicalNumber& c, NumberStats* stats) {
  const int sa = sign(a, stats);
  const int sb = sign(b, stats);
  const int sc = sign(c, stats);
  if (sb == 0 || sc == 0) return sa;
  if (sa == 0 || sa == sb) return sb;
  // Opposite signs: the term of larger magnitude wins; compare a^2 with b^2 c.
  const int d = sign(a * a - b * b * c, stats);
  return d == 0 ? 0 : (d > 0 ? sa : sb);
}

int sign_two_roots(const RadicalNumber& a, const RadicalNumber& c, const RadicalNumber& b, const RadicalNumber& d,
                   NumberStats* stats) {
  const int s1 = sign(c, stats) == 0 ? 0 : sign(a, stats);
  const int s2 = sign(d, stats) == 0 ? 0 : sign(b, stats);
  if (s1 == 0) return s2;
  if (s2 == 0 || s1 == s2) return s1;
  const int e = sign(a * a * c - b * b * d, stats);
  return e == 0 ? 0 : (e > 0 ? s1 : s2);
}

mpq_class approximate_quotient(const RadicalNumber& x, const RadicalNumber& w, long bits, double* error) {
  for (long prec = bits + 64;; prec *= 2) {
    MpfrBounds xs(prec), ws(prec), q(prec);
    x.enclose(xs.lo, xs.hi);
    w.enclose(ws.lo, ws.hi);
    if (mpfr_sgn(ws.lo) <= 0 && mpfr_sgn(ws.hi) >= 0) {
      if (prec > (1L << 16)) throw std::domain_error("approximate_quotient: zero denominator");
      continue;
    }
    // Interval quotient: the extreme values are among the four corner quotients.
    mpfr_t c;
    mpfr_init2(c, prec);
    bool first = true;
    for (mpfr_ptr xv : {xs.lo, xs.hi})
      for (mpfr_ptr wv : {ws.lo, ws.hi}) {
        mpfr_div(c, xv, wv, MPFR_RNDD);
        if (first || mpfr_cmp(c, q.lo) < 0) mpfr_set(q.lo, c, MPFR_RNDD);
        mpfr_div(c, xv, wv, MPFR_RNDU);
        if (first || mpfr_cmp(c, q.hi) > 0) mpfr_set(q.hi, c, MPFR_RNDU);
        first = false;
      }
    mpfr_t mid;
    mpfr_init2(mid, bits);
    mpfr_add(c, q.lo, q.hi, MPFR_RNDN);
    mpfr_div_2ui(c, c, 1, MPFR_RNDN);
    mpfr_set(mid, c, MPFR_RNDN);
    mpq_class out;
    mpfr_get_q(out.get_mpq_t(), mid);
    // error <= max(mid - lo, hi - mid), rounded up.
    mpfr_sub(c, mid, q.lo, MPFR_RNDU);
    double e1 = mpfr_get_d(c, MPFR_RNDU);
    mpfr_sub(c, q.hi, mid, MPFR_RNDU);
    double e2 = mpfr_get_d(c, MPFR_RNDU);
    *error = std::max(e1, e2);
    mpfr_clear(mid);
    mpfr_clear(c);
    return out;
  }
}

}  // namespace grassfire
