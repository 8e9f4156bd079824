// load_shape.h -- a shape from a command-line argument: a file or a built-in name.
//
// Computes: the validated, normalized Shape2 named by `arg`:
//   - "builtin:NAME": the built-in shape NAME (shapes/builtin_shapes.h);
//   - an existing file ending in .json (io/shape_json.h), .wkt or .txt (WKT, io/shape_wkt.h),
//     or .png or .gif (a binary image: its foreground as shapes/image_shape.h takes it, with
//     the given image options);
//   - otherwise, when no such file exists and arg is a built-in name, that built-in.
// Anything else is an error whose message names the argument, says what was tried, and
// lists the built-in names. File shapes are named by their path, built-ins by their name.
// Errors: ShapeFormatError (unreadable or malformed file), InvalidShapeError (a shape that
// breaks the contract of geometry2/shape2.h), ImageFormatError and ImageShapeError (images),
// std::invalid_argument (nothing matches).
// Complexity: that of the reader plus validate_shape.
#pragma once

#include <string>

#include "io/image_raster.h"
#include "shapes/image_shape.h"
#include "geometry2/shape2.h"
#include "shapes/validate_shape.h"

namespace grassfire {

// When `report` is given it receives what validate_shape found (vertex counts, reorientation).
Shape2 load_shape(const std::string& arg, ShapeValidation* report = nullptr);
Shape2 load_shape(const std::string& arg, const ImageShapeOptions& image, ShapeValidation* report = nullptr);

}  // namespace grassfire
