// bind_3d.cpp -- grassfire.medial3d and grassfire.burn3d from Python.
//
// medial3d builds the axis as `grassfire medial3d` does (complex3/builders/
// medial_axis_input.h), burn3d loads and burns as `grassfire burn3d` does
// (pipeline/burn3d.h). Both return a dict: the complex as numpy arrays ("vertices" (n, 3),
// "triangles" (m, 3), "segments" (k, 2), "R" (n,)), for burn3d also "BT" and "ET" (n,)
// with inf where nothing burns, and the members of the program's --json report (for
// burn3d without "vertex_values", which the arrays replace).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.h"
#include "complex3/builders/medial_axis_input.h"
#include "complex3/medial_complex.h"
#include "pipeline/burn3d.h"
#include "python_values.h"

namespace py = pybind11;

namespace grassfire::python {

namespace {

void add_complex(py::dict& out, const MedialComplex& mc) {
  std::vector<std::array<double, 3>> vertices;
  std::vector<double> radius;
  for (const ComplexVertex& v : mc.vertices()) vertices.push_back(v.approx), radius.push_back(v.radius);
  std::vector<std::array<std::int64_t, 3>> triangles;
  for (const ComplexTriangle& t : mc.triangles()) triangles.push_back({t.v[0], t.v[1], t.v[2]});
  std::vector<std::array<std::int64_t, 2>> segments;
  for (const ComplexEdge& e : mc.edges())
    if (e.stratum == EdgeStratum::Dangling) segments.push_back({e.v[0], e.v[1]});
  out["vertices"] = row_array(vertices);
  out["triangles"] = row_array(triangles);
  out["segments"] = row_array(segments);
  out["R"] = float_array(radius);
}

void add_report(py::dict& out, const nlohmann::json& report, const char* skip = nullptr) {
  for (const auto& item : report.items())
    if (!skip || item.key() != skip) out[py::str(item.key())] = to_python(item.value());
}

py::dict medial3d(const std::string& path, const std::string& kind, int samples) {
  if (samples < 1 || samples > 64) throw std::invalid_argument("samples must be in [1, 64], got " + std::to_string(samples));
  const MedialInputKind k = parse_medial_input_kind(kind);
  std::optional<MedialAxisBuild> axis;
  std::optional<MedialComplex> mc;
  {
    py::gil_scoped_release release;
    axis.emplace(build_medial_axis(path, k, samples));
    mc.emplace(axis->complex);
    mc->validate();
  }
  py::dict out;
  add_complex(out, *mc);
  add_report(out, axis->report);
  return out;
}

// The methods and inputs burn3d takes in this build; what is not built yet raises
// NotImplementedError with the program's message.
void check_burn_request(const std::string& method, const py::object& sources, const py::object& at) {
  // The program's messages (tools/burn3d.cpp, tools/burn3d_exact.cpp).
  if (method == "exact")
    raise_not_implemented("method 'exact' is not available yet: the exact window-propagation engine (issue 8) "
                          "has not landed; use --method discrete");
  if (method != "discrete") throw py::value_error("unknown method '" + method + "' (discrete or exact)");
  if (!sources.is_none()) raise_not_implemented("sources: point sources are not part of this build");
  if (!at.is_none()) raise_not_implemented("at: query points are not part of this build");
}

py::dict burn3d(const std::string& input, const std::string& method, const py::object& sources, const py::object& at,
                std::optional<double> spacing, bool mesh_is_complex, std::uint64_t max_points) {
  check_burn_request(method, sources, at);
  Burn3dOptions o;
  o.spacing = spacing;
  o.max_points = max_points;
  std::optional<MedialComplex> mc;
  std::optional<DiscreteBurning> d;
  nlohmann::json report;
  {
    py::gil_scoped_release release;
    mc.emplace(load_burn_complex(input, mesh_is_complex));
    mc->validate();
    d.emplace(burn3d_discrete(*mc, o));
    report = burn3d_report(input, *mc, *d);
  }
  py::dict out;
  add_complex(out, *mc);
  out["BT"] = float_array(d->vertex_bt);
  out["ET"] = float_array(d->vertex_et);
  add_report(out, report, "vertex_values");
  return out;
}

}  // namespace

void bind_3d(py::module_& m) {
  m.def("medial3d", &medial3d, py::arg("path"), py::arg("kind") = "auto", py::arg("samples") = 1,
        R"doc(The medial axis of a convex polyhedron, a union of balls or a closed mesh (grassfire medial3d).

path     a mesh (.off .ply .obj), a half-space list (.hs .halfspaces) or a ball list (.cin .balls)
kind     "auto", "convex", "balls" or "mesh" (as --kind)
samples  mesh kind: split every triangle edge into this many parts for the samples

Returns {"vertices": (n, 3), "triangles": (m, 3), "segments": (k, 2), "R": (n,)} as numpy
arrays, and the members of the program's --json report ("axis", "shape", timings, ...).)doc");
  m.def("burn3d", &burn3d, py::arg("input"), py::arg("method") = "discrete", py::arg("sources") = py::none(),
        py::arg("at") = py::none(), py::arg("spacing") = py::none(), py::arg("mesh_is_complex") = false,
        py::arg("max_points") = 50'000'000,
        R"doc(Burning time BT and ET = BT - R on the medial axis of a 3D shape (grassfire burn3d).

input            a .ma medial axis, a shape (as medial3d) or a synthetic complex name
                 (board-fin, book:3, ...)
method           "discrete" (the baseline; "exact" raises until the exact engine is built)
sources, at      point sources and query points (raise NotImplementedError in this build)
spacing          Steiner spacing h (default: 1/100 of the bounding box diagonal)
mesh_is_complex  burn a mesh itself as a 2-complex (R = 0)
max_points       refuse to place more graph points than this

Returns "vertices", "triangles", "segments", "R", "BT", "ET" as numpy arrays (inf where
nothing burns) and the program's --json report members ("complex", "stats", "summary", ...).)doc");
}

}  // namespace grassfire::python
