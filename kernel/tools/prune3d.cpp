// prune3d.cpp -- `grassfire prune3d`: the 3D medial axis pruned by ET and ST thresholds,
// keeping its homotopy type (curves3/axis_pruning3.h, pipeline/prune3d.h). Writes, each whole
// or not at all and only after the pruned complex was validated: --json (grassfire-pruned3d,
// pipeline/prune3d.h), --complex (grassfire-complex JSON, exact), --ma (Q-MAT .ma), --ply
// (with R, BT, ET per vertex).
#include <iostream>

#include "support/atomic_file.h"
#include "io/complex_export.h"
#include "io/complex_json.h"
#include "io/complex_ma.h"
#include "io/complex_text.h"
#include "support/progress.h"
#include "pipeline/complex_input.h"
#include "pipeline/prune3d.h"
#include "tools/commands.h"
#include "tools/field_input.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

mpq_class threshold(const Options& opt, const std::string& name) {
  const std::optional<mpq_class> v = parse_exact_decimal(opt.get(name));
  if (!v || sgn(*v) < 0)
    throw std::invalid_argument("option --" + name + " must be a non-negative decimal number, got '" + opt.get(name) + "'");
  return *v;
}

void write_ply(const Prune3dRun& run, const std::string& path) {
  std::vector<double> r, bt, et;
  for (const PrunedVertex3& v : run.pruned.vertices) r.push_back(v.radius), bt.push_back(v.bt), et.push_back(v.bt - v.radius);
  write_complex_ply(*run.pruned_complex, {{"R", r}, {"BT", bt}, {"ET", et}}, path);
}

int run_prune3d(int argc, char** argv) {
  Options opt("prune3d",
              "Prunes the medial axis of a 3D shape by erosion thickness ET = BT - R and shape tubularity\n"
              "ST = 1 - R/BT (3.4.1, 3.5.1 with the burning time of ch. 4): keeps ET >= T and ST >= S, cut\n"
              "exactly along the threshold lines of the piecewise-linear fields (per triangle its side times,\n"
              "per edge and vertex the point times), and removes failing parts only by collapses from the\n"
              "free border inward, so the pruned axis has the homotopy type of the axis.");
  opt.positional("INPUT", complex_input_help())
      .option("et", "T", "ET threshold in shape units (a fraction of the axis' largest R with --relative)")
      .option("st", "S", "ST threshold, in [0, 1]")
      .flag("relative", "T is a fraction of the largest medial radius R of the axis");
  declare_field_options(opt, "exact");
  opt.option("json", "OUT", "write the report and the pruned axis as JSON (format grassfire-pruned3d)")
      .option("complex", "OUT", "write the pruned axis in the grassfire-complex JSON format (exact)")
      .option("ma", "OUT", "write the pruned axis as .ma (Q-MAT: v x y z r, e i j, f i j k)")
      .option("ply", "OUT", "write the pruned axis with R, BT, ET per vertex as PLY")
      .epilog("Thresholds are read exactly as decimals. The Betti numbers of the axis, of its subdivision\n"
              "and of the pruned axis are checked equal before anything is written.\n"
              "Example: grassfire prune3d data/meshes/tripod.off --et 0.2 --relative --ply tripod_pruned.ply");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  Prune3dSetup setup = default_prune3d_setup();
  const std::string input = opt.arg("INPUT");
  if (opt.has("et")) setup.erosion = threshold(opt, "et");
  if (opt.has("st")) setup.tubularity = threshold(opt, "st");
  setup.relative = opt.has("relative");
  if (setup.relative && !opt.has("et")) throw std::invalid_argument("--relative needs --et");
  setup.field = field_setup(opt, input, "prune3d");
  const Prune3dRun run = prune3d(setup);  // its stages on stderr (pipeline/prune3d.h)
  if (opt.has("json")) write_file_atomically(opt.get("json"), run.report.dump(1) + "\n");
  if (opt.has("complex")) write_complex_json(run.pruned.complex, opt.get("complex"));
  if (opt.has("ma") && !write_ma_file(run.pruned.complex, opt.get("ma")))
    note("prune3d: " + opt.get("ma") + ": some values are not decimals and were written as nearest doubles");
  if (opt.has("ply")) write_ply(run, opt.get("ply"));
  if (opt.has("quiet")) return 0;
  const nlohmann::json& j = run.report;
  std::cout << "prune3d " << input << " (" << setup.field.method << "): ET >= " << j["thresholds"]["et"].dump()
            << ", ST >= " << j["thresholds"]["st"].dump() << "\n"
            << "axis    " << j["axis"]["vertices"] << " vertices, " << j["axis"]["triangles"] << " triangles, "
            << j["axis"]["segments"] << " segments, betti " << j["axis"]["betti"].dump() << "\n"
            << "refined " << j["refined"]["triangles"] << " triangles (" << j["refined"]["cut_points"]
            << " cut points), failing " << j["refined"]["failing_triangles"] << " triangles\n"
            << "pruned  " << j["pruned"]["vertices"] << " vertices, " << j["pruned"]["triangles"] << " triangles, "
            << j["pruned"]["segments"] << " segments, betti " << j["pruned"]["betti"].dump() << "; kept failing "
            << j["pruned"]["kept_failing"]["triangles"] << " triangles, " << j["pruned"]["kept_failing"]["edges"]
            << " edges\n"
            << "uncertified " << j["uncertified"].dump() << "; " << j["seconds"]["burning"] << " s burning, "
            << j["seconds"]["pruning"] << " s pruning\n";
  return 0;
}

GF_REGISTER_COMMAND("prune3d", "3D medial axis pruned by ET and ST thresholds, keeping its topology", run_prune3d);

}  // namespace
}  // namespace grassfire::cli
