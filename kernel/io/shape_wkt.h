// shape_wkt.h -- planar polygons with holes as OGC Well-Known Text (Simple Features Access,
// ISO 19125-1), the plain-text polygon format that GIS tools (GEOS, Shapely, PostGIS,
// QGIS, CGAL's IO/WKT.h) read and write.
//
// Format read:
//   POLYGON ((x y, x y, ...), (x y, x y, ...), ...)
// The first ring is the outer boundary, the others are holes; vertices in order. Keywords
// are case-insensitive; whitespace, newlines included, may separate any two tokens. The
// standard closes every ring (its last point repeats the first); an unclosed ring is read
// too (the closing edge is implicit); validate_shape drops the repeated point. Also read:
// MULTIPOLYGON (((...), (...))) holding exactly one polygon (more is an error: a grassfire
// shape is one polygon with holes); one trailing ';'. Rejected with a message: EMPTY,
// Z / M / ZM (three- and four-dimensional coordinates), other geometry types.
// Numbers: [+|-]digits[.digits][(e|E)[+|-]digits] (or .digits), converted to the nearest
// double by std::from_chars (correctly rounded like strtod, independent of the locale);
// NaN, infinities and out-of-range values are errors.
// Errors (ShapeFormatError): "<source>:<line>:<column>: <problem>", 1-based positions.
// Writing: POLYGON with one ring per line, each closed, coordinates printed as the shortest
// decimals that read back exactly, so write then read returns the same doubles.
// The result is not validated: call validate_shape (or use io/load_shape.h).
// Complexity: O(file size).
#pragma once

#include <ostream>
#include <string>

#include "io/shape_format.h"
#include "geometry2/shape2.h"

namespace grassfire {

// `source` names the text in messages and becomes the shape's name.
Shape2 parse_shape_wkt(const std::string& text, const std::string& source);
Shape2 read_shape_wkt(const std::string& path);

void write_shape_wkt(const Shape2& shape, std::ostream& out);
std::string to_wkt(const Shape2& shape);

}  // namespace grassfire
