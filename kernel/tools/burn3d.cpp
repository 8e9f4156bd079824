// burn3d.cpp -- `grassfire burn3d`: burning time on the medial axis of a 3D shape (ch. 4).
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "burn3/discrete_burning.h"
#include "complex3/medial_complex.h"
#include "io/complex_export.h"
#include "io/complex_text.h"
#include "tools/commands.h"
#include "tools/complex_input.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

nlohmann::json finite_or_null(const std::vector<double>& values) {
  nlohmann::json a = nlohmann::json::array();
  for (double v : values) a.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr));
  return a;
}

nlohmann::json report(const std::string& input, const MedialComplex& mc, const DiscreteBurning& d) {
  nlohmann::json j;
  j["input"] = input;
  j["method"] = "discrete";
  j["spacing"] = d.spacing;
  j["complex"] = {{"vertices", mc.vertex_count()},
                  {"edges", mc.edge_count()},
                  {"triangles", mc.triangle_count()},
                  {"segments", mc.count(EdgeStratum::Dangling)},
                  {"border_edges", mc.count(EdgeStratum::Border)},
                  {"singular_edges", mc.count(EdgeStratum::Singular)},
                  {"singular_points", mc.count(VertexKind::SingularPoint)},
                  {"sheets", mc.sheets().size()}};
  j["stats"] = {{"steiner_points", d.stats.steiner_points},
                {"arrivals_pushed", d.stats.pushes},
                {"arrivals_popped", d.stats.pops},
                {"seconds", d.stats.seconds}};
  std::size_t unburned = 0;
  double max_bt = 0, max_et = 0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    if (!std::isfinite(d.vertex_bt[v])) {
      ++unburned;
      continue;
    }
    max_bt = std::max(max_bt, d.vertex_bt[v]);
    max_et = std::max(max_et, d.vertex_et[v]);
  }
  j["summary"] = {{"burned_vertices", mc.vertex_count() - unburned},
                  {"unburned_vertices", unburned},
                  {"max_bt", max_bt},
                  {"max_et", max_et}};
  std::vector<double> x, y, z, r;
  for (const ComplexVertex& v : mc.vertices()) {
    x.push_back(v.approx[0]), y.push_back(v.approx[1]), z.push_back(v.approx[2]), r.push_back(v.radius);
  }
  j["vertex_values"] = {{"x", x}, {"y", y}, {"z", z}, {"R", r}, {"BT", finite_or_null(d.vertex_bt)},
                        {"ET", finite_or_null(d.vertex_et)}};
  return j;
}

int run_burn3d(int argc, char** argv) {
  Options opt("burn3d", "Burning time BT (Definitions 9-10) and ET = BT - R on the medial axis of a 3D shape.");
  opt.positional("INPUT", complex_input_help())
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
  const MedialComplex mc(load_complex(input, opt.has("mesh-is-complex"), "burn3d"));
  mc.validate();
  DiscreteBurningOptions o;
  if (opt.has("spacing")) {
    o.spacing = opt.get_double("spacing");
  } else {
    Vec3d lo = mc.vertex(0).approx, hi = lo;
    for (const ComplexVertex& v : mc.vertices())
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v.approx[i]), hi[i] = std::max(hi[i], v.approx[i]);
    o.spacing = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 100;
    if (!(o.spacing > 0)) o.spacing = 1;
  }
  if (!(o.spacing > 0) || !std::isfinite(o.spacing)) throw std::runtime_error("--spacing must be a positive number");
  o.max_points = static_cast<std::uint64_t>(opt.get_long("max-points", 1, 2'000'000'000L));
  const DiscreteBurning d = burn_discrete(mc, o);
  const nlohmann::json j = report(input, mc, d);
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
