// medial3d.cpp -- `grassfire medial3d`: the medial axis of a 3D shape (2.1, ch. 4).
#include <fstream>
#include <iostream>

#include "pipeline/medial_axis_input.h"
#include "complex3/medial_complex.h"
#include "io/complex_export.h"
#include "io/complex_json.h"
#include "io/complex_ma.h"
#include "support/progress.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

int run_medial3d(int argc, char** argv) {
  Options opt("medial3d", "The medial axis of a convex polyhedron, a union of balls or a closed mesh, as a 2-complex.");
  opt.positional("INPUT", "a mesh (.off .ply .obj .stl), a half-space list (.hs .halfspaces: one `a b c d` per line, "
                          "a x + b y + c z <= d) or a ball list (.cin .balls: `x y z w`, w = r^2)")
      .option("kind", "K", "convex (exact axis of a convex polyhedron), balls (exact axis of the union), mesh "
                           "(inner Voronoi axis of a closed mesh, refined until it has the solid's Betti numbers), auto (by extension; convex meshes "
                           "go to the convex builder)", "auto")
      .option("samples", "S", "mesh kind: initial sample spacing = mean edge length / S (halved until the axis "
                              "has the solid's Betti numbers)", "1")
      .option("angle", "DEG", "mesh kind: Voronoi faces narrower than DEG degrees seen from the axis are pruned "
                              "while the topology allows (0: no angle test)", "0")
      .option("refinements", "N", "mesh kind: at most N halvings of the spacing", "5")
      .option("max-samples", "N", "mesh kind: at most N surface samples in a round (memory and time grow about linearly "
                                  "with N: ~2 GB per million samples); a round needing more stops the refinement",
              "2000000")
      .option("ma", "OUT", "write the axis as .ma (Q-MAT format: v x y z r, e i j, f i j k)")
      .option("complex", "OUT", "write the axis in the grassfire-complex JSON format (exact; burn3d reads it)")
      .option("ply", "OUT", "write the axis with per-vertex R as PLY")
      .option("json", "OUT", "write a JSON report (counts, exactness, error bounds, Betti numbers, timings;\n"
                             "with --repair: \"repair\", the defects found, the method, alpha, offset, the repaired mesh's size,\n"
                             "the Hausdorff distance)");
  add_repair_options(opt);
  opt.epilog("Nothing is written unless the whole axis was built and its complex validated.\n"
              "Example: grassfire medial3d data/balls/caffeine.cin --ma caffeine.ma --json caffeine.json");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  const std::string input = opt.arg("INPUT");
  const MeshAxisOptions mesh =
      medial3d_mesh_options(opt.get_double("samples"), opt.get_double("angle"), opt.get_long("refinements", 0, 12),
                            opt.get_long("max-samples", 1000, 1000000000L));
  Progress progress("medial3d " + input, 3);
  progress.stage("building the medial axis");
  const MedialAxisBuild axis = build_medial_axis(input, parse_medial_input_kind(opt.get("kind")), mesh, repair_options(opt));
  if (const std::string r = axis.report.value("/mesh_input/repairs"_json_pointer, ""); !r.empty())
    note("medial3d: " + input + ": " + r);
  progress.advance();
  progress.stage("building and validating the complex");
  const MedialComplex mc(axis.complex);
  mc.validate();
  progress.advance();
  progress.stage("writing");
  if (opt.has("complex")) write_complex_json(axis.complex, opt.get("complex"));
  if (opt.has("ma") && !write_ma_file(axis.complex, opt.get("ma")))
    note("medial3d: " + opt.get("ma") + ": some values are irrational and were written as nearest doubles");
  if (opt.has("ply")) {
    std::vector<double> r;
    for (const ComplexVertex& v : mc.vertices()) r.push_back(v.radius);
    write_complex_ply(mc, {{"R", r}}, opt.get("ply"));
  }
  if (opt.has("json")) {
    std::ofstream out(opt.get("json"));
    out << axis.report.dump(1) << '\n';
    if (!out) throw std::runtime_error(opt.get("json") + ": cannot write");
  }
  progress.done();
  if (opt.has("quiet")) return 0;
  const nlohmann::json& a = axis.report["axis"];
  std::cout << "medial3d " << input << " (" << axis.kind << "): " << a["vertices"] << " vertices, " << a["triangles"]
            << " triangles, " << a["segments"] << " segments, " << mc.count(EdgeStratum::Singular)
            << " singular edges, " << mc.sheets().size() << " sheets, Betti " << a["betti"].dump() << ", "
            << axis.report["total_seconds"] << " s\n";
  if (axis.report.contains("repair"))
    std::cout << "medial3d " << input << ": " << axis.report["repair"]["summary"].get<std::string>() << '\n';
  return 0;
}

GF_REGISTER_COMMAND("medial3d", "medial axis of a 3D shape: convex polyhedron, union of balls, closed mesh", run_medial3d);

}  // namespace
}  // namespace grassfire::cli
