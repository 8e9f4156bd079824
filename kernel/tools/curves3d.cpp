// curves3d.cpp -- `grassfire curves3d`: medial curves of a 3D medial axis (5.1.2).
//
// Runs pipeline/curves3d.h (the complex, its burning field, the medial curve graph validated
// with the axis' b0 and b1, the planar / tubular split of 5.3) and only then writes the outputs, each whole or not at all: --json (format grassfire-curves3d with the
// analysis, io/curves_export.h), --ply and --vtk (polylines with R, BT, ET), and for a mesh
// input --surface-ply / --surface-vtk: the mesh with BT, ET, R of the medial ball touching
// each vertex (Fig. 5.5).
#include <iostream>

#include "complex3/medial_complex.h"
#include "io/complex_export.h"
#include "io/complex_text.h"
#include "io/mesh_io.h"
#include "support/atomic_file.h"
#include "io/curves_export.h"
#include "pipeline/complex_input.h"
#include "pipeline/curves3d.h"
#include "tools/commands.h"
#include "tools/field_input.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

void write_surface(const TriangleMesh3& mesh, const AxisRefinement& k, const Options& opt) {
  const MedialComplex surface(mesh_as_complex(mesh));
  std::vector<Vec3d> points;
  for (const ComplexVertex& v : surface.vertices()) points.push_back(v.approx);
  const SurfaceValues values = map_to_surface(k, points);
  const std::vector<VertexField> fields = {{"BT", values.bt}, {"ET", values.et}, {"R", values.radius}};
  if (opt.has("surface-ply")) write_complex_ply(surface, fields, opt.get("surface-ply"));
  if (opt.has("surface-vtk")) write_complex_vtk(surface, fields, opt.get("surface-vtk"));
}

int run_curves3d(int argc, char** argv) {
  Options opt("curves3d", "Medial curves of the medial axis of a 3D shape: where burning paths end, made "
                          "connected and homotopy-preserving by the burning collapse (5.1.2).");
  opt.positional("INPUT", complex_input_help());
  declare_field_options(opt);
  opt.option("arrive-cosine", "C", "a side arrives at an edge when its fire runs into it at an angle whose sine "
                                   "is above C (significance of a path end)", "0.5")
      .option("depart-cosine", "C", "a side departs when its fire leaves at an angle whose sine is above C", "0.1")
      .option("min-et", "F", "drop pieces of path ends whose largest ET is below F times the axis' largest ET "
                             "(significance by erosion thickness)", "0")
      .option("time-margin", "T", "a front arrived before the curve burned when earlier by more than T (default: "
                                  "the field's resolution, h for the discrete method)")
      .option("json", "OUT", "write the curve graph as JSON (format grassfire-curves3d)")
      .option("ply", "OUT", "write the curve graph as PLY polylines with R, BT, ET")
      .option("vtk", "OUT", "write the curve graph as legacy VTK polylines with R, BT, ET")
      .option("planar-tubularity", "S", "a part of the axis is planar where 1 - R / BT >= S, else tubular (5.3)", "0.5")
      .option("surface-ply", "OUT", "mesh input: write the mesh with BT, ET, R of the medial ball touching each vertex")
      .option("surface-vtk", "OUT", "mesh input: the same as legacy VTK")
      .epilog("The graph has the b0 and b1 of the axis (checked by simplicial homology before anything is written).\n"
              "Example: grassfire curves3d board-fin --spacing 0.1 --json board_fin_curves.json");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  const std::string input = opt.arg("INPUT");
  Curves3dSetup setup;
  MedialCurveOptions& o = setup.curves;
  o.arrive_cosine = opt.get_double("arrive-cosine");
  o.depart_cosine = opt.get_double("depart-cosine");
  if (opt.has("time-margin")) {
    o.time_margin = opt.get_double("time-margin");
    if (!(o.time_margin >= 0)) throw std::runtime_error("--time-margin must be >= 0");
  }
  o.min_et_fraction = opt.get_double("min-et");
  setup.planar_tubularity = opt.get_double("planar-tubularity");
  const bool surface = opt.has("surface-ply") || opt.has("surface-vtk");
  const std::string ext = file_extension(input);
  if (surface && ext != "off" && ext != "ply" && ext != "obj")
    throw std::runtime_error("--surface-ply / --surface-vtk need a mesh input (.off, .ply, .obj)");
  setup.field = field_setup(opt, input, "curves3d");
  const Curves3dRun run = curves3d(setup);
  const MedialCurves& curves = run.curves;
  const ShapeAnalysis& analysis = run.analysis;
  if (surface) write_surface(read_triangle_mesh(input), *run.refinement, opt);
  if (opt.has("json")) write_file_atomically(opt.get("json"), run.json.dump(1) + "\n");
  const PolylineSet lines = medial_curves_polylines(curves);
  if (opt.has("ply")) write_polylines_ply(lines, "grassfire medial curves of " + input, opt.get("ply"));
  if (opt.has("vtk")) write_polylines_vtk(lines, "grassfire medial curves of " + input, opt.get("vtk"));
  const MedialCurveStats& s = curves.stats;
  std::cout << "curves3d " << input << " (" << curves.method << "): " << curves.nodes.size() << " nodes, "
            << curves.edges.size() << " edges, length " << curves.total_length() << "; betti [" << curves.curve_betti.b0
            << ", " << curves.curve_betti.b1 << "] = axis [" << curves.axis_betti.b0 << ", " << curves.axis_betti.b1
            << "] (axis b2 = " << curves.axis_betti.b2 << ")\n"
            << "refinement " << s.refined_triangles << " triangles; " << s.raw_end_edges << " raw end edges, "
            << s.punctures << " punctures, " << s.walls_opened << " walls opened, " << s.peeled_edges << " edges peeled; "
            << s.seconds << " s\n"
            << "planar area " << analysis.signature.planar_area << ", tubular area " << analysis.signature.tubular_area
            << "; curves in tubular parts " << analysis.signature.tubular_curve_length << " ("
            << analysis.signature.curve_lengths.size() << " branches), in planar parts "
            << analysis.signature.planar_curve_length << "\n";
  return 0;
}

GF_REGISTER_COMMAND("curves3d", "medial curves of a 3D medial axis from its burning (5.1.2)", run_curves3d);

}  // namespace
}  // namespace grassfire::cli
