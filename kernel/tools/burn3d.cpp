// burn3d.cpp -- `grassfire burn3d`: burning time on the medial axis of a 3D shape (ch. 4).
//
// The pipeline (pipeline/burn3d.h, shared with the Python module): load and validate the
// complex (pipeline/complex_input.h); read the point sources (--sources, x,y,z,t0) and the
// queries (--at, x,y,z), locating each exactly on the complex (complex3/point_location.h:
// a source must lie on it, a query snaps to its nearest point); burn by the chosen method
// (pipeline/burn3d_methods.h). This file writes every output through a temporary file
// renamed when complete (support/atomic_file.h), so a failure leaves no partial file. Long
// stages report progress on stderr (support/progress.h).
//
// --csv OUT: header `x,y,z,bt,bt_error,snap`, one row per query in query order; x,y,z
// are the query's own text; bt is the burning time at the located point (`inf` where it
// never burns); bt_error bounds |bt - BT| (`inf` for the discrete method, whose bt is an
// upper bound only; the exact method's certified bound); snap is the distance from the query to the point located (0 when the
// query lies on the complex; nearest double).
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/atomic_file.h"
#include "io/burn_field_file.h"
#include "io/complex_export.h"
#include "io/complex_text.h"
#include "io/point_csv.h"
#include "pipeline/burn3d.h"
#include "pipeline/complex_input.h"
#include "tools/commands.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

std::string number_text(double x) { return std::isinf(x) ? (x > 0 ? "inf" : "-inf") : shortest_double(x); }

std::string query_csv(const Burn3dRun& run) {
  std::ostringstream os;
  os << "x,y,z,bt,bt_error,snap\n";
  for (std::size_t i = 0; i < run.query_rows.size(); ++i) {
    const CsvPoint& row = run.query_rows[i];
    const BurnValue& value = run.outcome.query_values[i];
    os << row.text[0] << ',' << row.text[1] << ',' << row.text[2] << ',' << number_text(value.bt) << ','
       << number_text(value.bt_error) << ',' << number_text(run.queries[i].snap()) << '\n';
  }
  return os.str();
}

