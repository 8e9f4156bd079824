// bench_shapes_throughput -- the whole 2D pipeline over every shape of a folder: the exact
// polygon axis with EDF, EMA and the measures, and the sampled pipeline at 2000 samples.
//
// For each *.json / *.wkt file (sorted by name): load and validate (io/load_shape.h);
// (1) exact: pipeline/edf2d.h with AxisMethod::ExactPolygon (axis, burning, ET and ST),
// then every measure of burn2/ on that axis: closest boundary points, potential residue
// with its maximum, separation angle and feature size, E(x), rate pruning, topology-
// preserving ET+ST pruning (T = 0.05 x the bounding box's larger side, S = 1 - 1/sqrt 2,
// 3.5.1), and the LFS signature at 200 boundary samples (apps2d); (2) sampled:
// pipeline/edf2d.h with 2000 samples, then closest points and boundary eccentricity BE
// (defined on a sampled axis). Baselines per shape, in the same run: Boost.Polygon's
// construct_voronoi alone on the exact axis's integer frame (the polygon's segments scaled
// by the frame scale; shapes on the CGAL SDG path get none), and CGAL's
// Delaunay_triangulation_2 alone on the sampled pipeline's 2000 samples; exact_ratio =
// exact_total_s / boost_s, sampled_ratio = sampled_total_s / dt2_s. Each stage is timed
// with steady_clock; a failure in either is recorded with its message and the next shape
// goes on.
// Output: OUT/shapes_throughput.csv (one row per shape, with the 1-minute load average when
// it was measured, machine_load.h), OUT/shapes_throughput_summary.csv
// (shapes, failures per pipeline, total, median and max seconds per pipeline and of the
// two ratios, with the first failure messages), the summary also on stderr.
// --shard I/N runs every N-th shape and writes its rows only (experiments/shard.h).
// Usage: bench_shapes_throughput FOLDER [OUT] [--shard I/N] [--progress|--quiet]
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <boost/polygon/point_data.hpp>
#include <boost/polygon/segment_data.hpp>
#include <boost/polygon/voronoi.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "apps2d/boundary_matching.h"
#include "burn2/axis_pruning.h"
#include "burn2/boundary_eccentricity.h"
#include "burn2/closest_points.h"
#include "burn2/feature_size.h"
#include "burn2/potential_residue.h"
#include "burn2/rate_pruning.h"
#include "support/progress.h"
#include "pipeline/edf2d.h"
#include "io/load_shape.h"
#include "shard.h"
#include "cli.h"
#include "run_options.h"
#include "machine_load.h"

using namespace grassfire;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Row {
  std::string file;
  std::size_t vertices = 0;
  std::size_t exact_nodes = 0, sampled_nodes = 0;
  double exact_axis = 0, exact_burn = 0, exact_measures = 0, burn2_measures = 0, signatures = 0, exact_total = 0;
  double sampled_delaunay = 0, sampled_axis = 0, sampled_burn = 0, sampled_be = 0, sampled_total = 0;
  double boost = 0, dt2 = 0, exact_ratio = 0, sampled_ratio = 0;  // baselines; 0 = none
  std::uint32_t pr_maxima = 0;
  std::size_t pruned_edges = 0;
  std::string exact_error, sampled_error, load_error;
  double machine_load = 0;  // when the row was measured (machine_load.h)
};

// Boost.Polygon alone on the segments of every ring in the exact axis's integer frame.
double bare_boost(const Shape2& s, double frame_scale) {
  namespace bp = boost::polygon;
  std::vector<bp::segment_data<int>> seg;
  for (const Ring& ring : s.rings)
    for (std::size_t i = 0; i < ring.points.size(); ++i) {
      const Point2 a = ring.points[i], b = ring.points[(i + 1) % ring.points.size()];
      auto p = [&](Point2 q) {
        return bp::point_data<int>(int(std::lround(q.x * frame_scale)), int(std::lround(q.y * frame_scale)));
      };
      seg.emplace_back(p(a), p(b));
    }
  const auto t0 = Clock::now();
  bp::voronoi_diagram<double> vd;
  bp::construct_voronoi(seg.begin(), seg.end(), &vd);
  return since(t0);
}

