// multiquadratic.h -- exact arithmetic in a multiquadratic field Q(sqrt g_1, ..., sqrt g_k),
// and square roots of sums of square roots as exact sums or certified constants.
//
// Computes: sums, products and quotients of numbers  sum_S c_S sqrt(g_S)  (S a subset of
// the generators, g_S the product of its g_j, c_S rational), exactly. Division rationalises
// the denominator by flipping one generator at a time (x * conj_j(x) has no sqrt(g_j)
// term), which ends after k rounds because the g_j are kept independent: no product of a
// nonempty subset is a rational square (QuadraticBasis reduces every new radicand against
// the basis, e.g. sqrt 8 = 2 sqrt 2, sqrt 6 = sqrt 2 sqrt 3 / 1 when 2 and 3 are in it), so
// the formal ring is the field of degree 2^k (Besicovitch) and a nonzero number has a
// nonzero norm. Used for Voronoi vertices of boundary corners of a union of disks
// (medial2/disks/disk_union_axis.h), whose coordinates lie in such fields.
// Also: root_of_sum(x) = sqrt(x) as an ExactSum when it denests, else a certified
// constant whose identity is the canonical text of x (canonical_roots below).
// Contract: generators are positive rationals; at most kMaxGenerators of them.
// Complexity: a product is O(4^k) rational operations; an inverse k products.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <vector>

#include "number/exact_sum.h"

namespace grassfire {

constexpr std::size_t kMaxGenerators = 6;

class QuadraticBasis {
 public:
  // sqrt(s) = coef * prod_{j in mask} sqrt(g_j).
  struct Root {
    mpq_class coef;
    std::uint32_t mask = 0;
  };
  // Expresses sqrt(s) (s > 0) in the basis, adding s as a new generator when it is
  // independent of the basis. Throws std::length_error past kMaxGenerators.
  Root adjoin(const mpq_class& s);
  const std::vector<mpq_class>& generators() const { return g_; }
  std::size_t size() const { return g_.size(); }
  // g_S for a subset mask.
  mpq_class product(std::uint32_t mask) const;

 private:
  std::vector<mpq_class> g_;
};

class Multiquadratic {
 public:
  explicit Multiquadratic(const QuadraticBasis& basis, const mpq_class& q = 0);
  static Multiquadratic root(const QuadraticBasis& basis, const QuadraticBasis::Root& r);

  Multiquadratic& operator+=(const Multiquadratic& o);
  Multiquadratic& operator-=(const Multiquadratic& o);
  friend Multiquadratic operator+(Multiquadratic a, const Multiquadratic& b) { return a += b; }
  friend Multiquadratic operator-(Multiquadratic a, const Multiquadratic& b) { return a -= b; }
  friend Multiquadratic operator*(const Multiquadratic& a, const Multiquadratic& b);
  // 1 / x; throws std::domain_error when x is zero.
  Multiquadratic inverse() const;
  ExactSum to_exact_sum() const;
  bool is_zero() const;

 private:
  Multiquadratic conjugate(std::size_t j) const;  // sqrt(g_j) -> -sqrt(g_j)
  const QuadraticBasis* basis_;
  std::vector<mpq_class> c_;  // by subset mask
};

// The same value with radicands in a canonical form: integers with the squares of the
// primes below 1000 taken out, and radicands of one square class merged into the smallest.
// Equal values written over different radicands (symmetric nodes) then print alike.
ExactSum canonical_roots(const ExactSum& x);

// sqrt(x) for x >= 0 without constants: the denested ExactSum when number/sqrt_field.h
// finds one, else a certified constant identified by the simplified text of x.
ExactSum root_of_sum(const ExactSum& x);

}  // namespace grassfire
