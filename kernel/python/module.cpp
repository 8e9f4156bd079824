// module.cpp -- the Python module grassfire (pybind11): the kernel's pipelines from Python.
//
//   import grassfire
//   r = grassfire.edf2d("data/shapes2d/Bone-1.json", exact=True)   # the grassfire-medial2d JSON
//   a = grassfire.medial3d("data/balls/caffeine.cin")                # the axis as numpy arrays
//   b = grassfire.burn3d("board-fin", spacing=0.1)                   # BT, ET per vertex
//   p = grassfire.prune3d((V, F), et=0.2, relative=True)              # a mesh's axis, pruned
// Every function (edf2d, prune2d, match2d, validate, shapes, medial3d, burn3d, complex,
// curves3d, paths3d, prune3d) runs the same kernel code as the program's command of the same name and returns
// what its --json writes, with numpy arrays (bind_2d.cpp, bind_3d.cpp, bind_3d_analysis.cpp;
// inputs: python_inputs.h). The GIL is released while the kernel computes.
#include <pybind11/pybind11.h>

#include <map>

#include "bindings.h"
#include "grassfire_version.h"
#include "support/progress.h"

namespace py = pybind11;

namespace grassfire::python {

ImageShapeOptions image_options(const py::dict& options) {
  std::map<std::string, std::string> named;
  for (const auto& [key, value] : options) {
    const std::string k = py::str(key);
    named[k] = py::isinstance<py::bool_>(value) ? (value.cast<bool>() ? "true" : "false") : std::string(py::str(value));
  }
  return parse_image_shape_options(named);
}

}  // namespace grassfire::python

PYBIND11_MODULE(grassfire, m) {
  m.doc() = "grassfire: exact medial geometry (Liu 2011): medial axes, EDF, EMA, burning times.";
  m.attr("__version__") = GRASSFIRE_VERSION;
  m.def(
      "set_verbosity", [](const std::string& v) { grassfire::set_verbosity(grassfire::parse_verbosity(v)); },
      py::arg("verbosity"),
      "What long runs print on stderr: 'quiet' (nothing), 'normal' (notes), 'progress' (notes and\n"
      "progress lines) or 'auto' (progress when stderr is a terminal; the default).");
  grassfire::python::bind_2d(m);
  grassfire::python::bind_3d(m);
  grassfire::python::bind_3d_analysis(m);
}
