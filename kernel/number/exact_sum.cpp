// exact_sum.cpp -- see exact_sum.h.
#include "number/exact_sum.h"

#include "number/mpfr_bounds.h"
#include "number/root_separation.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <unordered_map>

namespace grassfire {

namespace {


// Adds c * [slo, shi] (with shi >= slo >= 0) to [lo, hi], rounding outwards.
void add_scaled(mpfr_ptr lo, mpfr_ptr hi, const mpq_class& c, mpfr_srcptr slo, mpfr_srcptr shi) {
  MpfrBounds t(mpfr_get_prec(lo));
  if (sgn(c) >= 0) {
    mpfr_mul_q(t.lo, slo, c.get_mpq_t(), MPFR_RNDD);
    mpfr_mul_q(t.hi, shi, c.get_mpq_t(), MPFR_RNDU);
  } else {
    mpfr_mul_q(t.lo, shi, c.get_mpq_t(), MPFR_RNDD);
    mpfr_mul_q(t.hi, slo, c.get_mpq_t(), MPFR_RNDU);
  }
  mpfr_add(lo, lo, t.lo, MPFR_RNDD);
  mpfr_add(hi, hi, t.hi, MPFR_RNDU);
}


int mpfr_sign(const ExactSum& x, long bits) {
  MpfrBounds b(bits);
  x.enclose(b.lo, b.hi);
  return b.sign();
}

// Odd primes used for Legendre-symbol fingerprints of square classes.
const std::vector<unsigned long>& fingerprint_primes() {
  static const std::vector<unsigned long> primes = [] {
    std::vector<unsigned long> p;
    for (unsigned long n = 3; p.size() < 96; n += 2) {
      bool prime = true;
      for (unsigned long d = 3; d * d <= n; d += 2)
        if (n % d == 0) prime = false;
      if (prime) p.push_back(n);
    }
    return p;
  }();
  return primes;
}

// Terms c * sqrt(m) with square-free-unknown positive integers m, none a perfect square.
struct IntegerRootTerm {
  mpq_class coef;
  mpz_class m;
};

// Fingerprint: Legendre symbols (m/p) over primes dividing none of the m. Two integers
// whose product is a perfect square have equal symbols at every such prime.
std::vector<std::uint64_t> fingerprints(const std::vector<IntegerRootTerm>& terms) {
  std::vector<unsigned long> chosen;
  for (unsigned long p : fingerprint_primes()) {
    bool divides_none = std::none_of(terms.begin(), terms.end(), [p](const IntegerRootTerm& t) {
      return mpz_divisible_ui_p(t.m.get_mpz_t(), p) != 0;
    });
    if (divides_none) chosen.push_back(p);
    if (chosen.size() == 64) break;
  }
  std::vector<std::uint64_t> fp(terms.size(), 0);
  for (std::size_t i = 0; i < terms.size(); ++i) {
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      mpz_class p = chosen[k];
      if (mpz_legendre(terms[i].m.get_mpz_t(), p.get_mpz_t()) == 1) fp[i] |= (std::uint64_t{1} << k);
    }
  }
  return fp;
}

}  // namespace

const Interval& CertifiedConstant::approx() const {
  if (!has_approx_) {
    MpfrBounds b(53);
    enclose(b.lo, b.hi);
    approx_ = {mpfr_get_d(b.lo, MPFR_RNDD), mpfr_get_d(b.hi, MPFR_RNDU)};
    has_approx_ = true;
  }
  return approx_;
}

Interval enclose(const mpq_class& q) {
  MpfrBounds b(53);
  mpfr_set_q(b.lo, q.get_mpq_t(), MPFR_RNDD);
  mpfr_set_q(b.hi, q.get_mpq_t(), MPFR_RNDU);
  return {mpfr_get_d(b.lo, MPFR_RNDD), mpfr_get_d(b.hi, MPFR_RNDU)};
}

void NumberStats::merge(const NumberStats& o) {
  filter_decided += o.filter_decided;
  extended_decided += o.extended_decided;
  mpfr_decided += o.mpfr_decided;
  exact_zero += o.exact_zero;
  separation_decided += o.separation_decided;
  class_zero += o.class_zero;
  uncertified_zero += o.uncertified_zero;
  max_bits_used = std::max(max_bits_used, o.max_bits_used);
}

ExactSum ExactSum::rational(const mpq_class& q) {
  ExactSum s;
  s.rational_ = q;
  return s;
}

ExactSum ExactSum::sqrt_of(const mpq_class& radicand) {
  ExactSum s;
  if (sgn(radicand) != 0) s.sqrt_.push_back({1, radicand});
  return s;
}

ExactSum ExactSum::constant(std::shared_ptr<const CertifiedConstant> c) {
  ExactSum s;
  s.constants_.push_back({1, std::move(c)});
  return s;
}

ExactSum& ExactSum::operator+=(const ExactSum& o) {
  rational_ += o.rational_;
  sqrt_.insert(sqrt_.end(), o.sqrt_.begin(), o.sqrt_.end());
  constants_.insert(constants_.end(), o.constants_.begin(), o.constants_.end());
  return *this;
}

