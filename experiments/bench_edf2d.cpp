// bench_edf2d -- the 2D pipeline against CGAL's Delaunay triangulation alone.
//
// usage: bench_edf2d [--shape SHAPE] [--repeat K] N1 N2 ...
// For each sample count N: resample SHAPE (default: data/shapes2d/elephant-1.json, a real
// silhouette) uniformly to N boundary samples; time CGAL Delaunay_triangulation_2 alone
// on those samples; then time the whole pipeline on the same samples (Delaunay, Voronoi
// medial axis with exact inside tests, exact extended grassfire, EDF, EMA, ET, ST). Each
// configuration runs in its own child process (peak memory = that child's VmHWM); the
// best of K repetitions is kept, for wall-clock and for thread CPU time separately (CPU
// time does not count the time other processes held the CPU: on a loaded machine its
// ratio is the one to read). Prints CSV:
//   samples,delaunay_s,pipeline_s,ratio,delaunay_cpu_s,pipeline_cpu_s,cpu_ratio,peak_mib,
//   nodes,edges,filter,multiprecision,exact_ties,uncertified,
//   dt_cpu_s,locate_cpu_s,edges_cpu_s,graph_cpu_s,burn_cpu_s,measures_cpu_s,load
// load: the 1-minute load average when the row was measured (machine_load.h).
// The six columns before it are the pipeline's stage profile (thread CPU seconds of the best
// repetition): its own triangulation, circumcircles and inside tests, cocircular merging
// and Voronoi edges, the medial graph, the extended grassfire, ET and ST.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "burn2/extended_grassfire.h"
#include "burn2/measures.h"
#include "support/cpu_clock.h"
#include "medial2/sampled/sampled_axis.h"
#include "peak_memory.h"
#include "io/load_shape.h"
#include "shapes/resample.h"
#include "cli.h"
#include "machine_load.h"

using namespace grassfire;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::vector<double> measure(const Shape2& shape, std::size_t n, int repeat) {
  const BoundarySamples samples = resample_by_count(shape, n);
  std::vector<Point2> flat;
  for (const auto& ring : samples) flat.insert(flat.end(), ring.begin(), ring.end());
  double best_dt = 1e300, best_pipeline = 1e300, best_dt_cpu = 1e300, best_pipeline_cpu = 1e300;
  std::vector<double> counts, stages;
  for (int k = 0; k < repeat; ++k) {
    double t = now(), c = thread_seconds();
    const std::uint64_t faces = plain_delaunay_triangle_count(flat);
    best_dt = std::min(best_dt, now() - t);
    best_dt_cpu = std::min(best_dt_cpu, thread_seconds() - c);
    if (faces == 0) throw std::runtime_error("empty triangulation");
    t = now();
    c = thread_seconds();
    SampledAxisReport report;
    const MedialGraph g = sampled_medial_axis(shape, samples, &report);
    const double c_burn = thread_seconds();
    const GrassfireResult r = extended_grassfire(g);
    const double c_measures = thread_seconds();
    const NodeMeasures m = node_measures(g, r);
    const double c_end = thread_seconds();
    best_pipeline = std::min(best_pipeline, now() - t);
    if (c_end - c < best_pipeline_cpu) {
      best_pipeline_cpu = c_end - c;
      stages = {report.delaunay_seconds, report.locate_seconds, report.edges_seconds, report.graph_seconds,
                c_measures - c_burn, c_end - c_measures};
    }
    const NumberStats& st = r.stats();
    counts = {static_cast<double>(g.node_count()), static_cast<double>(g.edge_count()),
              static_cast<double>(st.filter_decided), static_cast<double>(st.extended_decided + st.mpfr_decided),
              static_cast<double>(st.exact_zero), static_cast<double>(st.uncertified_zero),
              static_cast<double>(m.tubularity.size())};
  }
  std::vector<double> out{best_dt, best_pipeline, best_dt_cpu, best_pipeline_cpu};
  out.insert(out.end(), counts.begin(), counts.end());
  out.insert(out.end(), stages.begin(), stages.end());
  return out;
}

constexpr const char* kUsage =
    "usage: bench_edf2d [--shape SHAPE] [--repeat K] N1 N2 ...\nthe 2D pipeline against CGAL's Delaunay triangulation alone.\n(CSV columns and details: the header of experiments/bench_edf2d.cpp)\n";

int run(int argc, char** argv) {
  std::string shape_arg = std::string(GF_PROJECT_DATA) + "/shapes2d/elephant-1.json";
  int repeat = 1;
  std::vector<std::size_t> sizes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--shape" && i + 1 < argc)
      shape_arg = argv[++i];
    else if (a == "--repeat" && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else
      sizes.push_back(static_cast<std::size_t>(std::atoll(a.c_str())));
  }
  if (sizes.empty()) sizes = {10000, 100000, 1000000};
  const Shape2 shape = load_shape(shape_arg);
  std::printf("# shape %s\nsamples,delaunay_s,pipeline_s,ratio,delaunay_cpu_s,pipeline_cpu_s,cpu_ratio,peak_mib,nodes,"
              "edges,filter,multiprecision,exact_ties,uncertified,dt_cpu_s,locate_cpu_s,edges_cpu_s,graph_cpu_s,"
              "burn_cpu_s,measures_cpu_s,load\n",
              shape.name.c_str());
  for (std::size_t n : sizes) {
    const std::vector<double> v = bench::in_child([&] { return measure(shape, n, repeat); });
    // v: wall dt, wall pipeline, cpu dt, cpu pipeline, 7 counts, 6 stages, peak.
    std::printf("%zu,%.4f,%.4f,%.3f,%.4f,%.4f,%.3f,%.1f,%.0f,%.0f,%.0f,%.0f,%.0f,%.0f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f\n", n,
                v[0], v[1], v[1] / v[0], v[2], v[3], v[3] / v[2], v.back(), v[4], v[5], v[6], v[7], v[8], v[9], v[11],
                v[12], v[13], v[14], v[15], v[16], bench::machine_load());
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_edf2d", kUsage, run);
}
