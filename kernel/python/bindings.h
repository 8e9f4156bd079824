// bindings.h -- the parts of the Python module grassfire (one function per file that adds them).
//
// module.cpp makes the module and calls these; each binds one area of the kernel:
// bind_2d.cpp (edf2d, prune2d, match2d), bind_3d.cpp (medial3d, burn3d), bind_3d_analysis.cpp
// (complex, curves3d, paths3d, prune3d). Errors: the kernel's exceptions
// become Python exceptions with the same message as the program prints after
// "grassfire <command>: " (std::invalid_argument -> ValueError, other std::exception ->
// RuntimeError).
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "shapes/image_shape.h"

namespace grassfire::python {

void bind_2d(pybind11::module_& m);
void bind_3d(pybind11::module_& m);
void bind_3d_analysis(pybind11::module_& m);

// The image options of a shape given as an image file, from a dict of the program's option
// names ("connectivity", "contour", "foreground", "threshold", "largest").
ImageShapeOptions image_options(const pybind11::dict& options);

}  // namespace grassfire::python
