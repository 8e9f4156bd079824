// field_input.h -- the burning field a 3D analysis command works on (curves3d, paths3d).
//
// Declares the options shared by those commands (--method, --spacing, --max-points,
// --mesh-is-complex) and builds, from INPUT (pipeline/complex_input.h), the validated
// MedialComplex and a BurningField over it (burn3/burning_field.h): `discrete` runs the
// baseline (burn3/discrete/discrete_burning.h) with the Steiner spacing h (default: 1/100 of the
// bounding box diagonal) and wraps it (burn3/discrete/discrete_burning_field.h); `exact` runs the
// window-propagation engine from the border ignition (burn3/exact/exact_burning.h; refused
// on complexes it cannot burn as Definition 9 unless --singular-walls) and wraps it
// (burn3/exact/exact_burning_field.h), with --spacing the spacing of the edge points at
// which medial curves are traced. A new method is a new branch in load_field that returns
// another BurningField.
#pragma once

#include <memory>
#include <string>

#include "burn3/burning_field.h"
#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/exact_burning.h"
#include "tools/options.h"

namespace grassfire::cli {

struct FieldInput {
  std::unique_ptr<MedialComplex> complex;
  std::unique_ptr<DiscreteBurning> burning;  // the discrete method's graph values
  std::unique_ptr<ExactBurning> exact;       // the exact method's engine
  std::unique_ptr<BurningField> field;
};

void declare_field_options(Options& opt);
FieldInput load_field(const Options& opt, const std::string& input, const std::string& command);

}  // namespace grassfire::cli
