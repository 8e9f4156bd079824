// multiquadratic.cpp -- see multiquadratic.h.
#include "number/multiquadratic.h"

#include <memory>
#include <optional>
#include <stdexcept>

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

}  // namespace grassfire
