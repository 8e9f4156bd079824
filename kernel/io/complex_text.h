// complex_text.h -- what the 3D readers and writers (.ma, OFF, PLY, OBJ, ball lists) share:
// the error type, line-by-line tokenising with line numbers, exact decimal parsing, and
// printing rationals exactly when they are decimals.
//
// Numbers: decimals are read by io/decimal_text.h (the one reading of decimal text).
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/format_error.h"
#include "support/number_text.h"  // shortest_double, which the 3D writers use
#include "io/decimal_text.h"

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

std::optional<std::uint64_t> parse_index(const std::string& token);  // decimal digits only

// Exact decimal text of q when its denominator is 2^a 5^b, else nothing.
std::optional<std::string> exact_decimal_string(const mpq_class& q);
// Exact decimal when there is one, else the shortest text of the nearest double.
std::string decimal_or_nearest(const mpq_class& q);

}  // namespace grassfire
