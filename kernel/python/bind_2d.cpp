// bind_2d.cpp -- grassfire.edf2d, prune2d, match2d, validate and shapes: the 2D pipelines (pipeline/edf2d.h,
// prune2d.h, match2d.h) from Python.
//
// A shape is a file path or built-in name (as the program's SHAPE argument, images
// included), an (n, 2) array of floats (one ring), a list of such arrays (the outer ring,
// then holes), a shapely polygon or a 2D boolean array (python_inputs.h). Arrays are
// validated and normalized exactly as files are (shapes/validate_shape.h). Each result is
// the document the program's --json writes (grassfire-medial2d, -pruned2d, -match2d), as
// Python values (python_values.h), so the two are equal member by member.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "bindings.h"
#include "io/disk_list.h"
#include "pipeline/edf2d.h"
#include "pipeline/edf2d_json.h"
#include "apps2d/match2d.h"
#include "pipeline/prune2d.h"
#include "pipeline/shape_report.h"
#include "io/shape_json.h"
#include "shapes/builtin_shapes.h"
#include "python_inputs.h"
#include "python_values.h"
#include "shapes/image_shape.h"
#include "io/load_shape.h"

namespace py = pybind11;

namespace grassfire::python {

namespace {

py::dict edf2d(const py::object& shape, std::size_t samples, bool exact, const std::string& variant,
               std::optional<double> spacing, const std::string& name, const ImageShapeOptions& image,
               bool image_given) {
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
  const Shape2 s = shape_of(shape, name, image, image_given);
  std::string json;
  {
    py::gil_scoped_release release;
    const Edf2dResult r = compute_edf2d(s, options);
    json = edf2d_json(s, options, r);
  }
  return to_python(nlohmann::json::parse(json)).cast<py::dict>();
}

// exact_threshold (python_inputs.h), non-negative.
mpq_class threshold_of(const py::object& x, const char* name) {
  const mpq_class v = exact_threshold(x, name);
  if (sgn(v) < 0) throw std::invalid_argument(std::string(name) + " must be non-negative");
  return v;
}

py::dict prune2d(const py::object& shape, const py::object& et, const py::object& st, bool relative, bool topology,
                 std::size_t samples, bool exact, const std::string& name, const py::dict& image) {
  Prune2dSetup setup;
  setup.erosion = threshold_of(et, "et");
  setup.tubularity = threshold_of(st, "st");
  setup.relative = relative;
  setup.topology = topology;
  if (samples < 8) throw std::invalid_argument("samples must be at least 8, got " + std::to_string(samples));
  setup.options.samples = samples;
  if (exact) setup.options.axis = AxisMethod::ExactPolygon;
  const Shape2 s = shape_of(shape, name, image_options(image), !image.empty());
  std::string json;
  {
    py::gil_scoped_release release;
    json = prune2d(s, setup).json;
  }
  return to_python(nlohmann::json::parse(json)).cast<py::dict>();
}

py::dict match2d(const py::object& a, const py::object& b, const std::string& signature, std::size_t samples,
                 double stretch, const py::dict& image) {
  Match2dSetup setup;
  setup.signature = signature;
  setup.samples = samples;
  setup.stretch = stretch;
  const ImageShapeOptions o = image_options(image);
  const Shape2 sa = shape_of(a, "a", o, !image.empty()), sb = shape_of(b, "b", o, !image.empty());
  std::string json;
  {
    py::gil_scoped_release release;
    json = match2d(sa, sb, setup).json;
  }
  return to_python(nlohmann::json::parse(json)).cast<py::dict>();
}

py::dict validate(const py::object& shape, const std::string& name, const ImageShapeOptions& image, bool image_given) {
  ShapeValidation report;
  const Shape2 s = shape_of(shape, name, image, image_given, &report);
  return to_python(nlohmann::json::parse(shape_validation_json(s, report))).cast<py::dict>();
}

py::dict shapes(const std::optional<std::string>& name) {
  if (!name) return to_python(nlohmann::json::parse(builtin_shapes_json())).cast<py::dict>();
  if (!is_builtin_shape(*name))
    throw std::invalid_argument("no built-in shape '" + *name + "' (built-in: " + builtin_shape_names() + ")");
  std::ostringstream out;
  write_shape_json(builtin_shape(*name), out);
  return to_python(nlohmann::json::parse(out.str())).cast<py::dict>();
}

}  // namespace

void bind_2d(py::module_& m) {
  m.def(
      "edf2d",
      [](const py::object& shape, std::size_t samples, bool exact, const std::string& variant,
         std::optional<double> spacing, const std::string& name, const py::dict& image) {
        return edf2d(shape, samples, exact, variant, spacing, name, image_options(image), !image.empty());
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
"inf". Errors raise ValueError or RuntimeError with the program's message.

>>> import grassfire
>>> r = grassfire.edf2d("rectangle", samples=200)
>>> r["format"], r["ema"]["kind"]
('grassfire-medial2d', 'point'))doc");
  m.def("prune2d", &prune2d, py::arg("shape"), py::arg("et") = 0.0, py::arg("st") = 0.0, py::arg("relative") = false,
        py::arg("topology") = false, py::arg("samples") = kDefaultSamples, py::arg("exact") = false,
        py::arg("name") = "array", py::arg("image") = py::dict(),
        R"doc(The medial axis pruned by ET and ST thresholds (grassfire prune2d --json).

shape     as edf2d's (a path, a built-in name, (n, 2) arrays, a shapely polygon, a 2D
          boolean array)
et        ET threshold T (shape units; a fraction of the shape's size with relative): a
          float (its exact binary value) or a decimal string (read exactly, as --et)
st        ST threshold S in [0, 1], likewise
relative  T is a fraction of the shape's size (the larger side of its bounding box)
topology  peel failing leaves only (the thinning of 3.3.2): keeps the homotopy type
samples   boundary samples of the sampled axis; exact: the exact polygon axis
image     image options, as edf2d's

Returns the members of the grassfire-pruned2d JSON (kernel/pipeline/prune2d.h): "nodes"
and "edges" as dicts of numpy columns, "thresholds", "error_bound".

>>> import grassfire
>>> r = grassfire.prune2d("blunt-sharp", et=0.05, relative=True, st=0.3, topology=True)
>>> r["format"], len(r["nodes"]["x"]) > 0
('grassfire-pruned2d', True))doc");
  m.def("match2d", &match2d, py::arg("a"), py::arg("b"), py::arg("signature") = "be", py::arg("samples") = 200,
        py::arg("stretch") = 0.05, py::arg("image") = py::dict(),
        R"doc(Boundary correspondence of two planar shapes guided by a signature (grassfire match2d --json).

a, b       shapes, as edf2d's
signature  "be" (boundary eccentricity), "lfs" (local feature size) or "curvature"
samples    boundary samples per shape, in [8, 2000] (the DP costs O(N^3))
stretch    cost of a step where only one curve advances (normalised units)

Returns the members of the grassfire-match2d JSON (kernel/apps2d/match2d.h): "cost",
"offset", "path" (k, 2), "correspondence" (N,), "a_samples"/"b_samples" columns x, y, value.

>>> import grassfire
>>> m = grassfire.match2d("rectangle", "rectangle-bump", samples=40)
>>> m["correspondence"].shape
(40,))doc");
  m.def(
      "validate",
      [](const py::object& shape, const std::string& name, const py::dict& image) {
        return validate(shape, name, image_options(image), !image.empty());
      },
      py::arg("shape"), py::arg("name") = "array", py::arg("image") = py::dict(),
      R"doc(Checks a planar shape exactly and describes it (grassfire validate --json).

shape  as edf2d's (a path, a built-in name, (n, 2) arrays, a shapely polygon, a 2D boolean
       array)
name   the shape's name in messages and in the result, for arrays
image  image options, as edf2d's

Returns the members of the grassfire-shape-validation JSON (kernel/pipeline/shape_report.h):
per ring its vertices, the repeated vertices dropped, whether it was reversed, its signed
area and that area's certified error; the area; the exact predicates used. An invalid shape
raises ValueError with the program's message (the first problem found).

>>> import grassfire
>>> v = grassfire.validate("hole")
>>> v["valid"], v["area"], v["rings"]["orientation"]
(True, 56.875, ['ccw', 'cw']))doc");
  m.def("shapes", &shapes, py::arg("name") = py::none(),
        R"doc(The built-in shapes (grassfire shapes --list-json), or one of them (grassfire shapes --json NAME).

name  None for the list ("shapes": name, description, rings, vertices of each), or a
      built-in name for that shape in the shapes2d JSON format

>>> import grassfire
>>> "rectangle" in list(grassfire.shapes()["shapes"]["name"])
True)doc");
}

}  // namespace grassfire::python
