// bench_edf2d -- the 2D pipeline against CGAL's Delaunay triangulation alone.
//
// usage: bench_edf2d [--shape SHAPE] [--repeat K] N1 N2 ...
// For each sample count N: resample SHAPE (default: data/shapes2d/elephant-1.json, a real
// silhouette) uniformly to N boundary samples; time CGAL Delaunay_triangulation_2 alone
// on those samples; then time the whole pipeline on the same samples (Delaunay, Voronoi
// medial axis with exact inside tests, exact extended grassfire, EDF, EMA, ET, ST). Each
// configuration runs in its own child process (peak memory = that child's VmHWM); the
// best of K repetitions is kept. Prints CSV:
//   samples,delaunay_s,pipeline_s,ratio,peak_mib,nodes,edges,filter,multiprecision,exact_ties
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "burn2/extended_grassfire.h"
#include "burn2/measures.h"
#include "medial2/sampled_axis.h"
#include "peak_memory.h"
#include "shapes/load_shape.h"
#include "shapes/resample.h"

using namespace grassfire;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::vector<double> measure(const Shape2& shape, std::size_t n, int repeat) {
  const BoundarySamples samples = resample_by_count(shape, n);
  std::vector<Point2> flat;
  for (const auto& ring : samples) flat.insert(flat.end(), ring.begin(), ring.end());
  double best_dt = 1e300, best_pipeline = 1e300;
  std::vector<double> counts;
  for (int k = 0; k < repeat; ++k) {
    double t = now();
    const std::uint64_t faces = plain_delaunay_triangle_count(flat);
    best_dt = std::min(best_dt, now() - t);
    if (faces == 0) throw std::runtime_error("empty triangulation");
    t = now();
    const MedialGraph g = sampled_medial_axis(shape, samples);
    const GrassfireResult r = extended_grassfire(g);
    const NodeMeasures m = node_measures(g, r);
    best_pipeline = std::min(best_pipeline, now() - t);
    const NumberStats& st = r.stats();
    counts = {static_cast<double>(g.node_count()), static_cast<double>(g.edge_count()),
              static_cast<double>(st.filter_decided), static_cast<double>(st.mpfr_decided),
              static_cast<double>(st.exact_zero), static_cast<double>(m.tubularity.size())};
  }
  std::vector<double> out{best_dt, best_pipeline};
  out.insert(out.end(), counts.begin(), counts.end());
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string shape_arg = std::string(GF_PROJECT_DATA) + "/shapes2d/elephant-1.json";
  int repeat = 1;
  std::vector<std::size_t> sizes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--shape" && i + 1 < argc)
      shape_arg = argv[++i];
    else if (a == "--repeat" && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (a == "--help" || a == "-h") {
      std::printf("usage: bench_edf2d [--shape SHAPE] [--repeat K] N1 N2 ...\n");
      return 0;
    } else
      sizes.push_back(static_cast<std::size_t>(std::atoll(a.c_str())));
  }
  if (sizes.empty()) sizes = {10000, 100000, 1000000};
  const Shape2 shape = load_shape(shape_arg);
  std::printf("# shape %s\nsamples,delaunay_s,pipeline_s,ratio,peak_mib,nodes,edges,filter,multiprecision,exact_ties\n",
              shape.name.c_str());
  for (std::size_t n : sizes) {
    const std::vector<double> v = bench::in_child([&] { return measure(shape, n, repeat); });
    std::printf("%zu,%.4f,%.4f,%.3f,%.1f,%.0f,%.0f,%.0f,%.0f,%.0f\n", n, v[0], v[1], v[1] / v[0], v.back(), v[2], v[3],
                v[4], v[5], v[6]);
    std::fflush(stdout);
  }
  return 0;
}
