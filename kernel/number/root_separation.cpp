// root_separation.cpp -- see root_separation.h.
#include "number/root_separation.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

#include "number/mpfr_bounds.h"

namespace grassfire {

namespace {

// coef * sqrt(multiplier) * sqrt(E_group): a radical term with its radicand written as a
// rational multiple of its group's representative.
struct GroupedRadical {
  mpq_class coef, multiplier;
  std::size_t group = 0;
};

// t > 0 with a = t b, when an exact test proves it (nullopt says nothing).
std::optional<mpq_class> rational_ratio(const ExactSum& a, const ExactSum& b) {
  mpq_class t;
  if (sgn(b.rational_part()) != 0) {
    t = a.rational_part() / b.rational_part();
  } else if (!b.sqrt_terms().empty()) {
    const SqrtTerm& lead = b.sqrt_terms().front();
    const auto it = std::find_if(a.sqrt_terms().begin(), a.sqrt_terms().end(),
                                 [&](const SqrtTerm& s) { return s.radicand == lead.radicand; });
    if (it == a.sqrt_terms().end()) return std::nullopt;
    t = it->coef / lead.coef;
  } else {
    return std::nullopt;
  }
  if (sgn(t) <= 0) return std::nullopt;
  ExactSum scaled = b;
  scaled.scale(t);
  if (!is_zero_sqrt_part(a - scaled)) return std::nullopt;
  return t;
}

// The number of square classes of Q*/Q*^2 among the positive rationals r (squares excluded):
// an upper bound on the rank of the group they generate.
int square_classes(const std::vector<mpq_class>& radicands) {
  std::vector<mpz_class> reps;
  for (const mpq_class& r : radicands) {
    const mpz_class m = r.get_num() * r.get_den();  // sqrt(n/d) = sqrt(n d) / d
    if (mpz_perfect_square_p(m.get_mpz_t())) continue;
    const bool known = std::any_of(reps.begin(), reps.end(), [&](const mpz_class& rep) {
      const mpz_class product = rep * m;
      return mpz_perfect_square_p(product.get_mpz_t()) != 0;
    });
    if (!known) reps.push_back(m);
  }
  return static_cast<int>(reps.size());
}

void lcm_into(mpz_class& acc, const mpq_class& q) { mpz_lcm(acc.get_mpz_t(), acc.get_mpz_t(), q.get_den().get_mpz_t()); }

// acc += |c| sqrt(r) * factor, rounded up (factor >= 0).
void add_abs_root(mpfr_ptr acc, const mpq_class& c, const mpq_class& r, mpfr_srcptr factor) {
  MpfrBounds t(mpfr_get_prec(acc));
  mpfr_set_q(t.hi, r.get_mpq_t(), MPFR_RNDU);
  mpfr_sqrt(t.hi, t.hi, MPFR_RNDU);
  const mpq_class a = abs(c);
  mpfr_mul_q(t.hi, t.hi, a.get_mpq_t(), MPFR_RNDU);
  mpfr_mul(t.hi, t.hi, factor, MPFR_RNDU);
  mpfr_add(acc, acc, t.hi, MPFR_RNDU);
}

// The parts of x that the bound needs: the groups of radicands and the grouped terms.
struct RadicalParts {
  std::vector<ExactSum> groups;
  std::vector<GroupedRadical> radicals;
};

std::optional<RadicalParts> radical_parts(const ExactSum& x) {
  RadicalParts p;
  for (const ConstantTerm& t : x.constant_terms()) {
    const ExactSum* e = t.value->radicand();
    if (!e) return std::nullopt;
    if (is_zero_sqrt_part(*e)) continue;  // sqrt(0)
    GroupedRadical r{t.coef, 1, p.groups.size()};
    for (std::size_t g = 0; g < p.groups.size(); ++g)
      if (std::optional<mpq_class> ratio = rational_ratio(*e, p.groups[g])) {
        r.multiplier = *ratio;
        r.group = g;
        break;
      }
    if (r.group == p.groups.size()) p.groups.push_back(*e);
    p.radicals.push_back(std::move(r));
  }
  return p;
}

}  // namespace

std::optional<SeparationBound> separation_bound(const ExactSum& input, long max_bits) {
  ExactSum x = input;
  x.simplify();
  const std::optional<RadicalParts> parts = radical_parts(x);
  if (!parts) return std::nullopt;
  std::vector<mpq_class> rational_radicands;
  for (const SqrtTerm& t : x.sqrt_terms()) rational_radicands.push_back(t.radicand);
  for (const GroupedRadical& r : parts->radicals) rational_radicands.push_back(r.multiplier);
  for (const ExactSum& g : parts->groups)
    for (const SqrtTerm& t : g.sqrt_terms()) rational_radicands.push_back(t.radicand);
  SeparationBound bound;
  bound.degree_log2 = square_classes(rational_radicands) + static_cast<int>(parts->groups.size());
  if (bound.degree_log2 > 40) return std::nullopt;

  // M: y = M x is an algebraic integer (root_separation.h). lambda[g]^2 E_g is one.
  mpz_class M = 1;
  lcm_into(M, x.rational_part());
  for (const SqrtTerm& t : x.sqrt_terms()) lcm_into(M, t.coef / mpq_class(t.radicand.get_den()));
  std::vector<mpz_class> lambda(parts->groups.size(), 1);
  for (std::size_t g = 0; g < parts->groups.size(); ++g) {
    lcm_into(lambda[g], parts->groups[g].rational_part());
    for (const SqrtTerm& t : parts->groups[g].sqrt_terms())
      lcm_into(lambda[g], t.coef / mpq_class(t.radicand.get_den()));
  }
  for (const GroupedRadical& r : parts->radicals)
    lcm_into(M, r.coef / (mpq_class(r.multiplier.get_den()) * mpq_class(lambda[r.group])));

  // |x|_abs: every embedding of y is at most M |x|_abs in modulus.
  constexpr long kBoundBits = 64;
  mpfr_t abs_sum, one;
  mpfr_init2(abs_sum, kBoundBits);
  mpfr_init2(one, kBoundBits);
  mpfr_set_ui(one, 1, MPFR_RNDN);
  const mpq_class q0 = abs(x.rational_part());
  mpfr_set_q(abs_sum, q0.get_mpq_t(), MPFR_RNDU);
  for (const SqrtTerm& t : x.sqrt_terms()) add_abs_root(abs_sum, t.coef, t.radicand, one);
  std::deque<MpfrBounds> root_abs;  // MpfrBounds does not move
  for (const ExactSum& g : parts->groups) {
    root_abs.emplace_back(kBoundBits);
    mpfr_ptr e = root_abs.back().hi;
    const mpq_class e0 = abs(g.rational_part());
    mpfr_set_q(e, e0.get_mpq_t(), MPFR_RNDU);
    for (const SqrtTerm& t : g.sqrt_terms()) add_abs_root(e, t.coef, t.radicand, one);
    mpfr_sqrt(e, e, MPFR_RNDU);
  }
  for (const GroupedRadical& r : parts->radicals) add_abs_root(abs_sum, r.coef, r.multiplier, root_abs[r.group].hi);
  // log2 B = log2 M + log2 |x|_abs, taken >= 0 (B >= 1 keeps B^(D'-1) <= B^(D-1) for D' <= D).
  mpfr_log2(abs_sum, abs_sum, MPFR_RNDU);
  const double log2_abs = mpfr_zero_p(abs_sum) ? 0 : mpfr_get_d(abs_sum, MPFR_RNDU);
  mpfr_clear(abs_sum);
  mpfr_clear(one);
  const double log2_m = static_cast<double>(mpz_sizeinbase(M.get_mpz_t(), 2));  // >= log2 M
  const double log2_b = std::max(0.0, log2_m + log2_abs);
  const double degree = std::ldexp(1.0, bound.degree_log2);
  // Doubles round here, so pad by a relative 2^-40 and two bits: the result stays an upper bound.
  const double bits = (log2_m + (degree - 1) * log2_b) * (1 + 0x1p-40) + 2;
  if (!(bits <= static_cast<double>(max_bits))) return std::nullopt;
  bound.bits = static_cast<long>(std::ceil(bits));
  return bound;
}

std::optional<int> radical_sign(const ExactSum& input, long max_bits, long* bits_used) {
  ExactSum x = input;
  x.simplify();
  const std::optional<SeparationBound> bound = separation_bound(x, max_bits);
  if (!bound) return std::nullopt;
  // Enough working bits that the enclosure is narrower than 2^-bound.bits: the magnitude of
  // the terms, the bound, and slack for the rounding of some dozens of operations.
  const Interval a = x.approx();
  const double largest = std::fmax(std::fabs(a.lo), std::fabs(a.hi));
  const long magnitude = std::isfinite(largest) ? static_cast<long>(std::ceil(std::log2(largest + 1))) : 1024;
  const long terms = static_cast<long>(x.term_count());
  long bits = bound->bits + magnitude + 64 + 2 * static_cast<long>(std::ceil(std::log2(terms + 1.0)));
  for (int round = 0; round < 8; ++round, bits *= 2) {
    MpfrBounds b(bits);
    x.enclose(b.lo, b.hi);
    const int s = b.sign();
    if (bits_used) *bits_used = bits;
    if (s != kUndecided) return s;
    // The enclosure holds x and 0; if it is narrower than the bound, x = 0.
    MpfrBounds w(bits);
    mpfr_sub(w.hi, b.hi, b.lo, MPFR_RNDU);
    if (mpfr_cmp_ui_2exp(w.hi, 1, -bound->bits) < 0) return 0;
  }
  return std::nullopt;
}

}  // namespace grassfire
