// burn3d.cpp -- `grassfire burn3d`: burning time on the medial axis of a 3D shape (ch. 4).
//
// Stages: load and validate the complex (tools/complex_input.h); read the point sources
// (--sources, x,y,z,t0) and the queries (--at, x,y,z), locating each exactly on the
// complex (complex3/point_location.h: a source must lie on it, a query snaps to its
// nearest point); burn by the chosen method (tools/burn3d_methods.h); write every output
// through a temporary file renamed when complete (io/atomic_file.h), so a failure leaves
// no partial file. Long stages report progress on stderr.
//
// --csv OUT: header `x,y,z,bt,bt_error,snap`, one row per query in query order; x,y,z
// are the query's own text; bt is the burning time at the located point (`inf` where it
// never burns); bt_error bounds |bt - BT| (`inf` for the discrete method, whose bt is an
// upper bound only); snap is the distance from the query to the point located (0 when the
// query lies on the complex; nearest double).
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "complex3/medial_complex.h"
#include "complex3/point_location.h"
#include "io/atomic_file.h"
#include "io/complex_export.h"
#include "io/complex_text.h"
#include "io/point_csv.h"
#include "tools/burn3d_methods.h"
#include "tools/commands.h"
#include "tools/complex_input.h"
#include "tools/options.h"

namespace grassfire::cli {
namespace {

struct MethodRow {
  const char* name;
  BurnOutcome (*run)(const BurnRequest&);
};
const MethodRow kMethods[] = {{"discrete", burn_by_discrete}, {"exact", burn_by_exact}};

// Progress lines on stderr for long runs: nothing in the first two seconds, then at most
// one line a second.
class Progress {
 public:
  void operator()(const std::string& stage, double fraction) {
    const double now = seconds();
    if (now < 2.0 || now - last_ < 1.0) return;
    last_ = now;
    std::cerr << "burn3d: " << stage << " " << static_cast<int>(100 * fraction) << "% (" << static_cast<int>(now)
              << " s)\n";
  }
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double last_ = 0.0;
};

std::string number_text(double x) { return std::isinf(x) ? (x > 0 ? "inf" : "-inf") : shortest_double(x); }

std::string point_text(const ExactPoint3& p) {
  return "(" + decimal_or_nearest(p.x) + ", " + decimal_or_nearest(p.y) + ", " + decimal_or_nearest(p.z) + ")";
}

std::vector<PointSource> read_sources(const ComplexLocator& locator, const std::string& path) {
  std::vector<PointSource> sources;
  for (const CsvPoint& row : read_point_csv(path, true)) {
    ComplexPoint x = locator.locate(row.point);
    if (sgn(x.snap_squared) != 0)
      format_error(path, row.line, "source " + point_text(row.point) + " does not lie on the complex (its nearest "
                                   "point is at distance " + shortest_double(x.snap()) + ")");
    sources.push_back({std::move(x), row.t0});
  }
  return sources;
}

double default_spacing(const MedialComplex& mc) {
  Vec3d lo = mc.vertex(0).approx, hi = lo;
  for (const ComplexVertex& v : mc.vertices())
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v.approx[i]), hi[i] = std::max(hi[i], v.approx[i]);
  const double h = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 100;
  return h > 0 ? h : 1.0;
}

nlohmann::json finite_or_null(const std::vector<double>& values) {
  nlohmann::json a = nlohmann::json::array();
  for (double v : values) a.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr));
  return a;
}

nlohmann::json report(const std::string& input, const std::string& method, const BurnRequest& request,
                      const BurnOutcome& out, const std::vector<double>& et) {
  const MedialComplex& mc = request.mc;
  nlohmann::json j;
  j["input"] = input;
  j["method"] = method;
  if (method == "discrete") j["spacing"] = request.spacing;
  j["complex"] = {{"vertices", mc.vertex_count()},
                  {"edges", mc.edge_count()},
                  {"triangles", mc.triangle_count()},
                  {"segments", mc.count(EdgeStratum::Dangling)},
                  {"border_edges", mc.count(EdgeStratum::Border)},
                  {"singular_edges", mc.count(EdgeStratum::Singular)},
                  {"singular_points", mc.count(VertexKind::SingularPoint)},
                  {"sheets", mc.sheets().size()}};
  j["sources"] = request.sources.size();
  j["queries"] = request.queries.size();
  j["stats"] = out.report;
  std::size_t unburned = 0;
  double max_bt = 0, max_et = 0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    if (!std::isfinite(out.vertex_bt[v])) {
      ++unburned;
      continue;
    }
    max_bt = std::max(max_bt, out.vertex_bt[v]);
    max_et = std::max(max_et, et[v]);
  }
  j["summary"] = {{"burned_vertices", mc.vertex_count() - unburned},
                  {"unburned_vertices", unburned},
                  {"max_bt", max_bt},
                  {"max_et", max_et}};
  std::vector<double> x, y, z, r;
  for (const ComplexVertex& v : mc.vertices())
    x.push_back(v.approx[0]), y.push_back(v.approx[1]), z.push_back(v.approx[2]), r.push_back(v.radius);
  j["vertex_values"] = {{"x", x}, {"y", y}, {"z", z}, {"R", r}, {"BT", finite_or_null(out.vertex_bt)},
                        {"ET", finite_or_null(et)}};
  return j;
}