ExactSum& ExactSum::operator-=(const ExactSum& o) {
  rational_ -= o.rational_;
  for (const SqrtTerm& t : o.sqrt_) sqrt_.push_back({-t.coef, t.radicand});
  for (const ConstantTerm& t : o.constants_) constants_.push_back({-t.coef, t.value});
  return *this;
}

ExactSum& ExactSum::scale(const mpq_class& f) {
  rational_ *= f;
  for (SqrtTerm& t : sqrt_) t.coef *= f;
  for (ConstantTerm& t : constants_) t.coef *= f;
  return *this;
}

void ExactSum::simplify() {
  std::sort(sqrt_.begin(), sqrt_.end(),
            [](const SqrtTerm& a, const SqrtTerm& b) { return a.radicand < b.radicand; });
  std::vector<SqrtTerm> merged;
  for (const SqrtTerm& t : sqrt_) {
    if (!merged.empty() && merged.back().radicand == t.radicand)
      merged.back().coef += t.coef;
    else
      merged.push_back(t);
  }
  sqrt_.clear();
  for (SqrtTerm& t : merged) {
    if (sgn(t.coef) == 0 || sgn(t.radicand) == 0) continue;
    mpz_class num = t.radicand.get_num(), den = t.radicand.get_den();
    if (mpz_perfect_square_p(num.get_mpz_t()) && mpz_perfect_square_p(den.get_mpz_t())) {
      mpz_class rn, rd;
      mpz_sqrt(rn.get_mpz_t(), num.get_mpz_t());
      mpz_sqrt(rd.get_mpz_t(), den.get_mpz_t());
      rational_ += t.coef * make_rational(rn, rd);
    } else {
      sqrt_.push_back(std::move(t));
    }
  }
  std::map<std::string, ConstantTerm> by_identity;
  for (const ConstantTerm& t : constants_) {
    auto [it, fresh] = by_identity.emplace(t.value->identity(), t);
    if (!fresh) it->second.coef += t.coef;
  }
  constants_.clear();
  for (auto& [key, t] : by_identity)
    if (sgn(t.coef) != 0) constants_.push_back(std::move(t));
}

void ExactSum::merge_equal_constants() {
  for (std::size_t i = 0; i < constants_.size(); ++i) {
    if (sgn(constants_[i].coef) == 0) continue;
    const Interval a = constants_[i].value->approx();
    for (std::size_t j = i + 1; j < constants_.size(); ++j) {
      if (sgn(constants_[j].coef) == 0) continue;
      const Interval b = constants_[j].value->approx();
      if (a.hi < b.lo || b.hi < a.lo) continue;
      if (constants_[i].value->equals(*constants_[j].value).value_or(false)) {
        constants_[i].coef += constants_[j].coef;
        constants_[j].coef = 0;
      }
    }
  }
  std::vector<ConstantTerm> kept;
  for (ConstantTerm& t : constants_)
    if (sgn(t.coef) != 0) kept.push_back(std::move(t));
  constants_ = std::move(kept);
}

Interval ExactSum::approx() const {
  Interval sum = grassfire::enclose(rational_);
  for (const SqrtTerm& t : sqrt_) sum += grassfire::enclose(t.coef) * sqrt(grassfire::enclose(t.radicand));
  for (const ConstantTerm& t : constants_) sum += grassfire::enclose(t.coef) * t.value->approx();
  return sum;
}

void ExactSum::enclose(mpfr_ptr lo, mpfr_ptr hi) const {
  const long bits = mpfr_get_prec(lo);
  mpfr_set_q(lo, rational_.get_mpq_t(), MPFR_RNDD);
  mpfr_set_q(hi, rational_.get_mpq_t(), MPFR_RNDU);
  MpfrBounds s(bits);
  for (const SqrtTerm& t : sqrt_) {
    mpfr_set_q(s.lo, t.radicand.get_mpq_t(), MPFR_RNDD);
    mpfr_set_q(s.hi, t.radicand.get_mpq_t(), MPFR_RNDU);
    mpfr_sqrt(s.lo, s.lo, MPFR_RNDD);
    mpfr_sqrt(s.hi, s.hi, MPFR_RNDU);
    add_scaled(lo, hi, t.coef, s.lo, s.hi);
  }
  for (const ConstantTerm& t : constants_) {
    t.value->enclose(s.lo, s.hi);
    // A constant's enclosure may straddle zero; add_scaled needs ordered bounds only.
    MpfrBounds u(bits);
    if (sgn(t.coef) >= 0) {
      mpfr_mul_q(u.lo, s.lo, t.coef.get_mpq_t(), MPFR_RNDD);
      mpfr_mul_q(u.hi, s.hi, t.coef.get_mpq_t(), MPFR_RNDU);
    } else {
      mpfr_mul_q(u.lo, s.hi, t.coef.get_mpq_t(), MPFR_RNDD);
      mpfr_mul_q(u.hi, s.lo, t.coef.get_mpq_t(), MPFR_RNDU);
    }
    mpfr_add(lo, lo, u.lo, MPFR_RNDD);
    mpfr_add(hi, hi, u.hi, MPFR_RNDU);
  }
}

