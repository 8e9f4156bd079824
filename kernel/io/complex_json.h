// complex_json.h -- the grassfire-complex JSON format: every RawComplex, exactly.
//
// Format (version 1; later versions add members and never change one):
//   {"format": "grassfire-complex", "version": 1,
//    "vertices": [[x, y, z], ...],                  vertex id = array index
//    "radius_squared": [r2, ...],                   optional; one per vertex, >= 0; default 0
//    "triangles": [[i, j, k], ...],                 optional; vertex ids
//    "segments": [[i, j], ...],                     optional; 1-dimensional parts
//    "border": [{"edge": [i, j], "rule": "linear" | "never" | "point",
//                "point": [x, y, z]}, ...],         optional; "point" only with rule "point"
//    "source": "text", "comment": "text"}           optional; ignored on reading
// Border edges not listed in "border" ignite linearly (f interpolates R, raw_complex.h);
// "point" is f(x) = |x - point| (DistanceToPoint); "never" never ignites.
// Numbers: a number is a JSON number or a string; either is read as the exact rational it
// writes: a decimal [+-]digits[.digits][(e|E)[+-]digits] (JSON number tokens are read from
// their own text, never through a double), or, in a string only, "p/q" with integers p and
// q > 0 (rationals that are not finite decimals). A JSON number beyond the range of a
// double (1e400) is refused by the JSON parser: write it as a string ("1e400"). Indices
// are non-negative JSON integers below 2^32. Writing: integers and finite decimals below
// 10^300 in magnitude as JSON numbers written exactly (0.1 is the rational 1/10, not a
// double), every other rational as a string (its decimal, or "p/q"), so
// that every RawComplex written and read back is the same RawComplex (member by member;
// the border list keeps its order, "source" records the RawComplex's source).
// Errors (ComplexFormatError, one message, nothing returned): JSON syntax
// "<file>:<line>:<column>: invalid JSON: <reason>"; otherwise "<file>: <where>: <problem>"
// with <where> a path into the document such as triangles[12][2] or border[3].point:
// a wrong "format" or "version", unknown or repeated members, a member of the wrong type,
// an array of the wrong length, a value that is not an exact number, a negative
// radius_squared, an index out of range, an unknown rule, a missing or extra "point",
// no vertices. The geometry (degenerate or duplicate cells, overlaps, border rules on edges
// that are not border edges) is checked by MedialComplex, whose messages name the file too.
// Complexity: O(file size) plus the big-number arithmetic of the values.
#pragma once

#include <gmpxx.h>

#include <optional>
#include <string>

#include "complex3/raw_complex.h"

namespace grassfire {

RawComplex parse_complex_json(const std::string& text, const std::string& source);
RawComplex read_complex_json(const std::string& path);

// The document text (one vertex, cell or rule per line).
std::string complex_json_text(const RawComplex& raw);
// Writes complex_json_text to `path` through a temporary file renamed when complete.
void write_complex_json(const RawComplex& raw, const std::string& path);

// A rational as this format writes it: a JSON number when it is a finite decimal, else
// the JSON string "p/q".
std::string rational_json(const mpq_class& q);
// A number of this format, as text: a decimal, or "p/q" with q > 0; nothing otherwise.
std::optional<mpq_class> parse_rational_text(const std::string& text, bool allow_fraction);

}  // namespace grassfire
