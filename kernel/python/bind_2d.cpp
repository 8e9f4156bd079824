// bind_2d.cpp -- grassfire.edf2d: the 2D pipeline (pipeline/edf2d.h) from Python.
//
// The shape is a file path or built-in name (as the program's SHAPE argument, images
// included), an (n, 2) array of floats (one ring) or a list of such arrays (the outer ring,
// then holes). Arrays are validated and normalized exactly as files are
// (shapes/validate_shape.h). The result is the "grassfire-medial2d" document that
// `grassfire edf2d --json` writes (pipeline/edf2d_json.h), as Python values
// (python_values.h), so the two are equal member by member.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.h"
#include "pipeline/edf2d.h"
#include "pipeline/edf2d_json.h"
#include "python_values.h"
#include "shapes/image_shape.h"
#include "io/load_shape.h"

namespace py = pybind11;

namespace grassfire::python {

namespace {

Ring ring_of(const py::handle& points, const std::string& name, std::size_t index) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  if (!a || a.ndim() != 2 || a.shape(1) != 2)
    throw std::invalid_argument(name + ": ring " + std::to_string(index) +
                                " is not an (n, 2) array of coordinates");
  Ring r;
  const auto m = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) r.points.push_back({m(i, 0), m(i, 1)});
  return r;
}

// A str or os.PathLike goes to load_shape; an array is one ring; a list or tuple of
// arrays is the rings.
Shape2 shape_of(const py::object& shape, const std::string& name, const ImageShapeOptions& image) {
  const py::object fspath = py::module_::import("os").attr("fspath");
  if (py::isinstance<py::str>(shape) || py::hasattr(shape, "__fspath__"))
    return load_shape(fspath(shape).cast<std::string>(), image);
  Shape2 s;
  s.name = name;
  const bool one_ring = py::isinstance<py::array>(shape) && shape.cast<py::array>().ndim() == 2;
  if (one_ring) {
    s.rings.push_back(ring_of(shape, name, 0));
  } else if (py::isinstance<py::list>(shape) || py::isinstance<py::tuple>(shape)) {
    std::size_t i = 0;
    for (const py::handle ring : shape) s.rings.push_back(ring_of(ring, name, i++));
  } else {
    throw std::invalid_argument(name + ": a shape is a file path, a built-in name, an (n, 2) array or a list of them");
  }
  validate_shape(s, name);
  return s;
}

py::dict edf2d(const py::object& shape, std::size_t samples, bool exact, const std::string& variant,
               std::optional<double> spacing, const std::string& name, const ImageShapeOptions& image) {
  Edf2dOptions options;
  if (exact) options.axis = AxisMethod::ExactPolygon;
  if (samples < 8) throw std::invalid_argument("samples must be at least 8, got " + std::to_string(samples));
  options.samples = samples;
  if (spacing) {
    if (!(*spacing > 0)) throw std::invalid_argument("spacing must be positive");
    options.spacing = *spacing;
  }
  if (variant == "dissertation")
    options.variant = GrassfireVariant::Dissertation;
  else if (variant != "exact")
    throw std::invalid_argument("variant must be 'exact' or 'dissertation', got '" + variant + "'");
  const Shape2 s = shape_of(shape, name, image);
  std::string json;
  {
    py::gil_scoped_release release;
    const Edf2dResult r = compute_edf2d(s, options);
    json = edf2d_json(s, options, r);
  }
  return to_python(nlohmann::json::parse(json)).cast<py::dict>();
}

}  // namespace

void bind_2d(py::module_& m) {
  m.def(
      "edf2d",
      [](const py::object& shape, std::size_t samples, bool exact, const std::string& variant,
         std::optional<double> spacing, const std::string& name, const py::dict& image) {
        return edf2d(shape, samples, exact, variant, spacing, name, image_options(image));
      },
      py::arg("shape"), py::arg("samples") = kDefaultSamples, py::arg("exact") = false,
      py::arg("variant") = "exact", py::arg("spacing") = py::none(), py::arg("name") = "array",
      py::arg("image") = py::dict(),
      R"doc(Medial axis, EDF, EMA, ET, ST and PR of a planar shape (grassfire edf2d --json).

shape    a file path (.json, .wkt, .txt, .png, .gif), a built-in name, an (n, 2) array
         (one ring) or a list of (n, 2) arrays (the outer ring, then holes)
samples  boundary samples of the sampled axis (ignored with exact=True or spacing)
exact    the exact polygon axis instead of samples
variant  "exact" (the definition) or "dissertation" (the thinning of 3.3.2)
spacing  arc-length spacing of the samples instead of a count
name     the shape's name in messages and in the result, for arrays
image    options for image files: {"connectivity": 4 | 8, "contour": "pixel" |
         "marching-squares", "foreground": "auto" | "dark" | "light" | "opaque",
         "threshold": 0..255, "largest": bool} (grassfire edf2d --help)

Returns the members of the grassfire-medial2d JSON (README): "nodes" and "edges" as dicts
of numpy columns (x, y, R, edf, et, st, pr; u, v, length, kind), inf where the JSON has
"inf". Errors raise ValueError or RuntimeError with the program's message.)doc");
}

}  // namespace grassfire::python
