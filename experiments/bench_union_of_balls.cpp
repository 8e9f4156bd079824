// bench_union_of_balls -- the exact medial axis of a union of balls against CGAL's
// Regular_triangulation_3 construction alone on the same balls.
//
// usage: bench_union_of_balls [N1 N2 ...]   (default 100 1000 10000)
// For each N: random_ball_set(N, seed 2024) (union_alpha_complex.h: dyadic centres in a cube
// of side 2 N^(1/3), radii in [0.8, 1.2)); time CGAL Regular_triangulation_3 alone on the
// weighted points, then the whole axis (triangulation, exact alpha complex, boundary
// vertices, Voronoi cells in the tetrahedra, assembly with rational output). Each N runs
// in its own child process, so peak memory (VmHWM) is that configuration's. Times are
// process CPU seconds. CSV on stdout:
//   balls,regular_triangulation_s,axis_s,ratio,axis_vertices,axis_triangles,peak_mem_mb,load
// (load: the machine's 1-minute load average when the row was measured, machine_load.h)
// and, as comment lines, the structure, the filter/exact counters and the profile (CPU
// seconds per stage of the axis) of each run.
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "medial3/balls/union_of_balls_axis.h"
#include "support/cpu_clock.h"
#include "machine_load.h"
#include "peak_memory.h"
#include "cli.h"

using namespace grassfire;

namespace {

// The stages of UnionOfBallsAxis::stage_seconds, in order.
const std::vector<const char*> kStages = {"regular triangulation", "alpha complex", "betti numbers", "boundary vertices",
                                          "voronoi cells in tetrahedra", "assembly", "output values"};


std::vector<double> measure(std::size_t n) {
  const BallSet balls = random_ball_set(n, 2024);
  // CPU seconds (cpu_clock.h): the machine is shared, and both sides are single-threaded.
  double t = cpu_seconds();
  const std::size_t cells = cgal_regular_triangulation_cells(balls);
  const double rt = cpu_seconds() - t;
  t = cpu_seconds();
  const UnionOfBallsAxis a = union_of_balls_axis(balls);
  const double axis = cpu_seconds() - t;
  const ClipStats& s = a.stats;
  std::vector<double> v = {rt,
          axis,
          double(a.complex.vertices.size()),
          double(a.complex.triangles.size()),
          double(cells),
          double(a.alpha_simplices[3]),
          double(a.boundary.size()),
          double(a.tet_polygons),
          double(a.complex.segments.size()),
          double(s.sign_tests),
          double(s.by_filter),
          double(s.by_structure),
          double(s.by_exact),
          a.coordinate_error,
          a.triangulation_seconds,
          double(a.tetrahedra_candidates),
          double(a.voronoi_cells),
          double(a.clips),
          double(a.beyond_reach)};
  for (const auto& stage : a.stage_seconds) v.push_back(stage.second);  // the profile, CPU seconds
  return v;
}

constexpr const char* kUsage =
    "usage: bench_union_of_balls [N1 N2 ...]   (default 100 1000 10000)\nthe exact medial axis of a union of balls against CGAL's Regular_triangulation_3 construction alone on the same balls.\n(CSV columns and details: the header of experiments/bench_union_of_balls.cpp)\n";

int run(int argc, char** argv) {
  std::vector<std::size_t> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(static_cast<std::size_t>(std::atoll(argv[i])));
  if (sizes.empty()) sizes = {100, 1000, 10000};
  std::printf("balls,regular_triangulation_s,axis_s,ratio,axis_vertices,axis_triangles,peak_mem_mb,load\n");
  for (std::size_t n : sizes) {
    const std::vector<double> v = bench::in_child([&] { return measure(n); });
    std::printf("%zu,%.4f,%.4f,%.1f,%.0f,%.0f,%.1f,%.1f\n", n, v[0], v[1], v[1] / v[0], v[2], v[3], v.back(),
                bench::machine_load());
    std::printf("# n=%zu: rt cells %.0f, alpha tetrahedra %.0f, boundary vertices %.0f, tet polygons %.0f, segments %.0f, "
                "sign tests %.0f (filter %.0f, structural %.0f, exact %.0f), max coordinate error %.3g, "
                "triangulation inside the axis %.3f s, candidates per tetrahedron %.1f, cells clipped per tetrahedron %.1f, "
                "bisectors clipped per cell %.1f, skipped by the reach bound per cell %.1f\n",
                n, v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12], v[13], v[14], v[15] / v[5], v[16] / v[5],
                v[17] / v[16], v[18] / v[16]);
    std::printf("# n=%zu profile (CPU s):", n);
    for (std::size_t k = 0; k < kStages.size(); ++k) std::printf(" %s %.3f;", kStages[k], v[19 + k]);
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_union_of_balls", kUsage, run);
}
