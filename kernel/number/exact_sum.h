// exact_sum.h -- real numbers of the form  q + sum_i c_i sqrt(r_i) + sum_k c_k A_k,
// with rational q, c_i, r_i >= 0, and certified constants A_k; their certified sign.
//
// Computes: the exact sign of such a sum (hence exact comparison of burn times, which
// are sums of a boundary distance and edge lengths along a path of the medial axis).
// Method (docs/design.md 3): a double interval filter, then MPFR enclosures at doubling
// precision; when those cannot separate the value from zero, an exact zero test.
// Square roots of rationals in different square classes (r_i / r_j not the square of a
// rational) are linearly independent over Q (Besicovitch 1940), so after grouping the
// terms by square class the sum is zero iff every class coefficient is zero. A nonzero
// sum is then separated from zero by raising the precision, which terminates.
// Certified constants (transcendental values such as parabolic arc lengths, docs/exactness.md)
// cancel by identity, or, when no precision up to 512 bits separates the sum from zero,
// by exact equality of pairs (CertifiedConstant::equals) among those whose enclosures
// overlap. When the constants left are all square roots of constant-free sums (nested
// radicals), a root-separation bound decides the sign exactly (root_separation.h). A sum
// with other uncancelled constants that no precision up to kMaxBits separates from zero is
// reported as zero and counted as an uncertified tie.
// Complexity: O(k log k) for k terms plus the MPFR work; the zero test does pairwise
// perfect-square tests only inside buckets of equal Legendre-symbol fingerprints.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "number/interval.h"

namespace grassfire {

// A real constant known through certified enclosures at any precision.
class ExactSum;

class CertifiedConstant {
 public:
  virtual ~CertifiedConstant() = default;
  // Sets lo <= value <= hi, each rounded at its own precision.
  virtual void enclose(mpfr_ptr lo, mpfr_ptr hi) const = 0;
  // Constants with equal identity strings are equal; distinct strings say nothing.
  virtual std::string identity() const = 0;
  // Exact equality with another constant when this pair can be decided exactly (for
  // example two square roots of sums of square roots, equal exactly when the sums are:
  // number/sqrt_field.h); nullopt when it cannot. Never decided from enclosures alone.
  virtual std::optional<bool> equals(const CertifiedConstant& other) const {
    (void)other;
    return std::nullopt;
  }
  // When the constant is sqrt(E) for a constant-free sum E >= 0 (sqrt_field.h's
  // sqrt_constant), E; the root-separation test (root_separation.h) then decides sums of
  // such constants exactly. nullptr for any other constant.
  virtual const ExactSum* radicand() const { return nullptr; }
  // The 53-bit enclosure, computed once (sign() of a sum asks for it on every filter pass).
  const Interval& approx() const;

 private:
  mutable Interval approx_;
  mutable bool has_approx_ = false;
};

struct SqrtTerm {
  mpq_class coef;
  mpq_class radicand;  // >= 0
};

struct ConstantTerm {
  mpq_class coef;
  std::shared_ptr<const CertifiedConstant> value;
};

class ExactSum {
 public:
  ExactSum() = default;
  static ExactSum rational(const mpq_class& q);
  static ExactSum sqrt_of(const mpq_class& radicand);
  static ExactSum constant(std::shared_ptr<const CertifiedConstant> c);

  ExactSum& operator+=(const ExactSum& other);
  ExactSum& operator-=(const ExactSum& other);
  ExactSum& scale(const mpq_class& factor);
  friend ExactSum operator+(ExactSum a, const ExactSum& b) { return a += b; }
  friend ExactSum operator-(ExactSum a, const ExactSum& b) { return a -= b; }

  const mpq_class& rational_part() const { return rational_; }
  const std::vector<SqrtTerm>& sqrt_terms() const { return sqrt_; }
  const std::vector<ConstantTerm>& constant_terms() const { return constants_; }
  std::size_t term_count() const { return 1 + sqrt_.size() + constants_.size(); }

  // Merges equal radicands and equal constants, moves square radicands into the
  // rational part and drops zero coefficients. The value does not change.
  void simplify();
  // Merges constants proved equal by CertifiedConstant::equals (pairs whose double
  // enclosures overlap). The value does not change. O(k^2) pairs for k constants.
  void merge_equal_constants();

  Interval approx() const;                       // certified double enclosure
  void enclose(mpfr_ptr lo, mpfr_ptr hi) const;  // at the precision of lo and hi
  double to_double() const { return approx().mid(); }

 private:
  mpq_class rational_ = 0;
  std::vector<SqrtTerm> sqrt_;
  std::vector<ConstantTerm> constants_;
};

// How often each stage of the certified sign decided (docs/design.md 3: count fallbacks).
struct NumberStats {
  std::uint64_t filter_decided = 0;    // decided by the double interval
  std::uint64_t extended_decided = 0;  // decided by x87 extended-precision enclosures
  std::uint64_t mpfr_decided = 0;      // decided by a multiprecision enclosure
  std::uint64_t exact_zero = 0;        // proved zero by the square-class test or by value classes
  std::uint64_t class_zero = 0;        // of exact_zero: by value classes, no exact form built
  std::uint64_t separation_decided = 0;  // of exact_zero and mpfr_decided: by a root-separation bound
  std::uint64_t uncertified_zero = 0;  // constants left, no precision up to kMaxBits separated
  std::uint64_t max_bits_used = 0;
  void merge(const NumberStats& o);
};

constexpr long kMaxBits = 1 << 14;

// Exact sign (-1, 0, +1) of x; see the header comment for the one uncertified case.
int sign(const ExactSum& x, NumberStats* stats = nullptr);
inline int compare(const ExactSum& a, const ExactSum& b, NumberStats* stats = nullptr) {
  return sign(a - b, stats);
}

// Exact zero test for the rational and square-root part (constants must be absent).
bool is_zero_sqrt_part(const ExactSum& x);

// Human-readable form, e.g. "3/2 + 1*sqrt(2) - 1/2*sqrt(5)".
std::string to_string(const ExactSum& x);

// The canonical rational n / d (gmpxx's two-argument constructor does not reduce, and
// every mpq function requires reduced operands).
inline mpq_class make_rational(const mpz_class& n, const mpz_class& d) {
  mpq_class q(n, d);
  q.canonicalize();
  return q;
}

// Exact enclosure of a rational as a double interval.
Interval enclose(const mpq_class& q);

}  // namespace grassfire
