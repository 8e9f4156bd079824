// field_input.h -- the burning field a 3D analysis command works on (curves3d, paths3d,
// prune3d): the options those commands share (--method, --spacing, --singular-walls,
// --max-points, --mesh-is-complex, --field) and the field they select (pipeline/burn3d_field.h,
// which the Python module calls too).
#pragma once

#include <string>

#include "pipeline/burn3d_field.h"
#include "tools/options.h"

namespace grassfire::cli {

using FieldInput = FieldRun;

// `default_method`: the method when --method is not given.
void declare_field_options(Options& opt, const std::string& default_method = "discrete");
FieldSetup field_setup(const Options& opt, const std::string& input, const std::string& command);
FieldInput load_field(const Options& opt, const std::string& input, const std::string& command);

}  // namespace grassfire::cli
