// radical_number.h -- exact numbers of a multiquadratic field Q(sqrt s_1, ..., sqrt s_k).
//
// Computes: sums  sum_A c_A prod_{r in A} sqrt(s_r)  with rational c_A over subsets A of
// registered positive rationals s_r ("radicals"), with exact +, -, * and a certified
// sign. The vertices of the boundary of a union of balls are z + sqrt(s) N with rational
// z, N, s (three spheres meet in two mirror points), so the bisector planes of such
// vertices, and the points where three of them meet (the medial axis inside the alpha
// complex, Amenta-Kolluri 2001), have coordinates in such a field. A product of radicals
// is kept symbolically as the set of its ids (sqrt(s_r)^2 = s_r), so radicands never grow.
// Sign (docs/design.md 3): a double interval filter, then the number layer's certified sign of
// the equivalent ExactSum (MPFR enclosures, then the exact square-class zero test, which
// also catches radicals that are dependent over Q).
// Contract: every number of one expression uses the same RadicalTable; at most
// kMaxRadicals distinct radicals per term (std::length_error otherwise).
// Complexity: + is linear in the terms, * quadratic; at most 2^k terms for k radicals.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <array>
#include <cstdint>
#include <vector>

#include "number/exact_sum.h"
#include "number/interval.h"

namespace grassfire {

// The radicals s_r > 0 of one computation, with certified enclosures of their roots.
class RadicalTable {
 public:
  std::uint32_t add(const mpq_class& s);  // s > 0 (std::invalid_argument otherwise)
  const mpq_class& radicand(std::uint32_t r) const { return radicand_[r]; }
  const Interval& root(std::uint32_t r) const { return root_[r]; }
  std::size_t size() const { return radicand_.size(); }

 private:
  std::vector<mpq_class> radicand_;
  std::vector<Interval> root_;
};

// The set of radicals multiplied in one term, as sorted ids.
struct RadicalKey {
  static constexpr int kMaxRadicals = 8;
  std::uint8_t n = 0;
  std::array<std::uint32_t, kMaxRadicals> id{};
  friend bool operator<(const RadicalKey& a, const RadicalKey& b);
  friend bool operator==(const RadicalKey& a, const RadicalKey& b);
};

class RadicalNumber {
 public:
  struct Term {
    RadicalKey key;
    mpq_class coef;
  };

  RadicalNumber() = default;
  RadicalNumber(const mpq_class& q);  // NOLINT: rationals embed in the field
  RadicalNumber(long q) : RadicalNumber(mpq_class(q)) {}  // NOLINT
  // c * sqrt(s_r) for radical r of `table`.
  static RadicalNumber root(const RadicalTable& table, std::uint32_t r, const mpq_class& c = 1);

  RadicalNumber& operator+=(const RadicalNumber& o);
  RadicalNumber& operator-=(const RadicalNumber& o);
  RadicalNumber& operator*=(const mpq_class& f);
  friend RadicalNumber operator+(RadicalNumber a, const RadicalNumber& b) { return a += b; }
  friend RadicalNumber operator-(RadicalNumber a, const RadicalNumber& b) { return a -= b; }
  friend RadicalNumber operator-(RadicalNumber a) { return a *= mpq_class(-1); }
  friend RadicalNumber operator*(const RadicalNumber& a, const RadicalNumber& b);
  friend RadicalNumber operator*(RadicalNumber a, const mpq_class& f) { return a *= f; }

  const std::vector<Term>& terms() const { return terms_; }
  bool is_zero_form() const { return terms_.empty(); }  // zero as a formal sum
  // The rational value if the number is rational (exact test), else false.
  bool rational_value(mpq_class* q) const;

  ExactSum to_exact_sum() const;
  Interval approx() const;                       // certified double enclosure
  void enclose(mpfr_ptr lo, mpfr_ptr hi) const;  // at the precision of lo and hi

 private:
  void normalize();  // sort by key, merge, drop zero coefficients
  const RadicalTable* table_ = nullptr;
  std::vector<Term> terms_;
};

// Exact sign of x, counting the filter stages in `stats`.
int sign(const RadicalNumber& x, NumberStats* stats = nullptr);

// Exact sign of a + b sqrt(c) for field elements a, b and c >= 0 (squaring once).
int sign_plus_root(const RadicalNumber& a, const RadicalNumber& b, const RadicalNumber& c,
                   NumberStats* stats = nullptr);
// Exact sign of a sqrt(c) + b sqrt(d) for field elements, c, d >= 0.
int sign_two_roots(const RadicalNumber& a, const RadicalNumber& c, const RadicalNumber& b, const RadicalNumber& d,
                   NumberStats* stats = nullptr);

// A rational approximation q of x / w (w != 0) with |q - x/w| <= *error (an upper bound),
// rounded to about `bits` significant bits.
mpq_class approximate_quotient(const RadicalNumber& x, const RadicalNumber& w, long bits, double* error);

}  // namespace grassfire
