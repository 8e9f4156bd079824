// simplest_rational.h -- the rational of smallest denominator in an interval of doubles.
//
// Computes: q = the simplest rational in [lo, hi] (smallest denominator; the continued-
// fraction construction makes it unique), returned when its denominator is below
// 2^max_bits, else nullopt (also after 64 continued-fraction terms). Output values of exact
// constructions use it to recognise small-denominator values (centres of symmetric
// configurations) inside certified enclosures; the caller confirms q exactly.
// Two implementations with the same result: simplest_rational_reference recurses in GMP
// rationals (the definition); simplest_rational runs the same continued fraction in 128-bit
// integers, stopping as soon as a convergent's denominator reaches 2^max_bits (the final
// denominator is at least that large), when |lo|, |hi| < 2^30, 1 <= max_bits <= 40 and a common
// power-of-two denominator of lo and hi is at most 2^90; otherwise it calls the reference.
// Contract: lo <= hi, both finite. Complexity: O(terms), at most 64.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <optional>

namespace grassfire {

std::optional<mpq_class> simplest_rational(double lo, double hi, std::size_t max_bits);
std::optional<mpq_class> simplest_rational_reference(const mpq_class& lo, const mpq_class& hi, std::size_t max_bits);

}  // namespace grassfire
