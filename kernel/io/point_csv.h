// point_csv.h -- point lists for burn3d: sources (x,y,z,t0) and queries (x,y,z).
//
// Format: comma-separated text; the first line that is not blank and not a `#` comment is
// the header, exactly `x,y,z` (queries) or `x,y,z,t0` (sources), spaces around fields
// allowed; then one point per line, blank lines and `#` comment lines skipped. Values are
// decimals ([+-]digits[.digits][(e|E)[+-]digits]) read as the exact rationals they write;
// the text of each field is kept too (burn3d echoes a query's own numbers).
// Errors (ComplexFormatError "<file>:<line>: <problem>", nothing returned): no header, a
// wrong header, a wrong number of fields, a value that is not a decimal (nan, inf, hex,
// empty); an empty list is allowed.
// Complexity: O(file size).
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "complex3/raw_complex.h"

namespace grassfire {

struct CsvPoint {
  std::size_t line = 0;              // 1-based, for messages
  std::array<std::string, 3> text;   // x, y, z as written (trimmed)
  ExactPoint3 point;
  mpq_class t0;                      // sources only
};

// with_t0: the header is x,y,z,t0; else x,y,z.
std::vector<CsvPoint> parse_point_csv(const std::string& text, const std::string& source, bool with_t0);
std::vector<CsvPoint> read_point_csv(const std::string& path, bool with_t0);

}  // namespace grassfire
