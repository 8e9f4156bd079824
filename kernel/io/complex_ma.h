// complex_ma.h -- the .ma medial-axis format of Q-MAT and the erosion-thickness code.
//
// Accepted (reading): after optional blank lines and `#` comments, a header line
// `nv ne nf` (three non-negative integers), then exactly nv lines `v x y z r`, ne lines
// `e i j` and nf lines `f i j k` in any order (Q-MAT writes them in this order), with
// 0-based vertex indices. Numbers are decimals ([+-]digits[.digits][e[+-]digits]); they
// are stored exactly: vertex coordinates as the rationals written, R^2 = r^2 for the
// radius r as written (r >= 0). Faces must be triangles. Edges that are edges of a face
// are implied by it and dropped; the others become the complex's 1-dimensional segments
// (duplicate `e` lines are merged). Every border edge ignites with the Linear rule (f
// interpolates R). Rejected with "<file>:<line>: <problem>": a missing or malformed
// header, counts that differ from the lines present, an unknown line tag, a wrong number
// of fields, NaN/inf/non-numeric values, negative r, indices out of range, an edge from a
// vertex to itself, nv = 0. Geometric problems (coincident vertices, degenerate or
// duplicate triangles) are left to MedialComplex, which names the file too.
// Writing: all unique edges (face edges and segments), as Q-MAT does; coordinates and r
// exactly when they are decimals (r when R^2 is the square of one), else the nearest
// double, in which case write_ma returns false.
#pragma once

#include <ostream>
#include <string>

#include "complex3/raw_complex.h"

namespace grassfire {

RawComplex parse_ma(const std::string& text, const std::string& source);
RawComplex read_ma(const std::string& path);
// True when every value was written exactly.
bool write_ma(const RawComplex& complex, std::ostream& out);
bool write_ma_file(const RawComplex& complex, const std::string& path);

}  // namespace grassfire
