// radical_number.cpp -- see radical_number.h.
#include "number/radical_number.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "number/mpfr_bounds.h"

namespace grassfire {

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