bool is_zero_sqrt_part(const ExactSum& input) {
  ExactSum x = input;
  x.simplify();
  // Rewrite c * sqrt(n/d) as (c/d) * sqrt(n*d) with an integer radicand.
  std::vector<IntegerRootTerm> terms;
  for (const SqrtTerm& t : x.sqrt_terms()) {
    mpz_class m = t.radicand.get_num() * t.radicand.get_den();
    terms.push_back({t.coef / mpq_class(t.radicand.get_den()), m});
  }
  if (terms.empty()) return sgn(x.rational_part()) == 0;
  if (sgn(x.rational_part()) != 0) {
    // simplify() moved every square radicand into the rational part, so a nonzero
    // rational part is independent of the remaining roots.
    return false;
  }
  const std::vector<std::uint64_t> fp = fingerprints(terms);
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> buckets;
  for (std::size_t i = 0; i < terms.size(); ++i) buckets[fp[i]].push_back(i);
  for (auto& [key, members] : buckets) {
    std::vector<bool> assigned(members.size(), false);
    for (std::size_t a = 0; a < members.size(); ++a) {
      if (assigned[a]) continue;
      const IntegerRootTerm& rep = terms[members[a]];
      // Class coefficient in units of sqrt(rep.m): sqrt(m) = sqrt(m * m0) / m0 * sqrt(m0).
      mpq_class coefficient = rep.coef;
      for (std::size_t b = a + 1; b < members.size(); ++b) {
        if (assigned[b]) continue;
        const IntegerRootTerm& other = terms[members[b]];
        mpz_class product = other.m * rep.m;
        if (!mpz_perfect_square_p(product.get_mpz_t())) continue;
        mpz_class root;
        mpz_sqrt(root.get_mpz_t(), product.get_mpz_t());
        coefficient += other.coef * make_rational(root, rep.m);
        assigned[b] = true;
      }
      if (sgn(coefficient) != 0) return false;
    }
  }
  return true;
}

int sign(const ExactSum& input, NumberStats* stats) {
  NumberStats local;
  NumberStats& st = stats ? *stats : local;
  const int quick = certified_sign(input.approx());
  if (quick != kUndecided) {
    ++st.filter_decided;
    return quick;
  }
  ExactSum x = input;
  x.simplify();
  for (long bits : {128L, 512L}) {
    const int s = mpfr_sign(x, bits);
    if (s != kUndecided) {
      ++st.mpfr_decided;
      st.max_bits_used = std::max<std::uint64_t>(st.max_bits_used, bits);
      return s;
    }
  }
  if (!x.constant_terms().empty()) x.merge_equal_constants();
  if (x.constant_terms().empty() && is_zero_sqrt_part(x)) {
    ++st.exact_zero;
    return 0;
  }
  if (!x.constant_terms().empty()) {
    long bits = 0;
    if (const std::optional<int> s = radical_sign(x, kMaxSeparationBits, &bits)) {
      ++st.separation_decided;
      ++(*s == 0 ? st.exact_zero : st.mpfr_decided);
      st.max_bits_used = std::max<std::uint64_t>(st.max_bits_used, static_cast<std::uint64_t>(bits));
      return *s;
    }
  }
  // Nonzero (or with constants): raise the precision until the enclosure excludes zero.
  for (long bits = 1024; bits <= kMaxBits; bits *= 2) {
    const int s = mpfr_sign(x, bits);
    if (s != kUndecided) {
      ++st.mpfr_decided;
      st.max_bits_used = std::max<std::uint64_t>(st.max_bits_used, bits);
      return s;
    }
  }
  if (x.constant_terms().empty()) {
    // A nonzero sum of square roots: keep doubling; the loop ends because the
    // enclosure width goes to zero while |x| > 0.
    for (long bits = 2 * kMaxBits;; bits *= 2) {
      const int s = mpfr_sign(x, bits);
      if (s != kUndecided) {
        ++st.mpfr_decided;
        st.max_bits_used = std::max<std::uint64_t>(st.max_bits_used, bits);
        return s;
      }
    }
  }
  ++st.uncertified_zero;
  return 0;
}

std::string to_string(const ExactSum& x) {
  std::ostringstream os;
  os << x.rational_part().get_str();
  for (const SqrtTerm& t : x.sqrt_terms())
    os << (sgn(t.coef) < 0 ? " - " : " + ") << mpq_class(abs(t.coef)).get_str() << "*sqrt(" << t.radicand.get_str()
       << ")";
  for (const ConstantTerm& t : x.constant_terms())
    os << (sgn(t.coef) < 0 ? " - " : " + ") << mpq_class(abs(t.coef)).get_str() << "*" << t.value->identity();
  return os.str();
}

}  // namespace grassfire