int run_burn3d(int argc, char** argv) {
  Options opt("burn3d", "Burning time BT (Definitions 9-10) and ET = BT - R on the medial axis of a 3D shape.");
  opt.positional("INPUT", complex_input_help())
      .option("method", "NAME", "discrete (Dijkstra over vertices and Steiner points with the link rule) or exact "
                                "(certified window propagation; complexes without singular edges/points)", "discrete")
      .option("spacing", "H", "discrete: Steiner point spacing h (default: 1/100 of the bounding box diagonal)")
      .option("max-points", "N", "discrete: refuse to place more than N graph points", "50000000")
      .flag("mesh-is-complex", "burn a mesh itself as a 2-complex (R = 0) instead of its medial axis")
      .flag("no-border-ignition", "the border never ignites (every border rule set to never): only --sources burn")
      .flag("singular-walls", "exact: burn complexes with singular edges, each edge a wall where fronts stop\n"
                              "(not Definition 9's junction rule; the report says so)")
      .option("sources", "FILE", "CSV `x,y,z,t0`: points of the complex that ignite at time t0 (exact decimals)")
      .option("at", "FILE", "CSV `x,y,z`: query points, each located exactly on the complex, else at its nearest point")
      .option("csv", "OUT", "with --at: one row per query `x,y,z,bt,bt_error,snap` (inf where it never burns)")
      .option("ply", "OUT", "write the complex with per-vertex R, BT, ET as PLY")
      .option("vtk", "OUT", "write the complex with per-vertex R, BT, ET as legacy VTK")
      .option("json", "OUT", "write a JSON report (counts, timings, per-vertex x y z R BT ET; null = never burns)")
      .option("field", "OUT", "discrete, from the border: write the whole burning (format grassfire-burn3d-field),\n"
                              "which curves3d, paths3d and prune3d --field read instead of burning again");
  add_repair_options(opt);
  opt.epilog("The discrete method over-estimates BT by O(h) (kernel/burn3/discrete/discrete_burning.h); at --at points its\n"
              "bt is an upper bound from the graph points of the point's triangles (kernel/burn3/discrete/discrete_query.h).\n"
              "The exact method returns certified enclosures: |bt - BT| <= bt_error at every query and vertex\n"
              "(--json: vertex_values.BT_error, stats.certification per stage, stats.uncertified; on singular\n"
              "curves stats.kinks, stats.merges, stats.quenches, stats.tangents as {x,y,z,bt,error} and stats.unclassified_switches).\n"
              "Every output is written to a temporary file and renamed when complete.\n"
              "Example: grassfire burn3d board-fin --spacing 0.1 --vtk board_fin.vtk\n"
              "         grassfire burn3d data/meshes/cube.off --mesh-is-complex --sources s.csv --at q.csv --csv bt.csv\n"
              "         grassfire burn3d data/meshes/cube.off --mesh-is-complex --method exact --sources s.csv --json r.json");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  Burn3dSetup setup;
  setup.input = opt.arg("INPUT");
  setup.method = opt.get("method");
  burn_method(setup.method);  // an unknown method is refused before anything is read
  if (opt.has("csv") && !opt.has("at")) throw std::runtime_error("--csv needs --at (the query points)");
  setup.mesh_is_complex = opt.has("mesh-is-complex");
  setup.repair = repair_options(opt);
  setup.no_border_ignition = opt.has("no-border-ignition");
  setup.singular_walls = opt.has("singular-walls");
  if (setup.singular_walls && setup.method != "exact") throw std::runtime_error("--singular-walls needs --method exact");
  if (opt.has("spacing")) setup.spacing = opt.get_double("spacing");
  setup.max_points = static_cast<std::uint64_t>(opt.get_long("max-points", 1, 2'000'000'000L));
  if (opt.has("field") && (setup.method != "discrete" || opt.has("sources") || setup.no_border_ignition))
    throw std::runtime_error("--field writes a discrete burning from the border (--method discrete, no --sources, "
                             "no --no-border-ignition): the burning curves3d, paths3d and prune3d make");
  if (opt.has("sources")) setup.sources.file = opt.get("sources");
  if (opt.has("at")) setup.queries.file = opt.get("at");
  const Burn3dRun run = burn3d(setup);
  const MedialComplex& mc = *run.mc;
  std::vector<double> r;
  for (const ComplexVertex& v : mc.vertices()) r.push_back(v.radius);
  const std::vector<VertexField> fields = {{"R", r}, {"BT", run.outcome.vertex_bt}, {"ET", run.et}};
  if (opt.has("csv")) write_file_atomically(opt.get("csv"), query_csv(run));
  if (opt.has("ply")) write_complex_ply(mc, fields, opt.get("ply"));
  if (opt.has("vtk")) write_complex_vtk(mc, fields, opt.get("vtk"));
  if (opt.has("json")) write_file_atomically(opt.get("json"), run.report.dump(1) + "\n");
  if (opt.has("field")) write_burn_field(mc, *run.outcome.discrete, setup.input, opt.get("field"));
  if (opt.has("quiet")) return 0;
  const nlohmann::json& summary = run.report["summary"];
  std::cout << "burn3d " << setup.input << ": " << mc.vertex_count() << " vertices, " << mc.triangle_count()
            << " triangles, " << mc.count(EdgeStratum::Singular) << " singular edges, " << mc.sheets().size() << " sheets, "
            << run.sources.size() << " point sources, " << run.queries.size() << " queries\n"
            << run.outcome.summary << "; " << summary["unburned_vertices"] << " vertices never burn; max BT "
            << summary["max_bt"] << ", max ET " << summary["max_et"] << '\n';
  return 0;
}

GF_REGISTER_COMMAND("burn3d", "burning time on the medial axis of a 3D shape or a given complex", run_burn3d);

}  // namespace
}  // namespace grassfire::cli
