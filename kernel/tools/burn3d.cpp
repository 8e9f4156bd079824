// burn3d.cpp -- `grassfire burn3d`: burning time on the medial axis of a 3D shape (ch. 4).
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "complex3/medial_complex.h"
#include "io/complex_export.h"
#include "io/progress.h"
#include "pipeline/burn3d.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

int run_burn3d(int argc, char** argv) {
  Options opt("burn3d", "Burning time BT (Definitions 9-10) and ET = BT - R on the medial axis of a 3D shape.");
  opt.positional("INPUT", "a .ma medial axis; a shape whose medial axis is built as by `grassfire medial3d`: a "
                          "closed mesh (.off/.ply/.obj: exact for convex meshes, else from its inner polar balls), "
                          "a half-space list (.hs) or a ball list (.cin/.balls, exact); or a synthetic "
                          "complex: board-fin, board-cylinder, book:K, y-junction, tetrahedron, octahedron, "
                          "double-cone, tetrahedron-flap")
      .option("method", "NAME", "discrete (Dijkstra over vertices and Steiner points with the link rule)", "discrete")
      .option("spacing", "H", "Steiner point spacing h (default: 1/100 of the bounding box diagonal)")
      .option("max-points", "N", "refuse to place more than N graph points", "50000000")
      .flag("mesh-is-complex", "burn a mesh itself as a 2-complex (R = 0) instead of its medial axis")
      .option("ply", "OUT", "write the complex with per-vertex R, BT, ET as PLY")
      .option("vtk", "OUT", "write the complex with per-vertex R, BT, ET as legacy VTK")
      .option("json", "OUT", "write a JSON report (counts, timings, per-vertex x y z R BT ET; null = never burns)")
      .epilog("The discrete method over-estimates BT by O(h) (see kernel/burn3/discrete_burning.h).\n"
              "Example: grassfire burn3d board-fin --spacing 0.1 --vtk board_fin.vtk");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  if (opt.get("method") != "discrete")
    throw std::runtime_error("method '" + opt.get("method") + "' is not available: only 'discrete' (the exact "
                             "sweep-event engine is not part of this build)");
  const std::string input = opt.arg("INPUT");
  Progress progress("burn3d " + input, 3);
  progress.stage("loading or building the complex");
  const MedialComplex mc(load_burn_complex(input, opt.has("mesh-is-complex")));
  mc.validate();
  progress.advance();
  progress.stage("burning");
  Burn3dOptions o;
  if (opt.has("spacing")) o.spacing = opt.get_double("spacing");
  o.max_points = static_cast<std::uint64_t>(opt.get_long("max-points", 1, 2'000'000'000L));
  const DiscreteBurning d = burn3d_discrete(mc, o);
  progress.advance();
  progress.stage("writing");
  const nlohmann::json j = burn3d_report(input, mc, d);
  const std::vector<VertexField> fields = {{"R", j["vertex_values"]["R"].get<std::vector<double>>()},
                                           {"BT", d.vertex_bt},
                                           {"ET", d.vertex_et}};
  if (opt.has("ply")) write_complex_ply(mc, fields, opt.get("ply"));
  if (opt.has("vtk")) write_complex_vtk(mc, fields, opt.get("vtk"));
  if (opt.has("json")) {
    std::ofstream out(opt.get("json"));
    out << j.dump(1) << '\n';
    if (!out) throw std::runtime_error(opt.get("json") + ": cannot write");
  }
  progress.advance();
  progress.done();
  if (opt.has("quiet")) return 0;
  std::cout << "burn3d " << input << ": " << mc.vertex_count() << " vertices, " << mc.triangle_count() << " triangles, "
            << mc.count(EdgeStratum::Singular) << " singular edges, " << mc.sheets().size() << " sheets\n"
            << "discrete h = " << d.spacing << ": " << d.stats.steiner_points << " Steiner points, "
            << d.stats.seconds << " s; " << j["summary"]["unburned_vertices"] << " vertices never burn; max BT "
            << j["summary"]["max_bt"] << ", max ET " << j["summary"]["max_et"] << '\n';
  return 0;
}

GF_REGISTER_COMMAND("burn3d", "burning time on the medial axis of a 3D shape (discrete baseline)", run_burn3d);

}  // namespace
}  // namespace grassfire::cli