// CGAL's Delaunay_triangulation_2 alone on the samples (bulk insertion, spatially sorted).
double bare_dt2(const BoundarySamples& samples) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_2> pts;
  for (const auto& ring : samples)
    for (const Point2& p : ring) pts.emplace_back(p.x, p.y);
  const auto t0 = Clock::now();
  CGAL::Delaunay_triangulation_2<K> dt(pts.begin(), pts.end());
  return since(t0);
}

void run_exact(const Shape2& s, Row& r) {
  try {
    const auto t0 = Clock::now();
    Edf2dOptions o;
    o.axis = AxisMethod::ExactPolygon;
    const Edf2dResult e = compute_edf2d(s, o);
    const auto t1 = Clock::now();
    const MedialGraph& g = *e.graph;
    const ClosestPoints cp = closest_points(g);
    const PotentialResidue pr = potential_residue(g, cp);
    const LocalFeatureMeasures lf = local_feature_measures(g, cp);
    const AxisEccentricity ecc = distance_to_ema(g, *e.burning);
    const RatePruning rp = rate_pruning(g);
    PruningThresholds t;
    t.erosion = mpq_class(0.05 * shape_dimension(s));
    t.tubularity = 1 - 1 / std::sqrt(2.0);
    t.topology = true;
    const PrunedAxis pruned = prune_axis(g, *e.burning, t);
    r.burn2_measures = since(t1);
    r.pr_maxima = pr.local_maxima;
    r.pruned_edges = pruned.edges.size();
    const auto t2 = Clock::now();
    const BoundarySignature b = boundary_samples(s, 200);
    const std::vector<double> lfs = local_feature_size(b.points, g);
    r.signatures = since(t2);
    r.exact_nodes = e.graph->node_count();
    r.exact_axis = e.timings.axis;
    r.exact_burn = e.timings.burn;
    r.exact_measures = e.timings.measures;
    r.exact_total = since(t0);
    if (e.polygon_report.construction == AxisConstruction::BoostPolygon) {
      r.boost = bare_boost(s, e.polygon_report.frame_scale);
      r.exact_ratio = r.exact_total / r.boost;
    }
  } catch (const std::exception& ex) {
    r.exact_error = ex.what();
  }
}

void run_sampled(const Shape2& s, Row& r) {
  try {
    const auto t0 = Clock::now();
    Edf2dOptions o;
    o.samples = 2000;
    const Edf2dResult e = compute_edf2d(s, o);
    r.sampled_nodes = e.graph->node_count();
    r.sampled_delaunay = e.timings.delaunay;
    r.sampled_axis = e.timings.axis;
    r.sampled_burn = e.timings.burn;
    const auto t1 = Clock::now();
    const ClosestPoints cp = closest_points(*e.graph, &s, &e.samples);
    const BoundaryEccentricity be =
        boundary_eccentricity(*e.graph, *e.burning, distance_to_ema(*e.graph, *e.burning), cp);
    r.sampled_be = since(t1);
    r.sampled_total = since(t0);
    r.dt2 = bare_dt2(e.samples);
    r.sampled_ratio = r.sampled_total / r.dt2;
  } catch (const std::exception& ex) {
    r.sampled_error = ex.what();
  }
}

