// builtin_shapes.h -- the named planar shapes embedded in the program: small, exactly
// reproducible stand-ins for the shapes of the dissertation's figures (1.2, 3.2-3.4, 3.6).
//
// Computes: the shape of a given name, validated and normalized (shapes/validate_shape.h),
// coordinates in about [0, 10]. `noisy` is generated: a star-shaped body with five limbs
// whose radius is perturbed by pseudo-random noise from a fixed-seed SplitMix64 stream and
// rounded to 3 decimals; being star-shaped about its centre with increasing angles, it is
// simple whatever the noise (validation confirms it).
// Contract: none. Complexity: O(vertices) per call.
// Section: Fig. 1.2 (rectangle, rectangle-bump), Fig. 3.2 / 3.3 left (branches), Fig. 3.3
// right (hole), Fig. 3.4 (noisy), Fig. 3.6 (blunt-sharp).
#pragma once

#include <string>
#include <vector>

#include "geometry2/shape2.h"

namespace grassfire {

struct BuiltinShapeInfo {
  std::string name;
  std::string description;  // one line
};

// All built-in shapes, in a fixed order.
const std::vector<BuiltinShapeInfo>& builtin_shape_list();
bool is_builtin_shape(const std::string& name);
// "rectangle, rectangle-bump, ..." for messages.
std::string builtin_shape_names();

// The validated shape; its name is `name`. Throws std::invalid_argument for an unknown
// name, listing the built-in names.
Shape2 builtin_shape(const std::string& name);

}  // namespace grassfire
