// decimal_text.h -- the one reading of decimal numbers in text files (README, "Numbers").
//
// The rule: a decimal written in a text file ([+-]digits[.digits][(e|E)[+-]digits], also
// ".5" and "5.") denotes the rational it writes, exactly (0.1 is 1/10), in every format the
// exact and 3D code reads: meshes (OFF, PLY ASCII, OBJ, STL ASCII), point lists (CSV
// sources and queries), grassfire-complex JSON, .ma, ball, half-space and disk lists. So a
// point written with the same digits as a mesh vertex is that vertex. Where a double is
// needed too (CGAL's filtered predicates, the mesh checks, output), it is the double nearest
// to that rational (correctly rounded, ties to even), read from the same text. 2D shapes
// (shape JSON and WKT) hold doubles; their exact axis takes a double nearest to a decimal of
// at most 9 fractional digits as that decimal (medial2/polygon/polygon_axis.h), the same rational
// for the decimals people write.
// Refused: "nan", "inf", hexadecimal, anything else; more than kMaxDecimalDigits digits;
// a written exponent beyond max_exponent; a value that needs a power of ten beyond
// 10^+-4000 (every double is written exactly in 767 significant digits, and exact
// arithmetic on longer numbers would make a damaged file take minutes).
// Complexity: O(digits) plus the rational's construction.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <optional>
#include <string>

namespace grassfire {

constexpr std::size_t kMaxDecimalDigits = 1000;
constexpr long kMaxWrittenExponent = 999999;

// The rational the decimal writes, or nothing when `token` is not such a decimal.
std::optional<mpq_class> parse_exact_decimal(const std::string& token, long max_exponent = kMaxWrittenExponent);
// The double nearest to that rational, or nothing when it is not a decimal or not finite.
std::optional<double> parse_finite_double(const std::string& token);

// The double nearest to q (ties to even; +-inf beyond the range).
double nearest_double(const mpq_class& q);

// A coordinate as the readers keep it: the exact rational and its nearest double.
struct DecimalValue {
  mpq_class exact;
  double nearest = 0;
};
std::optional<DecimalValue> parse_decimal_value(const std::string& token);

}  // namespace grassfire
