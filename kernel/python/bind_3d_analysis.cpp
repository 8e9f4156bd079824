// bind_3d_analysis.cpp -- grassfire.complex, curves3d, paths3d and prune3d from Python.
//
// Each runs the pipeline the program's command of the same name runs (pipeline/
// complex_input.h, curves3d.h, paths3d.h, prune3d.h) on an input as python_inputs.h takes
// it, without the GIL, and returns the members of the program's --json document (to_python:
// lists of objects become dicts of numpy columns) plus numpy arrays of the geometry.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>

#include "bindings.h"
#include "curves3/medial_curves.h"
#include "burn3/point_sources.h"
#include "io/complex_text.h"
#include "pipeline/complex_input.h"
#include "pipeline/curves3d.h"
#include "pipeline/paths3d.h"
#include "pipeline/prune3d.h"
#include "python_inputs.h"
#include "python_values.h"

namespace py = pybind11;

namespace grassfire::python {

namespace {

// The repair of a defective mesh input, as the program's --repair, --repair-alpha, --repair-offset.
struct RepairArgs {
  bool repair = false;
  std::optional<double> alpha, offset;
  MeshRepairOptions options() const { return mesh_repair_options(repair, alpha, offset); }
};

FieldSetup field_setup(const InputFile& file, const std::string& method, std::optional<double> spacing,
                       bool mesh_is_complex, bool singular_walls, std::uint64_t max_points, const RepairArgs& repair,
                       const py::object& field, const char* command) {
  FieldSetup f;
  if (!field.is_none()) {
    if (!is_path(field)) throw std::invalid_argument("field: a path to the file burn3d --field wrote, or None");
    f.field_file = path_text(field);
  }
  f.repair = repair.options();
  f.input = file.path();
  f.method = method;
  f.spacing = spacing;
  f.mesh_is_complex = mesh_is_complex;
  f.singular_walls = singular_walls;
  f.max_points = max_points;
  f.command = command;
  return f;
}

void name_input(py::dict& out, const py::object& input, const std::string& name) {
  if (!is_path(input)) out["input"] = name;
}

py::dict complex_of(const py::object& input, bool mesh_is_complex, bool no_border_ignition, bool repair,
                    std::optional<double> repair_alpha, std::optional<double> repair_offset, const std::string& name) {
  const MeshRepairOptions repair_options = mesh_repair_options(repair, repair_alpha, repair_offset);
  const InputFile file(input, name);
  std::optional<MedialComplex> mc;
  BettiNumbers betti;
  file.run([&] {
    RawComplex raw = load_complex(file.path(), mesh_is_complex, "complex", repair_options);
    if (no_border_ignition) raw = without_border_ignition(std::move(raw));
    mc.emplace(raw);
    mc->validate();
    betti = complex_betti(*mc);
  });
  py::dict out;
  add_complex(out, *mc);
  out["input"] = is_path(input) ? path_text(input) : name;
  add_report(out, {{"counts",
                    {{"vertices", mc->vertex_count()},
                     {"edges", mc->edge_count()},
                     {"triangles", mc->triangle_count()},
                     {"segments", mc->count(EdgeStratum::Dangling)},
                     {"border_edges", mc->count(EdgeStratum::Border)},
                     {"singular_edges", mc->count(EdgeStratum::Singular)},
                     {"singular_points", mc->count(VertexKind::SingularPoint)},
                     {"sheets", mc->sheets().size()}}},
                   {"betti", {betti.b0, betti.b1, betti.b2}}});
  return out;
}

// The curve graph's geometry as arrays beside the JSON's columns.
void add_curve_arrays(py::dict& out, const MedialCurves& curves) {
  std::vector<std::array<double, 3>> points;
  for (const CurveNode& n : curves.nodes) points.push_back({n.position[0], n.position[1], n.position[2]});
  std::vector<std::array<std::int64_t, 2>> segments;
  for (const CurveEdge& e : curves.edges) segments.push_back({e.u, e.v});
  out["points"] = row_array(points);
  out["segments"] = row_array(segments);
}

py::dict curves3d(const py::object& input, const std::string& method, std::optional<double> spacing,
                  double arrive_cosine, double depart_cosine, double min_et, std::optional<double> time_margin,
                  double planar_tubularity, bool mesh_is_complex, bool singular_walls, std::uint64_t max_points,
                  bool repair, std::optional<double> repair_alpha, std::optional<double> repair_offset,
                  const py::object& field, const std::string& name) {
  const InputFile file(input, name);
  Curves3dSetup setup;
  setup.field = field_setup(file, method, spacing, mesh_is_complex, singular_walls, max_points,
                             {repair, repair_alpha, repair_offset}, field, "curves3d");
  setup.curves.arrive_cosine = arrive_cosine;
  setup.curves.depart_cosine = depart_cosine;
  setup.curves.min_et_fraction = min_et;
  if (time_margin) {
    if (!(*time_margin >= 0)) throw std::invalid_argument("--time-margin must be >= 0");
    setup.curves.time_margin = *time_margin;
  }
  setup.planar_tubularity = planar_tubularity;
  std::optional<Curves3dRun> run;
  file.run([&] { run.emplace(curves3d(setup)); });
  py::dict out;
  add_report(out, file.named(run->json));
  add_curve_arrays(out, run->curves);
  name_input(out, input, name);
  return out;
}

py::dict paths3d(const py::object& input, const std::string& from, const py::object& points, const std::string& method,
                 std::optional<double> spacing, bool mesh_is_complex, bool singular_walls, std::uint64_t max_points,
                 bool repair, std::optional<double> repair_alpha, std::optional<double> repair_offset,
                 const py::object& field, const std::string& name) {
  const InputFile file(input, name);
  Paths3dSetup setup;
  setup.from = from;
  if ((from == "points") != !points.is_none()) throw std::invalid_argument("points go with from='points'");
  const BurnPoints p = points_of(points, "points", 3);
  setup.points_name = p.file ? *p.file : p.name;
  setup.points = p.file ? read_point_csv(*p.file, false) : p.rows;
  setup.field = field_setup(file, method, spacing, mesh_is_complex, singular_walls, max_points,
                            {repair, repair_alpha, repair_offset}, field, "paths3d");
  std::optional<Paths3dRun> run;
  file.run([&] { run.emplace(paths3d(setup)); });
  py::dict out;
  add_report(out, file.named(run->json));
  out["farthest"] = run->farthest;
  name_input(out, input, name);
  return out;
}

std::optional<mpq_class> threshold(const py::object& x, const char* name) {
  if (x.is_none()) return std::nullopt;
  return exact_threshold(x, name);
}

py::dict prune3d(const py::object& input, const py::object& et, const py::object& st, bool relative,
                 const std::string& method, std::optional<double> spacing, bool mesh_is_complex, bool singular_walls,
                 std::uint64_t max_points, bool repair, std::optional<double> repair_alpha,
                 std::optional<double> repair_offset, const py::object& field, const std::string& name) {
  const InputFile file(input, name);
  Prune3dSetup setup = default_prune3d_setup();
  setup.erosion = threshold(et, "et");
  setup.tubularity = threshold(st, "st");
  setup.relative = relative;
  if (relative && !setup.erosion) throw std::invalid_argument("--relative needs --et");
  setup.field = field_setup(file, method, spacing, mesh_is_complex, singular_walls, max_points,
                             {repair, repair_alpha, repair_offset}, field, "prune3d");
  std::optional<Prune3dRun> run;
  file.run([&] { run.emplace(prune3d(setup)); });
  py::dict out;
  add_complex(out, *run->pruned_complex);
  std::vector<double> r, bt, et_values;
  for (const PrunedVertex3& v : run->pruned.vertices) r.push_back(v.radius), bt.push_back(v.bt), et_values.push_back(v.bt - v.radius);
  out["R"] = float_array(r);
  out["BT"] = float_array(bt);
  out["ET"] = float_array(et_values);
  nlohmann::json report = run->report;
  for (const char* key : {"vertex_values", "triangles", "segments"}) report.erase(key);
  add_report(out, file.named(report));
  name_input(out, input, name);
  return out;
}

}  // namespace

void bind_3d_analysis(py::module_& m) {
  m.def("complex", &complex_of, py::arg("input"), py::arg("mesh_is_complex") = false,
        py::arg("no_border_ignition") = false, py::arg("repair") = false, py::arg("repair_alpha") = py::none(), py::arg("repair_offset") = py::none(),
        py::arg("name") = "array",
        R"doc(Load a 2-complex, validate it exactly and describe its strata (grassfire complex).

input               as burn3d's (a complex file, a shape, arrays, a synthetic name)
mesh_is_complex     take a mesh itself as the complex (R = 0)
no_border_ignition  every border edge's rule set to never
repair, repair_alpha, repair_offset: a defective mesh input repaired first, as medial3d's

Returns "vertices" (n, 3), "triangles" (m, 3), "segments" (k, 2), "R" (n,), "counts" (the
program's line: vertices, edges, triangles, segments, border_edges, singular_edges,
singular_points, sheets) and "betti" [b0, b1, b2] by simplicial homology.

>>> import grassfire
>>> c = grassfire.complex("book:3")
>>> c["counts"]["singular_edges"] > 0, c["betti"].tolist()
(True, [1, 0, 0]))doc");
  m.def("curves3d", &curves3d, py::arg("input"), py::arg("method") = "discrete", py::arg("spacing") = py::none(),
        py::arg("arrive_cosine") = 0.5, py::arg("depart_cosine") = 0.1, py::arg("min_et") = 0.0,
        py::arg("time_margin") = py::none(), py::arg("planar_tubularity") = 0.5, py::arg("mesh_is_complex") = false,
        py::arg("singular_walls") = false, py::arg("max_points") = 50'000'000, py::arg("repair") = false, py::arg("repair_alpha") = py::none(), py::arg("repair_offset") = py::none(),
        py::arg("field") = py::none(), py::arg("name") = "array",
        R"doc(Medial curves of a 3D medial axis and its planar / tubular split (grassfire curves3d --json).

input              as burn3d's
method, spacing    the burning field: "discrete" (Steiner spacing h) or "exact" (h: the
                   spacing of the traced edge points); default h: 1/100 of the diagonal
arrive_cosine, depart_cosine, min_et, time_margin, planar_tubularity: as the options of
                   the same names (grassfire curves3d --help)
repair, repair_alpha, repair_offset: a defective mesh input repaired first, as medial3d's
field              the path of the burning burn3d --field wrote for this input (discrete):
                   read instead of burning again, the same curves; refused (ValueError
                   or RuntimeError naming the file) when burned on another complex

Returns the members of the grassfire-curves3d JSON ("nodes" columns x, y, z, R, bt, et;
"edges" columns u, v, length, kind; "betti", "axis_betti", "analysis", ...) and the graph
as arrays: "points" (n, 3) and "segments" (m, 2).

>>> import grassfire
>>> c = grassfire.curves3d("annulus", spacing=0.25)
>>> c["betti"].tolist(), c["points"].shape[1]
([1, 1], 3))doc");
  m.def("paths3d", &paths3d, py::arg("input"), py::arg("from_") = "ends", py::arg("points") = py::none(),
        py::arg("method") = "discrete", py::arg("spacing") = py::none(), py::arg("mesh_is_complex") = false,
        py::arg("singular_walls") = false, py::arg("max_points") = 50'000'000, py::arg("repair") = false, py::arg("repair_alpha") = py::none(), py::arg("repair_offset") = py::none(),
        py::arg("field") = py::none(), py::arg("name") = "array",
        R"doc(Burning paths on a 3D medial axis (grassfire paths3d --json).

input    as burn3d's
from_    "vertices", "curves", "ends" (the paths ending on the medial curves) or "points"
points   with from_="points": a CSV path (x,y,z) or an (n, 3) array; each point is
         located exactly at its nearest point of the complex
repair, repair_alpha, repair_offset: a defective mesh input repaired first, as medial3d's
field    as curves3d's: the burning burn3d --field wrote, read instead of burning again

Returns the members of the grassfire-paths3d JSON: "paths" with columns "bt", "length"
and "points" (a list of (k, 3) arrays, from the point back to where its fire started), and
"farthest" (from_="points": the largest distance from a point to the complex).

>>> import numpy as np, grassfire
>>> p = grassfire.paths3d("board-fin", from_="points", points=np.array([[-2.0, 3.0, 0.0]]), spacing=0.25)
>>> round(float(p["paths"]["bt"][0]), 9)
3.0)doc");
  m.def("prune3d", &prune3d, py::arg("input"), py::arg("et") = py::none(), py::arg("st") = py::none(),
        py::arg("relative") = false, py::arg("method") = "exact", py::arg("spacing") = py::none(),
        py::arg("mesh_is_complex") = false, py::arg("singular_walls") = false, py::arg("max_points") = 50'000'000,
        py::arg("repair") = false, py::arg("repair_alpha") = py::none(), py::arg("repair_offset") = py::none(),
        py::arg("field") = py::none(), py::arg("name") = "array",
        R"doc(The 3D medial axis pruned by ET and ST thresholds, keeping its topology (grassfire prune3d --json).

input     as burn3d's
et        keep ET = BT - R >= et (a fraction of the axis' largest R with relative): a float
          (its exact binary value) or a decimal string (read exactly, as --et)
st        keep ST = 1 - R / BT >= st, in [0, 1]
method    "exact" (default) or "discrete" (the baseline), with spacing as burn3d's
repair, repair_alpha, repair_offset: a defective mesh input repaired first, as medial3d's
field     as curves3d's (with method="discrete")

Cuts exactly along the threshold lines of the piecewise-linear fields and removes failing
parts only by collapses from the free border inward (kernel/curves3/axis_pruning3.h).
Returns "vertices", "triangles", "segments", "R", "BT", "ET" of the pruned axis as numpy
arrays and the members of the grassfire-pruned3d report ("axis", "refined", "removed",
"pruned" with their Betti numbers, "uncertified", "seconds", ...).

>>> import grassfire
>>> p = grassfire.prune3d("tube", et=3.5, spacing=0.5)
>>> p["pruned"]["betti"].tolist(), bool(p["vertices"][:, 2].min() >= 3.5 - 1e-9)
([1, 1, 0], True))doc");
}

}  // namespace grassfire::python