std::string query_csv(const std::vector<CsvPoint>& rows, const BurnRequest& request, const BurnOutcome& out) {
  std::ostringstream os;
  os << "x,y,z,bt,bt_error,snap\n";
  for (std::size_t i = 0; i < rows.size(); ++i)
    os << rows[i].text[0] << ',' << rows[i].text[1] << ',' << rows[i].text[2] << ','
       << number_text(out.query_values[i].bt) << ',' << number_text(out.query_values[i].bt_error) << ','
       << number_text(request.queries[i].snap()) << '\n';
  return os.str();
}

int run_burn3d(int argc, char** argv) {
  Options opt("burn3d", "Burning time BT (Definitions 9-10) and ET = BT - R on the medial axis of a 3D shape.");
  opt.positional("INPUT", complex_input_help())
      .option("method", "NAME", "discrete (Dijkstra over vertices and Steiner points with the link rule) or exact "
                                "(the window-propagation engine, when built)", "discrete")
      .option("spacing", "H", "discrete: Steiner point spacing h (default: 1/100 of the bounding box diagonal)")
      .option("max-points", "N", "discrete: refuse to place more than N graph points", "50000000")
      .flag("mesh-is-complex", "burn a mesh itself as a 2-complex (R = 0) instead of its medial axis")
      .flag("no-border-ignition", "the border never ignites (every border rule set to never): only --sources burn")
      .option("sources", "FILE", "CSV `x,y,z,t0`: points of the complex that ignite at time t0 (exact decimals)")
      .option("at", "FILE", "CSV `x,y,z`: query points, each located exactly on the complex, else at its nearest point")
      .option("csv", "OUT", "with --at: one row per query `x,y,z,bt,bt_error,snap` (inf where it never burns)")
      .option("ply", "OUT", "write the complex with per-vertex R, BT, ET as PLY")
      .option("vtk", "OUT", "write the complex with per-vertex R, BT, ET as legacy VTK")
      .option("json", "OUT", "write a JSON report (counts, timings, per-vertex x y z R BT ET; null = never burns)")
      .epilog("The discrete method over-estimates BT by O(h) (kernel/burn3/discrete_burning.h); at --at points its\n"
              "bt is an upper bound from the graph points of the point's triangles (kernel/burn3/discrete_query.h).\n"
              "Every output is written to a temporary file and renamed when complete.\n"
              "Example: grassfire burn3d board-fin --spacing 0.1 --vtk board_fin.vtk\n"
              "         grassfire burn3d data/meshes/cube.off --mesh-is-complex --sources s.csv --at q.csv --csv bt.csv");
  if (!opt.parse(argc, argv)) return opt.exit_code();
  const std::string method = opt.get("method");
  const MethodRow* row = nullptr;
  for (const MethodRow& m : kMethods)
    if (method == m.name) row = &m;
  if (!row) throw std::runtime_error("unknown method '" + method + "' (discrete or exact)");
  if (opt.has("csv") && !opt.has("at")) throw std::runtime_error("--csv needs --at (the query points)");
  Progress progress;
  const std::string input = opt.arg("INPUT");
  RawComplex raw = load_complex(input, opt.has("mesh-is-complex"), "burn3d");
  if (opt.has("no-border-ignition")) raw = without_border_ignition(std::move(raw));
  const MedialComplex mc(raw);
  mc.validate();
  BurnRequest request{mc, {}, {}, 0.0, 0, [&](const std::string& s, double f) { progress(s, f); }};
  request.spacing = opt.has("spacing") ? opt.get_double("spacing") : default_spacing(mc);
  if (!(request.spacing > 0)) throw std::runtime_error("--spacing must be a positive number");
  request.max_points = static_cast<std::uint64_t>(opt.get_long("max-points", 1, 2'000'000'000L));
  std::vector<CsvPoint> query_rows;
  if (opt.has("sources") || opt.has("at")) {
    const ComplexLocator locator(mc);
    if (opt.has("sources")) request.sources = read_sources(locator, opt.get("sources"));
    if (opt.has("at")) query_rows = read_point_csv(opt.get("at"), false);
    for (std::size_t i = 0; i < query_rows.size(); ++i) {
      request.queries.push_back(locator.locate(query_rows[i].point));
      if ((i & 1023) == 1023) progress("locating queries", static_cast<double>(i + 1) / query_rows.size());
    }
  }
  const BurnOutcome out = row->run(request);
  std::vector<double> r, et;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    r.push_back(mc.vertex(v).radius);
    et.push_back(out.vertex_bt[v] - mc.vertex(v).radius);
  }
  const nlohmann::json j = report(input, method, request, out, et);
  const std::vector<VertexField> fields = {{"R", r}, {"BT", out.vertex_bt}, {"ET", et}};
  if (opt.has("csv")) write_file_atomically(opt.get("csv"), query_csv(query_rows, request, out));
  if (opt.has("ply")) write_complex_ply(mc, fields, opt.get("ply"));
  if (opt.has("vtk")) write_complex_vtk(mc, fields, opt.get("vtk"));
  if (opt.has("json")) write_file_atomically(opt.get("json"), j.dump(1) + "\n");
  std::cout << "burn3d " << input << ": " << mc.vertex_count() << " vertices, " << mc.triangle_count() << " triangles, "
            << mc.count(EdgeStratum::Singular) << " singular edges, " << mc.sheets().size() << " sheets, "
            << request.sources.size() << " point sources, " << request.queries.size() << " queries\n"
            << out.summary << "; " << j["summary"]["unburned_vertices"] << " vertices never burn; max BT "
            << j["summary"]["max_bt"] << ", max ET " << j["summary"]["max_et"] << '\n';
  return 0;
}

GF_REGISTER_COMMAND("burn3d", "burning time on the medial axis of a 3D shape or a given complex", run_burn3d);

}  // namespace
}  // namespace grassfire::cli
