// sqrt_field.h -- the arithmetic of ExactSum (number/exact_sum.h): products, quotients and
// square roots of sums of square roots of rationals.
//
// ExactSum itself holds the representation, addition and the certified sign; this header
// adds what turns it into a number type for exact constructions: multiplication, division
// and square roots, each returning an ExactSum (or refusing when the result leaves that
// form). Numbers of a fixed multiquadratic field with their own faster representations are
// in number/multiquadratic.h; they convert to ExactSum.
// Computes: exact products of ExactSums without constants (sqrt(a) sqrt(b) = sqrt(ab)),
// and quotients by rationalising the denominator with conjugates (x / (a + b sqrt r) =
// x (a - b sqrt r) / (a^2 - b^2 r)), which keeps Voronoi vertices of segment sites in the
// form q + sum c_i sqrt(r_i) whenever they lie in a multiquadratic field (docs/exactness.md: exact
// R where the geometry allows). Also: the exact square root of a rational when it is
// rational, and denesting sqrt(u + v sqrt m) when u^2 - v^2 m is a rational square.
// Contract: no certified constants in the operands (checked: std::invalid_argument).
// Complexity: a product of k and l terms is O(k l) rational operations; a quotient does
// at most kMaxConjugations rounds, each a product.
#pragma once

#include <memory>
#include <optional>

#include "number/exact_sum.h"

namespace grassfire {

ExactSum multiply(const ExactSum& a, const ExactSum& b);
// multiply(a, b) with like terms merged (simplify); what exact constructions chain.
ExactSum multiply_simplified(const ExactSum& a, const ExactSum& b);
// c a for a rational c.
ExactSum scaled(ExactSum a, const mpq_class& c);
// a / b, or nullopt when the conjugate rounds do not make the denominator rational
// (or b is zero).
std::optional<ExactSum> divide(const ExactSum& a, const ExactSum& b);
// sqrt(q) as a rational when q is the square of one.
std::optional<mpq_class> rational_sqrt(const mpq_class& q);
// sqrt(x) as an ExactSum for x >= 0 rational or x = u + v sqrt(m) denestable; nullopt
// otherwise.
std::optional<ExactSum> sqrt_of_sum(const ExactSum& x);
// sqrt(x) for an exact sum x >= 0 without constants, as a certified constant (for when it
// does not denest): identity "sqrt[x]", and equality with another such root decided
// exactly (equal exactly when the radicands are: Besicovitch's test, is_zero_sqrt_part).
std::shared_ptr<const CertifiedConstant> sqrt_constant(ExactSum x);
// sqrt(x) as an ExactSum: denested when sqrt_of_sum can, otherwise rho * sqrt(x') with
// x = rho^2 x', rho rational and x' normalised (every radicand and the coefficients'
// common factor freed of squares of primes below 100), so that roots of sums that differ
// by such a square factor share one radicand and cancel or merge.
ExactSum sqrt_term(const ExactSum& x);
// a * b where a may also hold square roots of sums (sqrt_constant, sqrt_term) and b holds
// no constants: c sqrt(s) * d sqrt(E) = c d sqrt(s E), written with sqrt_term. Keeps nested
// radicals such as PSS circles (medial2/polygon/voronoi_circle.h) in the form that
// number/root_separation.h decides. Throws std::invalid_argument for any other constant.
ExactSum multiply_radical(const ExactSum& a, const ExactSum& b);
// Exact sign of a sum without constants (never uncertified).
int exact_sign(const ExactSum& x, NumberStats* stats = nullptr);

// A number type for formulas shared with Interval and Ball (voronoi_circle.cpp): exact
// field operations on sums of square roots; throws NestedRadical when a quotient or a
// square root leaves that form.
struct NestedRadical {};
struct RootSum {
  ExactSum v;
  RootSum() = default;
  RootSum(double d) : v(ExactSum::rational(mpq_class(d))) {}  // NOLINT: doubles are exact rationals
  explicit RootSum(ExactSum s) : v(std::move(s)) { v.simplify(); }
};
RootSum operator+(const RootSum& a, const RootSum& b);
RootSum operator-(const RootSum& a, const RootSum& b);
RootSum operator-(const RootSum& a);
RootSum operator*(const RootSum& a, const RootSum& b);
RootSum operator/(const RootSum& a, const RootSum& b);
RootSum sqrt(const RootSum& a);

}  // namespace grassfire
