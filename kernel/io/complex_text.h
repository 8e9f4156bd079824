// complex_text.h -- what the 3D readers and writers (.ma, OFF, PLY, OBJ, ball lists) share:
// the error type, line-by-line tokenising with line numbers, exact decimal parsing, and
// printing rationals exactly when they are decimals.
//
// Numbers: parse_exact_decimal reads [+-]digits[.digits][(e|E)[+-]digits] (also ".5",
// "5.") into the rational it denotes, exactly; "nan", "inf" and anything else are
// rejected, and so are numbers of more than kMaxDecimalDigits digits or whose value needs a
// power of ten beyond 10^+-4000: every double is written exactly in 767 significant digits,
// and exact arithmetic on longer numbers would make a damaged file take minutes.
// parse_finite_double reads the same syntax into the nearest double.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/format_error.h"
#include "support/number_text.h"  // shortest_double, which the 3D writers use

namespace grassfire {

// A file that cannot be read or parsed. what() is "<path>:<line>: <problem>" (or
// "<path>: <problem>" when no line applies).
class ComplexFormatError : public FormatError {  // support/format_error.h: the contract of what()
 public:
  using FormatError::FormatError;
};

[[noreturn]] void format_error(const std::string& source, std::size_t line, const std::string& problem);

std::string read_text_file(const std::string& path);  // throws ComplexFormatError

struct TextLine {
  std::size_t number = 0;  // 1-based
  std::vector<std::string> tokens;
};
// The non-empty lines of `text` split at white space; text from `comment` to the end of a
// line is dropped (comment = 0: none).
std::vector<TextLine> tokenize_lines(const std::string& text, char comment = '#');

constexpr std::size_t kMaxDecimalDigits = 1000;
std::optional<mpq_class> parse_exact_decimal(const std::string& token);
std::optional<double> parse_finite_double(const std::string& token);
std::optional<std::uint64_t> parse_index(const std::string& token);  // decimal digits only

// Exact decimal text of q when its denominator is 2^a 5^b, else nothing.
std::optional<std::string> exact_decimal_string(const mpq_class& q);
// Exact decimal when there is one, else the shortest text of the nearest double.
std::string decimal_or_nearest(const mpq_class& q);

}  // namespace grassfire
