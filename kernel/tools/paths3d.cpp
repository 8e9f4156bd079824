// paths3d.cpp -- `grassfire paths3d`: burning paths on a 3D medial axis (5.1.2, Fig. 5.2).
//
// Runs pipeline/paths3d.h: the complex and its burning field, then the burning paths
// of the chosen points (curves3/burning_paths.h): every vertex, every node of the medial
// curves (curves3/medial_curves.h; the curves are validated first), the paths that end on
// the curves (one per arriving side at a node on an edge), or the points of a CSV file
// (header x,y,z; io/point_csv.h), each located exactly at its nearest point of the complex
// (complex3/point_location.h). Outputs (each written whole or not at all): --json (format grassfire-paths3d,
// io/curves_export.h), --ply and --vtk (one polyline per path with BT along it).
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "pipeline/paths3d.h"
#include "support/atomic_file.h"
#include "io/complex_text.h"
#include "io/curves_export.h"
#include "io/point_csv.h"
#include "tools/commands.h"
#include "pipeline/complex_input.h"
#include "tools/field_input.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

int run_paths3d(int argc, char** argv) {
  Options opt("paths3d", "Burning paths on the medial axis of a 3D shape: the polylines the fire followed to "
                         "reach chosen points, back to where it started (5.1.2).");
  opt.positional("INPUT", complex_input_help());
  declare_field_options(opt);
  opt.option("from", "WHAT", "vertices (every vertex of the axis), curves (every node of the medial curves), ends "
                             "(the paths that end on the medial curves: at a node on an edge of the axis, one per "
                             "side whose fire runs into it) or points (--points FILE)", "ends")
      .option("points", "FILE", "points for --from points: a CSV file with the header x,y,z (io/point_csv.h); each "
                                "goes to its nearest point of the axis, located exactly")
      .option("json", "OUT", "write the paths as JSON (format grassfire-paths3d)")
      .option("ply", "OUT", "write the paths as PLY polylines with BT along them")
      .option("vtk", "OUT", "write the paths as legacy VTK polylines with BT along them")
      .epilog("Example: grassfire paths3d board-fin --spacing 0.1 --from curves --vtk paths.vtk");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  const std::string input = opt.arg("INPUT"), from = opt.get("from");
  if (from != "vertices" && from != "curves" && from != "ends" && from != "points")
    throw std::runtime_error("--from must be vertices, curves, ends or points");
  if ((from == "points") != opt.has("points")) throw std::runtime_error("--points FILE goes with --from points");
  Paths3dSetup setup;
  setup.from = from;
  if (from == "points") {
    setup.points_name = opt.get("points");
    setup.points = read_point_csv(setup.points_name, false);
    if (setup.points.empty()) throw std::runtime_error(setup.points_name + ": no points");
  }
  setup.field = field_setup(opt, input, "paths3d");
  const Paths3dRun run = paths3d(setup);
  const std::vector<BurningPath>& paths = run.paths;
  const double farthest = run.farthest;
  if (opt.has("json")) write_file_atomically(opt.get("json"), run.json.dump(1) + "\n");
  const PolylineSet lines = burning_paths_polylines(paths);
  if (opt.has("ply")) write_polylines_ply(lines, "grassfire burning paths of " + input, opt.get("ply"));
  if (opt.has("vtk")) write_polylines_vtk(lines, "grassfire burning paths of " + input, opt.get("vtk"));
  double total = 0;
  for (const BurningPath& p : paths) total += p.length;
  std::cout << "paths3d " << input << " (" << run.field.field->method() << "): " << paths.size() << " paths from " << from
            << ", total length " << total;
  if (from == "points") std::cout << "; farthest point from the axis " << farthest;
  std::cout << '\n';
  return 0;
}

GF_REGISTER_COMMAND("paths3d", "burning paths on a 3D medial axis (5.1.2)", run_paths3d);

}  // namespace
}  // namespace grassfire::cli
