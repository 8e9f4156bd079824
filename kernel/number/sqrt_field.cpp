// sqrt_field.cpp -- see sqrt_field.h.
#include "number/sqrt_field.h"

#include <stdexcept>

namespace grassfire {

namespace {

constexpr int kMaxConjugations = 6;

void require_no_constants(const ExactSum& x) {
  if (!x.constant_terms().empty())
    throw std::invalid_argument("sqrt_field: operand has certified constants: " + to_string(x));
}

// q * sqrt(r) as an ExactSum term (r >= 0).
ExactSum root_term(const mpq_class& q, const mpq_class& r) {
  ExactSum s = ExactSum::sqrt_of(r);
  s.scale(q);
  return s;
}

}  // namespace

ExactSum multiply(const ExactSum& a, const ExactSum& b) {
  require_no_constants(a);
  require_no_constants(b);
  ExactSum r = ExactSum::rational(a.rational_part() * b.rational_part());
  for (const SqrtTerm& t : b.sqrt_terms()) r += root_term(a.rational_part() * t.coef, t.radicand);
  for (const SqrtTerm& t : a.sqrt_terms()) {
    r += root_term(t.coef * b.rational_part(), t.radicand);
    for (const SqrtTerm& u : b.sqrt_terms()) {
      const mpq_class radicand = t.radicand * u.radicand;
      if (t.radicand == u.radicand)
        r += ExactSum::rational(t.coef * u.coef * t.radicand);
      else
        r += root_term(t.coef * u.coef, radicand);
    }
  }
  r.simplify();
  return r;
}

std::optional<ExactSum> divide(const ExactSum& a, const ExactSum& b) {
  ExactSum num = a, den = b;
  num.simplify();
  den.simplify();
  for (int round = 0; round <= kMaxConjugations; ++round) {
    if (den.sqrt_terms().empty()) {
      if (sgn(den.rational_part()) == 0) return std::nullopt;
      num.scale(1 / den.rational_part());
      return num;
    }
    if (den.sqrt_terms().size() == 1 && sgn(den.rational_part()) == 0) {
      // x / (c sqrt r) = x sqrt r / (c r)
      const SqrtTerm& t = den.sqrt_terms()[0];
      ExactSum result = multiply(num, ExactSum::sqrt_of(t.radicand));
      result.scale(1 / (t.coef * t.radicand));
      return result;
    }
    // Negate the last root term: (a + b sqrt r)(a - b sqrt r) = a^2 - b^2 r.
    ExactSum conj = ExactSum::rational(den.rational_part());
    for (std::size_t i = 0; i < den.sqrt_terms().size(); ++i) {
      const SqrtTerm& t = den.sqrt_terms()[i];
      conj += root_term(i + 1 == den.sqrt_terms().size() ? mpq_class(-t.coef) : t.coef, t.radicand);
    }
    num = multiply(num, conj);
    den = multiply(den, conj);
  }
  return std::nullopt;
}

std::optional<mpq_class> rational_sqrt(const mpq_class& q) {
  if (sgn(q) < 0) return std::nullopt;
  const mpz_class& n = q.get_num();
  const mpz_class& d = q.get_den();
  if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return std::nullopt;
  mpz_class rn, rd;
  mpz_sqrt(rn.get_mpz_t(), n.get_mpz_t());
  mpz_sqrt(rd.get_mpz_t(), d.get_mpz_t());
  return make_rational(rn, rd);
}

std::optional<ExactSum> sqrt_of_sum(const ExactSum& input) {
  ExactSum x = input;
  x.simplify();
  require_no_constants(x);
  if (x.sqrt_terms().empty()) {
    if (sgn(x.rational_part()) < 0) return std::nullopt;
    return ExactSum::sqrt_of(x.rational_part());
  }
  if (x.sqrt_terms().size() != 1) return std::nullopt;
  // sqrt(u + v sqrt m) = sqrt((u + w)/2) + sign(v) sqrt((u - w)/2), w = sqrt(u^2 - v^2 m).
  const mpq_class& u = x.rational_part();
  const mpq_class v = x.sqrt_terms()[0].coef;
  const mpq_class& m = x.sqrt_terms()[0].radicand;
  const std::optional<mpq_class> w = rational_sqrt(u * u - v * v * m);
  if (!w || sgn(u) < 0) return std::nullopt;
  ExactSum r = ExactSum::sqrt_of((u + *w) / 2);
  ExactSum second = ExactSum::sqrt_of((u - *w) / 2);
  if (sgn(v) < 0) second.scale(-1);
  r += second;
  r.simplify();
  return r;
}

int exact_sign(const ExactSum& x, NumberStats* stats) {
  require_no_constants(x);
  return sign(x, stats);
}

RootSum operator+(const RootSum& a, const RootSum& b) { return RootSum(a.v + b.v); }
RootSum operator-(const RootSum& a, const RootSum& b) { return RootSum(a.v - b.v); }
RootSum operator-(const RootSum& a) { return RootSum(ExactSum() - a.v); }
RootSum operator*(const RootSum& a, const RootSum& b) { return RootSum(multiply(a.v, b.v)); }
RootSum operator/(const RootSum& a, const RootSum& b) {
  std::optional<ExactSum> q = divide(a.v, b.v);
  if (!q) throw NestedRadical{};
  return RootSum(std::move(*q));
}
RootSum sqrt(const RootSum& a) {
  std::optional<ExactSum> r = sqrt_of_sum(a.v);
  if (!r) throw NestedRadical{};
  return RootSum(std::move(*r));
}

}  // namespace grassfire
