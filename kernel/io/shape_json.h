// shape_json.h -- the JSON polygon format of the 2D Shape Structure dataset (data/shapes2d).
//
// Format: an object whose member "points" is an array of objects {"x": number, "y": number},
// the vertices of one ring (the outer boundary) in order, the closing edge implicit; other
// members (the dataset's "triangles") are ignored. A repeated first vertex at the end is
// allowed; validate_shape drops it. The format has no holes: write shapes with holes as WKT.
// Reading: nlohmann::json converts decimal numbers with strtod (correctly rounded); values
// must be finite numbers. Errors (ShapeFormatError) start with the source and give the line
// and column of a syntax error, or the element (e.g. "points[12].y") of a bad value.
// The result is not validated: call validate_shape (or use io/load_shape.h).
// Complexity: O(file size).
#pragma once

#include <ostream>
#include <string>

#include "io/shape_format.h"
#include "geometry2/shape2.h"

namespace grassfire {

// `source` names the text in messages and becomes the shape's name.
Shape2 parse_shape_json(const std::string& text, const std::string& source);
Shape2 read_shape_json(const std::string& path);

// Writes {"points":[...]} with coordinates that read back exactly. Throws
// std::invalid_argument for a shape with holes (the format has one ring).
void write_shape_json(const Shape2& shape, std::ostream& out);

}  // namespace grassfire
