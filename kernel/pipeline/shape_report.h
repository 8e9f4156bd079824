// shape_report.h -- what `grassfire validate` and `grassfire shapes` report, as JSON documents
// the program writes (--json) and the Python module returns (grassfire.validate, .shapes).
//
// Computes: the exact validation of a planar shape (shapes/validate_shape.h: simple rings, no
// ring meeting another, holes inside the outer ring and outside each other) with its
// description,
//   {"format": "grassfire-shape-validation", "version": 1, "shape": NAME, "valid": true,
//    "rings": [{"vertices", "input_vertices", "reversed", "orientation": "ccw"|"cw",
//               "signed_area", "signed_area_error"}],
//    "area", "area_error", "candidate_pairs", "orientations_filtered", "orientations_exact"}
// (an invalid shape is an error, not a document: load_shape throws with the first problem),
// and the list of built-in shapes,
//   {"format": "grassfire-builtin-shapes", "version": 1,
//    "shapes": [{"name", "description", "rings", "vertices"}]}.
// Areas are the midpoints of certified enclosures; *_error their radii.
// Contract: `shape` was loaded with `report` (io/load_shape.h), so their rings match.
// Complexity: O(n) in the shape's vertices (the validation itself is load_shape's).
#pragma once

#include <string>

#include "geometry2/shape2.h"
#include "shapes/validate_shape.h"

namespace grassfire {

std::string shape_validation_json(const Shape2& shape, const ShapeValidation& report);

std::string builtin_shapes_json();

}  // namespace grassfire
