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

class SqrtOfSum : public CertifiedConstant {
 public:
  // The identity is built once: ExactSum::simplify asks for it on every merge.
  explicit SqrtOfSum(ExactSum x) : x_(std::move(x)), id_("sqrt[" + to_string(x_) + "]") {}
  void enclose(mpfr_ptr lo, mpfr_ptr hi) const override {
    x_.enclose(lo, hi);
    if (mpfr_sgn(lo) < 0) mpfr_set_zero(lo, 1);
    mpfr_sqrt(lo, lo, MPFR_RNDD);
    mpfr_sqrt(hi, hi, MPFR_RNDU);
  }
  std::string identity() const override { return id_; }
  const ExactSum* radicand() const override { return &x_; }
  std::optional<bool> equals(const CertifiedConstant& other) const override {
    const auto* o = dynamic_cast<const SqrtOfSum*>(&other);
    if (!o) return std::nullopt;
    return is_zero_sqrt_part(x_ - o->x_);
  }

 private:
  ExactSum x_;
  std::string id_;
};

}  // namespace

namespace {

constexpr unsigned kSmallPrimes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97};

// Divides squares of small primes out of m; returns the product of their roots.
mpz_class take_small_squares(mpz_class& m) {
  mpz_class root = 1;
  for (unsigned p : kSmallPrimes) {
    const unsigned long p2 = static_cast<unsigned long>(p) * p;
    while (m != 0 && mpz_divisible_ui_p(m.get_mpz_t(), p2)) {
      mpz_divexact_ui(m.get_mpz_t(), m.get_mpz_t(), p2);
      root *= p;
    }
  }
  return root;
}

// c sqrt(n / d) = (c s / d) sqrt(m) with n d = s^2 m, m freed of small squares.
ExactSum normalised_roots(const ExactSum& x) {
  ExactSum out = ExactSum::rational(x.rational_part());
  for (const SqrtTerm& t : x.sqrt_terms()) {
    mpz_class m = t.radicand.get_num() * t.radicand.get_den();
    const mpz_class root = take_small_squares(m);
    ExactSum term = ExactSum::sqrt_of(mpq_class(m));
    term.scale(t.coef * make_rational(root, t.radicand.get_den()));
    out += term;
  }
  out.simplify();
  return out;
}

}  // namespace

ExactSum sqrt_term(const ExactSum& input) {
  require_no_constants(input);
  ExactSum x = normalised_roots(input);
  if (std::optional<ExactSum> r = sqrt_of_sum(x)) return *r;
  // x = g x' with x' of coprime integer coefficients and g = a / b; sqrt(g) = sqrt(a b) / b.
  mpz_class num = 0, den = 1;
  auto visit = [&](const mpq_class& c) {
    mpz_gcd(num.get_mpz_t(), num.get_mpz_t(), c.get_num().get_mpz_t());
    mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), c.get_den().get_mpz_t());
  };
  visit(x.rational_part());
  for (const SqrtTerm& t : x.sqrt_terms()) visit(t.coef);
  if (num == 0) return ExactSum();
  const mpq_class g = make_rational(num, den);
  x.scale(1 / g);
  mpz_class m = g.get_num() * g.get_den();
  const mpz_class root = take_small_squares(m);
  x.scale(mpq_class(m));
  ExactSum out = ExactSum::constant(sqrt_constant(std::move(x)));
  out.scale(make_rational(root, g.get_den()));
  return out;
}

std::shared_ptr<const CertifiedConstant> sqrt_constant(ExactSum x) {
  require_no_constants(x);
  x.simplify();
  return std::make_shared<SqrtOfSum>(std::move(x));
}

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

ExactSum multiply_radical(const ExactSum& a, const ExactSum& b) {
  require_no_constants(b);
  ExactSum plain = ExactSum::rational(a.rational_part());
  for (const SqrtTerm& t : a.sqrt_terms()) plain += root_term(t.coef, t.radicand);
  ExactSum r = multiply(plain, b);
  for (const ConstantTerm& c : a.constant_terms()) {
    const ExactSum* e = c.value->radicand();
    if (!e) throw std::invalid_argument("sqrt_field: not a square root of a sum: " + c.value->identity());
    ExactSum kept = ExactSum::constant(c.value);
    kept.scale(c.coef * b.rational_part());
    r += kept;
    for (const SqrtTerm& t : b.sqrt_terms()) {
      ExactSum radicand = *e;
      ExactSum term = sqrt_term(radicand.scale(t.radicand));
      r += term.scale(c.coef * t.coef);
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

ExactSum multiply_simplified(const ExactSum& a, const ExactSum& b) {
  ExactSum r = multiply(a, b);
  r.simplify();
  return r;
}

ExactSum scaled(ExactSum a, const mpq_class& c) {
  a.scale(c);
  return a;
}

}  // namespace grassfire
