// multiquadratic.h -- exact numbers of a multiquadratic field Q(sqrt s_1, ..., sqrt s_k): the
// one home of that field, in its two representations, and square roots of sums of square
// roots as exact sums or certified constants.
//
// Computes: sums  sum_A c_A prod_{r in A} sqrt(s_r)  with rational c_A over subsets A of
// positive rationals s_r, exactly (+, -, *), each converting to the ExactSum of the same
// value (number/exact_sum.h, whose sign is certified), in one of two representations:
//  - RadicalNumber over a RadicalTable: sparse terms keyed by the sorted ids of their
//    radicals, any number of radicals in the table (they may be dependent over Q), a
//    product of radicals kept symbolically (sqrt(s_r)^2 = s_r, so radicands never grow).
//    Certified sign (docs/design.md 3): a double interval filter from the table's
//    enclosures of the roots, then the certified sign of the equivalent ExactSum (MPFR
//    enclosures, then the exact square-class zero test, which also catches radicals that
//    are dependent over Q); also signs of a + b sqrt c and a sqrt c + b sqrt d, and
//    rational approximations of quotients. Used where one computation meets many
//    radicals: the vertices of the boundary of a union of balls are z + sqrt(s) N with
//    rational z, N, s (three spheres meet in two mirror points), so the bisector planes of
//    such vertices, and the points where three of them meet (the medial axis inside the
//    alpha complex, Amenta-Kolluri 2001), have coordinates in such a field
//    (medial3/balls/, medial3/convex/exact_cell.h).
//  - Multiquadratic over a QuadraticBasis: dense coefficients by subset of at most
//    kMaxGenerators independent generators g_j (no product of a nonempty subset is a
//    rational square: QuadraticBasis reduces every new radicand against the basis, e.g.
//    sqrt 8 = 2 sqrt 2, sqrt 6 = sqrt 2 sqrt 3 when 2 and 3 are in it), so the formal ring
//    is the field of degree 2^k (Besicovitch), a nonzero number has a nonzero norm, and
//    division rationalises the denominator by flipping one generator at a time (x *
//    conj_j(x) has no sqrt(g_j) term), ending after k rounds. Used where a few radicals
//    meet and quotients are needed: Voronoi vertices of boundary corners of a union of
//    disks (medial2/disks/disk_union_axis.h) and the kinks of the exact 3D engine
//    (burn3/exact/junction_kinks.h). Its sign is that of to_exact_sum().
// Also: root_of_sum(x) = sqrt(x) as an ExactSum when it denests, else a certified
// constant whose identity is the canonical text of x (canonical_roots below).
// Contract: every number of one expression uses the same table or basis; positive
// radicands; a RadicalNumber term holds at most RadicalKey::kMaxRadicals radicals and a
// basis at most kMaxGenerators generators (std::length_error otherwise).
// Complexity: RadicalNumber + is linear in the terms, * quadratic (at most 2^k terms for k
// radicals); a Multiquadratic product is O(4^k) rational operations, an inverse k products.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <array>
#include <cstdint>
#include <vector>

#include "number/exact_sum.h"
#include "number/interval.h"

namespace grassfire {

// ---- the dense representation over an independent basis (see the header comment) ----

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

// ---- the sparse representation over a table of radicals (see the header comment) ----

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
