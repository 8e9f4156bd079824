// bind_3d.cpp -- grassfire.medial3d and grassfire.burn3d from Python (inputs: python_inputs.h).
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
#include "python_inputs.h"
#include "python_values.h"
#include "support/progress.h"

namespace py = pybind11;

namespace grassfire::python {

namespace {

py::dict medial3d(const py::object& input, const std::string& kind, double samples, double angle, long refinements,
                  long max_samples, bool repair, std::optional<double> repair_alpha, std::optional<double> repair_offset,
                  const std::string& name) {
  const MeshAxisOptions mesh = medial3d_mesh_options(samples, angle, refinements, max_samples);
  const MeshRepairOptions repair_options = mesh_repair_options(repair, repair_alpha, repair_offset);
  const MedialInputKind k = parse_medial_input_kind(kind);
  const InputFile file(input, name);
  const std::string label = is_path(input) ? path_text(input) : name;
  std::optional<MedialAxisBuild> axis;
  std::optional<MedialComplex> mc;
  file.run([&] {
    // The program's stages and notes (tools/medial3d.cpp), without its writing stage.
    Progress progress("medial3d " + label, 2);
    progress.stage("building the medial axis");
    axis.emplace(build_medial_axis(file.path(), k, mesh, repair_options));
    if (const std::string r = axis->report.value("/mesh_input/repairs"_json_pointer, ""); !r.empty())
      note("medial3d: " + label + ": " + r);
    progress.advance();
    progress.stage("building and validating the complex");
    mc.emplace(axis->complex);
    mc->validate();
    progress.advance();
  });
  py::dict out;
  add_complex(out, *mc);
  add_report(out, file.named(axis->report));
  if (!is_path(input)) out["input"] = name;
  return out;
}

py::dict burn3d(const py::object& input, const std::string& method, const py::object& sources, const py::object& at,
                std::optional<double> spacing, bool mesh_is_complex, bool no_border_ignition,
                std::uint64_t max_points, bool singular_walls, bool repair, std::optional<double> repair_alpha,
                std::optional<double> repair_offset, const std::string& name) {
  const InputFile file(input, name);
  Burn3dSetup setup;
  setup.repair = mesh_repair_options(repair, repair_alpha, repair_offset);
  setup.input = file.path();
  setup.method = method;
  setup.spacing = spacing;
  setup.mesh_is_complex = mesh_is_complex;
  setup.no_border_ignition = no_border_ignition;
  setup.singular_walls = singular_walls;
  setup.max_points = max_points;
  setup.sources = points_of(sources, "sources", 4);
  setup.queries = points_of(at, "at", 3);
  std::optional<Burn3dRun> run;
  file.run([&] { run.emplace(burn3d(setup)); });
  py::dict out;
  add_complex(out, *run->mc);
  out["BT"] = float_array(run->outcome.vertex_bt);
  out["ET"] = float_array(run->et);
  if (!run->outcome.vertex_bt_error.empty()) out["BT_error"] = float_array(run->outcome.vertex_bt_error);
  add_report(out, file.named(run->report), "vertex_values");
  if (!is_path(input)) out["input"] = name;
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
  m.def("medial3d", &medial3d, py::arg("path"), py::arg("kind") = "auto", py::arg("samples") = 1.0,
        py::arg("angle") = 0.0, py::arg("refinements") = 5, py::arg("max_samples") = 2000000,
        py::arg("repair") = false, py::arg("repair_alpha") = py::none(), py::arg("repair_offset") = py::none(), py::arg("name") = "array",
        R"doc(The medial axis of a convex polyhedron, a union of balls or a closed mesh (grassfire medial3d).

path     a mesh (.off .ply .obj), a half-space list (.hs .halfspaces) or a ball list (.cin .balls);
         or a mesh as a (V, F) pair of arrays or an object with .vertices and .faces
         (trimesh), or balls as an (n, 4) array x, y, z, r (each float exactly)
kind     "auto", "convex", "balls" or "mesh" (as --kind)
samples  mesh kind: initial sample spacing = mean edge length / samples, in (0, 1024]
angle    mesh kind: Voronoi faces narrower than angle degrees seen from the axis are
         pruned while the topology allows (0: no angle test; as --angle)
refinements  mesh kind: at most this many halvings of the spacing, in [0, 12]
max_samples  mesh kind: at most this many surface samples in a round, in [1000, 10^9]
         (as --max-samples; memory grows about 2 GB per million samples)
repair   a mesh that does not bound a solid (self-intersecting, non-manifold, open,
         overlapping shells) is repaired first (as --repair): welded, or its holes
         filled, or else alpha-wrapped with repair_alpha and repair_offset (defaults
         1/50 and 1/300 of the bounding box diagonal); the result's "repair" says how
name     names an array input in messages and in the result

Returns {"vertices": (n, 3), "triangles": (m, 3), "segments": (k, 2), "R": (n,)} as numpy
arrays, and the members of the program's --json report ("axis", "shape", timings, ...).

>>> import numpy as np, grassfire
>>> V = np.array([[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2]], float)
>>> F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
>>> a = grassfire.medial3d((V, F))
>>> a["kind"], a["vertices"].shape[1]
('convex', 3))doc");
  m.def("burn3d", &burn3d, py::arg("input"), py::arg("method") = "discrete", py::arg("sources") = py::none(),
        py::arg("at") = py::none(), py::arg("spacing") = py::none(), py::arg("mesh_is_complex") = false,
        py::arg("no_border_ignition") = false, py::arg("max_points") = 50'000'000, py::arg("singular_walls") = false,
        py::arg("repair") = false, py::arg("repair_alpha") = py::none(), py::arg("repair_offset") = py::none(),
        py::arg("name") = "array",
        R"doc(Burning time BT and ET = BT - R on the medial axis of a 3D shape (grassfire burn3d).

input               a complex (.json grassfire-complex, .ma), a shape (as medial3d: a path,
                    (V, F) arrays, an object with .vertices and .faces, (n, 4) balls) or
                    a synthetic complex name (board-fin, book:3, ...)
method              "discrete" (the baseline) or "exact" (the certified window
                    propagation of Definition 9, junction rule on singular edges; also
                    returns "BT_error", a certified bound per vertex)
sources             point sources: a CSV path (x,y,z,t0, exact decimals, as --sources) or
                    an (n, 4) array of x, y, z, t0 (each float at its exact value); every
                    source must lie on the complex exactly
at                  query points: a CSV path (x,y,z, as --at) or an (n, 3) array; each is
                    located at its nearest point of the complex
spacing             Steiner spacing h (default: 1/100 of the bounding box diagonal)
mesh_is_complex     burn a mesh itself as a 2-complex (R = 0)
no_border_ignition  the border never ignites: only the sources burn
max_points          refuse to place more graph points than this
singular_walls      exact: singular edges as walls where fronts stop (an upper bound, not
                    Definition 9)
repair, repair_alpha, repair_offset: a defective mesh input repaired first, as medial3d's
name                names an array input in messages and in the result

Returns "vertices", "triangles", "segments", "R", "BT", "ET" as numpy arrays (inf where
nothing burns), the program's --json report members ("complex", "stats", "summary", ...)
and, with at, "at": {"points" (n, 3) located points, "bt", "bt_error", "snap"}: the
columns of the program's --csv (bt_error is inf for the discrete method, an upper bound).

>>> import grassfire
>>> b = grassfire.burn3d("tube", method="exact", spacing=0.5)
>>> round(float(b["BT"].max()), 6), b["BT_error"].shape == b["BT"].shape
(4.0, True))doc");
}

}  // namespace grassfire::python
