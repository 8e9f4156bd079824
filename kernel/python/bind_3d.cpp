// bind_3d.cpp -- grassfire.medial3d and grassfire.burn3d from Python.
//
// medial3d builds the axis as `grassfire medial3d` does (complex3/builders/
// medial_axis_input.h), burn3d runs the pipeline `grassfire burn3d` runs
// (pipeline/burn3d.h: the same loader, method table, point location and report). Both
// return a dict: the complex as numpy arrays ("vertices" (n, 3), "triangles" (m, 3),
// "segments" (k, 2), "R" (n,)), for burn3d also "BT" and "ET" (n,) with inf where nothing
// burns, the values at the query points ("at"), and the members of the program's --json
// report (for burn3d without "vertex_values", which the arrays replace).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>

#include "bindings.h"
#include "pipeline/medial_axis_input.h"
#include "complex3/medial_complex.h"
#include "io/complex_text.h"
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

bool is_path(const py::object& x) { return py::isinstance<py::str>(x) || py::hasattr(x, "__fspath__"); }

std::string path_text(const py::object& x) { return py::module_::import("os").attr("fspath")(x).cast<std::string>(); }

// Points as burn3d takes them: None (no points), a CSV file read as the program reads it
// (io/point_csv.h: exact decimals), or an (n, columns) array of floats, each taken at its
// exact binary value; rows are named "<name>:<row from 1>" in messages.
BurnPoints points_of(const py::object& x, const std::string& name, py::ssize_t columns) {
  BurnPoints points;
  points.name = name;
  if (x.is_none()) return points;
  if (is_path(x)) {
    points.file = path_text(x);
    return points;
  }
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
  if (!a || a.ndim() != 2 || a.shape(1) != columns)
    throw std::invalid_argument(name + ": not a CSV path or an (n, " + std::to_string(columns) + ") array of " +
                                (columns == 4 ? "x, y, z, t0" : "x, y, z"));
  const auto m = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    CsvPoint row;
    row.line = static_cast<std::size_t>(i) + 1;
    for (py::ssize_t k = 0; k < columns; ++k)
      if (!std::isfinite(m(i, k)))
        throw std::invalid_argument(name + ":" + std::to_string(i + 1) + ": a value is not a finite number");
    for (int k = 0; k < 3; ++k) row.text[k] = shortest_double(m(i, k));
    row.point = {mpq_class(m(i, 0)), mpq_class(m(i, 1)), mpq_class(m(i, 2))};
    if (columns == 4) row.t0 = mpq_class(m(i, 3));
    points.rows.push_back(std::move(row));
  }
  return points;
}

py::dict burn3d(const py::object& input, const std::string& method, const py::object& sources, const py::object& at,
                std::optional<double> spacing, bool mesh_is_complex, bool no_border_ignition,
                std::uint64_t max_points, bool singular_walls) {
  Burn3dSetup setup;
  setup.input = is_path(input) ? path_text(input) : input.cast<std::string>();
  setup.method = method;
  setup.spacing = spacing;
  setup.mesh_is_complex = mesh_is_complex;
  setup.no_border_ignition = no_border_ignition;
  setup.singular_walls = singular_walls;
  setup.max_points = max_points;
  setup.sources = points_of(sources, "sources", 4);
  setup.queries = points_of(at, "at", 3);
  std::optional<Burn3dRun> run;
  {
    py::gil_scoped_release release;
    run.emplace(burn3d(setup));
  }
  py::dict out;
  add_complex(out, *run->mc);
  out["BT"] = float_array(run->outcome.vertex_bt);
  out["ET"] = float_array(run->et);
  if (!run->outcome.vertex_bt_error.empty()) out["BT_error"] = float_array(run->outcome.vertex_bt_error);
  add_report(out, run->report, "vertex_values");
  if (!at.is_none()) {
    std::vector<double> bt, bt_error, snap;
    std::vector<std::array<double, 3>> points;
    for (std::size_t i = 0; i < run->queries.size(); ++i) {
      bt.push_back(run->outcome.query_values[i].bt);
      bt_error.push_back(run->outcome.query_values[i].bt_error);
      snap.push_back(run->queries[i].snap());
      const Vec3d p = run->queries[i].approx();
      points.push_back({p[0], p[1], p[2]});
    }
    py::dict values;
    values["points"] = row_array(points);
    values["bt"] = float_array(bt);
    values["bt_error"] = float_array(bt_error);
    values["snap"] = float_array(snap);
    out["at"] = values;
  }
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
        py::arg("no_border_ignition") = false, py::arg("max_points") = 50'000'000, py::arg("singular_walls") = false,
        R"doc(Burning time BT and ET = BT - R on the medial axis of a 3D shape (grassfire burn3d).

input               a complex (.json grassfire-complex, .ma), a shape (as medial3d) or a
                    synthetic complex name (board-fin, book:3, ...)
method              "discrete" (the baseline) or "exact" (certified window propagation;
                    raises RuntimeError with the program's message on a complex with
                    singular edges unless singular_walls)
sources             point sources: a CSV path (x,y,z,t0, exact decimals, as --sources) or
                    an (n, 4) array of x, y, z, t0 (each float at its exact value); every
                    source must lie on the complex exactly
at                  query points: a CSV path (x,y,z, as --at) or an (n, 3) array; each is
                    located at its nearest point of the complex
spacing             Steiner spacing h (default: 1/100 of the bounding box diagonal)
mesh_is_complex     burn a mesh itself as a 2-complex (R = 0)
no_border_ignition  the border never ignites: only the sources burn
max_points          refuse to place more graph points than this
singular_walls      exact: burn complexes with singular edges, each a wall (not Definition 9)

Returns "vertices", "triangles", "segments", "R", "BT", "ET" as numpy arrays (inf where
nothing burns), the program's --json report members ("complex", "stats", "summary", ...)
and, with at, "at": {"points" (n, 3) located points, "bt", "bt_error", "snap"}: the
columns of the program's --csv (bt_error is inf for the discrete method, an upper bound).)doc");
}

}  // namespace grassfire::python
