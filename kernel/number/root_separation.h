// root_separation.h -- the exact sign of a sum of square roots of sums of square roots,
// by a root-separation bound (docs/design.md 3: "then proof of equality").
//
// Computes: the sign of x = q + sum_j c_j sqrt(s_j) + sum_i d_i sqrt(E_i), with rationals
// q, c_j, d_i, s_j >= 0 and radicands E_i >= 0 that are themselves constant-free sums
// (CertifiedConstant::radicand(), e.g. number/sqrt_field.h's sqrt_constant): the values of
// nested radicals such as PSS circles and bisector lengths (medial2/polygon/voronoi_circle.h).
// Method: x lies in K = Q(sqrt a_1, .., sqrt a_k, sqrt E_1, .., sqrt E_G), where a_1..a_k
// are the square classes of every rational radicand (those inside the E_i included) and
// E_i that are rational multiples of one another count once (sqrt(t E) = sqrt(t) sqrt(E)).
// So [K:Q] <= D = 2^(k+G). With an integer M that makes y = M x an algebraic integer and
// B >= |sigma(y)| for every embedding sigma (every coefficient and every inner coefficient
// taken in absolute value: B = M |x|_abs), a nonzero y has |Norm(y)| >= 1, hence
//     |x| >= 1 / (M B^(D-1))   (Mignotte's argument; BFMSS-type bound).
// An MPFR enclosure narrower than that bound which contains zero proves x = 0; one that
// excludes zero gives the sign. The bound is an upper bound on the degree, so it is
// conservative, never wrong.
// Contract: the constant terms of x all have radicands (else the answer is nullopt).
// Complexity: O(t^2) perfect-square tests for t rational radicands, then MPFR evaluations
// at about log2(M) + (D-1) log2(B) bits; nullopt when that exceeds max_bits.
#pragma once

#include <optional>

#include "number/exact_sum.h"

namespace grassfire {

struct SeparationBound {
  int degree_log2 = 0;  // k + G: [K:Q] <= 2^degree_log2
  long bits = 0;        // |x| >= 2^-bits when x != 0
};

// The bound for x, or nullopt when a constant of x has no radicand or the bound exceeds
// max_bits.
std::optional<SeparationBound> separation_bound(const ExactSum& x, long max_bits);

// The exact sign of x (-1, 0, +1), or nullopt as for separation_bound. *bits_used, when
// given, receives the precision of the deciding evaluation.
std::optional<int> radical_sign(const ExactSum& x, long max_bits, long* bits_used = nullptr);

constexpr long kMaxSeparationBits = 1L << 21;

}  // namespace grassfire
