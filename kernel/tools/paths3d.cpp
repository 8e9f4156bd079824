// paths3d.cpp -- `grassfire paths3d`: burning paths on a 3D medial axis (5.1.2, Fig. 5.2).
//
// Builds the complex and its burning field (tools/field_input.h), then the burning paths
// of the chosen points (burn3/burning_paths.h): every vertex, every node of the medial
// curves (burn3/medial_curves.h; the curves are validated first), the paths that end on
// the curves (one per arriving side at a node on an edge), or the points of a file
// (one `x y z` or `x,y,z` per line, `#` comments), each taken to its nearest point of the
// complex. Outputs (each written whole or not at all): --json (format grassfire-paths3d,
// io/curves_export.h), --ply and --vtk (one polyline per path with BT along it).
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "burn3/burning_paths.h"
#include "io/atomic_file.h"
#include "io/complex_text.h"
#include "io/curves_export.h"
#include "tools/commands.h"
#include "tools/complex_input.h"
#include "tools/field_input.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

std::vector<Vec3d> read_points(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read file");
  std::vector<Vec3d> points;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream is(line);
    Vec3d p;
    std::string extra;
    if (!(is >> p[0])) continue;
    if (!(is >> p[1] >> p[2]) || (is >> extra) || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected three finite numbers x y z");
    points.push_back(p);
  }
  if (points.empty()) throw std::runtime_error(path + ": no points");
  return points;
}

int run_paths3d(int argc, char** argv) {
  Options opt("paths3d", "Burning paths on the medial axis of a 3D shape: the polylines the fire followed to "
                         "reach chosen points, back to where it started (5.1.2).");
  opt.positional("INPUT", complex_input_help());
  declare_field_options(opt);
  opt.option("from", "WHAT", "vertices (every vertex of the axis), curves (every node of the medial curves), ends "
                             "(the paths that end on the medial curves: at a node on an edge of the axis, one per "
                             "side whose fire runs into it) or points (--points FILE)", "ends")
      .option("points", "FILE", "points for --from points: one `x y z` per line; each goes to its nearest point of "
                                "the axis")
      .option("json", "OUT", "write the paths as JSON (format grassfire-paths3d)")
      .option("ply", "OUT", "write the paths as PLY polylines with BT along them")
      .option("vtk", "OUT", "write the paths as legacy VTK polylines with BT along them")
      .epilog("Example: grassfire paths3d board-fin --spacing 0.1 --from curves --vtk paths.vtk");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  const std::string input = opt.arg("INPUT"), from = opt.get("from");
  if (from != "vertices" && from != "curves" && from != "ends" && from != "points")
    throw std::runtime_error("--from must be vertices, curves, ends or points");
  if ((from == "points") != opt.has("points")) throw std::runtime_error("--points FILE goes with --from points");
  const std::vector<Vec3d> queries = from == "points" ? read_points(opt.get("points")) : std::vector<Vec3d>{};
  const FieldInput in = load_field(opt, input, "paths3d");
  std::vector<BurningPath> paths;
  double farthest = 0;
  if (from == "vertices") {
    paths = paths_from_vertices(*in.field);
  } else if (from == "curves" || from == "ends") {
    const MedialCurves curves = medial_curves(*in.field);
    curves.validate(*in.complex);
    paths = from == "curves" ? paths_from_curve_nodes(*in.field, curves) : paths_ending_on_curves(*in.field, curves);
  } else {
    if (in.complex->triangle_count() == 0 && in.complex->count(EdgeStratum::Dangling) == 0)
      throw std::runtime_error(input + ": the complex has no triangle or segment to hold a point");
    std::vector<CellPoint> located;
    for (const Vec3d& q : queries) {
      double d;
      located.push_back(nearest_cell_point(*in.complex, q, &d));
      farthest = std::max(farthest, d);
    }
    paths = paths_from_points(*in.field, located);
  }
  if (opt.has("json"))
    write_file_atomically(opt.get("json"), burning_paths_json(paths, input, in.field->method(), from).dump(1) + "\n");
  const PolylineSet lines = burning_paths_polylines(paths);
  if (opt.has("ply")) write_polylines_ply(lines, "grassfire burning paths of " + input, opt.get("ply"));
  if (opt.has("vtk")) write_polylines_vtk(lines, "grassfire burning paths of " + input, opt.get("vtk"));
  double total = 0;
  for (const BurningPath& p : paths) total += p.length;
  std::cout << "paths3d " << input << " (" << in.field->method() << "): " << paths.size() << " paths from " << from
            << ", total length " << total;
  if (from == "points") std::cout << "; farthest point from the axis " << farthest;
  std::cout << '\n';
  return 0;
}

GF_REGISTER_COMMAND("paths3d", "burning paths on a 3D medial axis (5.1.2)", run_paths3d);

}  // namespace
}  // namespace grassfire::cli