std::string csv(std::string s) {
  std::replace(s.begin(), s.end(), ',', ';');
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

struct Stats {
  std::size_t ok = 0, failed = 0;
  double total = 0, median = 0, max = 0;
  std::map<std::string, std::size_t> reasons;
};

Stats stats(const std::vector<Row>& rows, double Row::*time, std::string Row::*error) {
  Stats s;
  std::vector<double> t;
  for (const Row& r : rows) {
    const std::string& e = !r.load_error.empty() ? r.load_error : r.*error;
    if (!e.empty()) {
      ++s.failed;
      ++s.reasons[e.substr(0, 160)];
      continue;
    }
    if (r.*time == 0) continue;  // no baseline for this shape
    ++s.ok;
    t.push_back(r.*time);
    s.total += r.*time;
  }
  std::sort(t.begin(), t.end());
  if (!t.empty()) s.median = t[t.size() / 2], s.max = t.back();
  return s;
}

constexpr const char* kUsage =
    "usage: bench_shapes_throughput FOLDER [OUT] [--shard I/N] [--progress|--quiet]\nthe whole 2D pipeline over every shape of a folder: the exact polygon axis with EDF, EMA and the measures, and the sampled pipeline at 2000 samples.\n(CSV columns and details: the header of experiments/bench_shapes_throughput.cpp)\n";

int run(int argc, char** argv) {
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, {{}, {}, 1, 2});
  const experiments::Shard shard = cmd.shard;
  const std::string out = cmd.positional_or(1, ".");
  const std::vector<std::filesystem::path> files =
      experiments::shard_of(experiments::folder_files(cmd.positional[0], {".json", ".wkt"}), shard);
  std::vector<Row> rows;
  Progress progress("bench_shapes_throughput " + shard.label(), files.size());
  for (const auto& f : files) {
    progress.item(f.filename().string());
    progress.advance();
    Row r;
    r.file = f.filename().string();
    try {
      const Shape2 s = load_shape(f.string());
      for (const Ring& ring : s.rings) r.vertices += ring.points.size();
      run_exact(s, r);
      run_sampled(s, r);
    } catch (const std::exception& ex) {
      r.load_error = ex.what();
    }
    r.machine_load = bench::machine_load();
    rows.push_back(r);
  }
  progress.done();
  std::vector<std::string> lines;
  for (const Row& r : rows) {
    char buf[640];
    std::snprintf(buf, sizeof buf,
                  "%s,%zu,%zu,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%u,%zu,%zu,%.5f,%.5f,%.5f,%.5f,%.5f,%.6f,%.6f,%.3f,%.3f,%.2f,",
                  csv(r.file).c_str(), r.vertices, r.exact_nodes, r.exact_axis, r.exact_burn, r.exact_measures,
                  r.burn2_measures, r.signatures, r.exact_total, r.pr_maxima, r.pruned_edges, r.sampled_nodes,
                  r.sampled_delaunay, r.sampled_axis, r.sampled_burn, r.sampled_be, r.sampled_total, r.boost, r.dt2,
                  r.exact_ratio, r.sampled_ratio, r.machine_load);
    std::string err = r.load_error;
    if (!r.exact_error.empty()) err += "exact: " + r.exact_error + " ";
    if (!r.sampled_error.empty()) err += "sampled: " + r.sampled_error;
    lines.push_back(buf + csv(err));
  }
  experiments::write_sorted_csv(out + "/shapes_throughput.csv",
                                "file,vertices,exact_nodes,exact_axis_s,exact_burn_s,exact_measures_s,burn2_measures_s,"
                                "signatures_s,exact_total_s,pr_local_maxima,pruned_edges,sampled_nodes,"
                                "sampled_delaunay_s,sampled_axis_s,sampled_burn_s,sampled_be_s,sampled_total_s,boost_s,dt2_s,"
                                "exact_ratio,sampled_ratio,load,error",
                                lines);
  if (experiments::rows_only(shard, out + "/shapes_throughput.csv")) return 0;
  std::ofstream sum(out + "/shapes_throughput_summary.csv");
  sum << "pipeline,shapes,ok,failed,total_s,median_s,max_s,failure_reasons\n";
  const struct {
    const char* name;
    double Row::*time;
    std::string Row::*error;
  } pipelines[] = {{"exact axis + EDF + all measures + LFS", &Row::exact_total, &Row::exact_error},
                   {"sampled 2000 + EDF + ET/ST + BE", &Row::sampled_total, &Row::sampled_error},
                   {"ratio: exact pipeline / Boost.Polygon alone", &Row::exact_ratio, &Row::exact_error},
                   {"ratio: sampled pipeline / CGAL DT2 alone", &Row::sampled_ratio, &Row::sampled_error}};
  for (const auto& p : pipelines) {
    const Stats s = stats(rows, p.time, p.error);
    std::string reasons;
    for (const auto& [why, n] : s.reasons) reasons += std::to_string(n) + "x " + csv(why) + "; ";
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%zu,%zu,%zu,%.3f,%.5f,%.4f,", p.name, rows.size(), s.ok, s.failed, s.total,
                  s.median, s.max);
    sum << buf << reasons << "\n";
    if (notes_enabled()) std::fprintf(stderr, "%s%s\n", buf, reasons.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_shapes_throughput", kUsage, run);
}
