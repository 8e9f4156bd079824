// curves3d.cpp -- `grassfire curves3d`: medial curves of a 3D medial axis (5.1.2).
//
// Builds the complex and its burning field (tools/field_input.h), the medial curve graph
// (burn3/medial_curves.h), validates it (1-dimensional, in the axis, the axis' b0 and b1)
// and only then writes the outputs, each whole or not at all: --json (format
// grassfire-curves3d, io/curves_export.h), --ply and --vtk (polylines with R, BT, ET).
#include <iostream>

#include "burn3/medial_curves.h"
#include "io/atomic_file.h"
#include "io/curves_export.h"
#include "tools/commands.h"
#include "tools/complex_input.h"
#include "tools/field_input.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

int run_curves3d(int argc, char** argv) {
  Options opt("curves3d", "Medial curves of the medial axis of a 3D shape: where burning paths end, made "
                          "connected and homotopy-preserving by the burning collapse (5.1.2).");
  opt.positional("INPUT", complex_input_help());
  declare_field_options(opt);
  opt.option("arrive-cosine", "C", "a side arrives at an edge when its fire runs into it at an angle whose sine "
                                   "is above C (significance of a path end)", "0.5")
      .option("depart-cosine", "C", "a side departs when its fire leaves at an angle whose sine is above C", "0.1")
      .option("time-margin", "T", "a front arrived before the curve burned when earlier by more than T (default: "
                                  "the field's resolution, h for the discrete method)")
      .option("json", "OUT", "write the curve graph as JSON (format grassfire-curves3d)")
      .option("ply", "OUT", "write the curve graph as PLY polylines with R, BT, ET")
      .option("vtk", "OUT", "write the curve graph as legacy VTK polylines with R, BT, ET")
      .epilog("The graph has the b0 and b1 of the axis (checked by simplicial homology before anything is written).\n"
              "Example: grassfire curves3d board-fin --spacing 0.1 --json board_fin_curves.json");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  const std::string input = opt.arg("INPUT");
  const FieldInput in = load_field(opt, input, "curves3d");
  MedialCurveOptions o;
  o.arrive_cosine = opt.get_double("arrive-cosine");
  o.depart_cosine = opt.get_double("depart-cosine");
  if (opt.has("time-margin")) o.time_margin = opt.get_double("time-margin");
  if (!(o.arrive_cosine >= 0 && o.arrive_cosine < 1) || !(o.depart_cosine >= 0 && o.depart_cosine < 1))
    throw std::runtime_error("--arrive-cosine and --depart-cosine must be in [0, 1)");
  if (opt.has("time-margin") && !(o.time_margin >= 0)) throw std::runtime_error("--time-margin must be >= 0");
  const MedialCurves curves = medial_curves(*in.field, o);
  curves.validate(*in.complex);
  if (opt.has("json")) write_file_atomically(opt.get("json"), medial_curves_json(curves, input).dump(1) + "\n");
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
            << s.seconds << " s\n";
  return 0;
}

GF_REGISTER_COMMAND("curves3d", "medial curves of a 3D medial axis from its burning (5.1.2)", run_curves3d);

}  // namespace
}  // namespace grassfire::cli
