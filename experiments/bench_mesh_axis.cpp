// bench_mesh_axis -- the medial axis of closed meshes against CGAL's Delaunay triangulation
// alone on the same sample points.
//
// usage: bench_mesh_axis [--repeat K] [--samples S] [--angle DEG] [--min-growth G] [--complex] MESH...
// (--min-growth: MeshAxisOptions::min_thickness_growth, to compare the round-skip rule)
// For each mesh (in its own child process, so that peak memory is that mesh's VmHWM):
// build the axis (mesh_axis.h: solid topology, every sampling round, inner Voronoi
// complex, pruning, Betti check, exact assembly), then time CGAL Delaunay_triangulation_3
// alone on the samples of the last round. Times are process CPU seconds (the machine is
// shared; CPU time is what load does not inflate), the best of K repetitions. With
// --complex, the MedialComplex of the axis (strata, frames: what medial3d and burn3d build
// next, not part of the axis) is timed too, once, in complex_s. CSV on stdout:
//   mesh,vertices,samples,delaunay_s,axis_s,ratio,peak_mem_mb,betti_solid,betti_axis,
//   faces,refinements,axis_vertices,axis_triangles,axis_segments,
//   samples_s,voronoi_delaunay_s,classify_s,extract_s,prune_s,betti_s,assemble_s,complex_s,load
// (load: the 1-minute load average when the row was measured, machine_load.h)
// with Betti numbers written b0:b1:b2; the stage seconds are summed over the rounds (the
// last round's alone are on the comment lines), ratio = axis_s / delaunay_s, complex_s is
// -1 without --complex; comment lines give the mesh checks' seconds and, per round, the
// stages and the next spacing's rule (refine). A mesh whose axis cannot reach the solid's Betti numbers is
// reported on a comment line.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "medial3/mesh/inner_voronoi.h"
#include "medial3/mesh/mesh_axis.h"
#include "complex3/medial_complex.h"
#include "support/cpu_clock.h"
#include "io/mesh_io.h"
#include "peak_memory.h"
#include "cli.h"
#include "machine_load.h"

using namespace grassfire;

namespace {

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return name.substr(0, name.find_last_of('.'));
}

// The values of one mesh, in the order of the CSV after `mesh` (Betti numbers as three
// values each), then the rounds: count, and per round samples and the six stage seconds.
std::vector<double> measure(const std::string& path, const MeshAxisOptions& options, int repeat, bool complex) {
  const TriangleMesh3 mesh = read_triangle_mesh(path);
  double best_axis = 1e300, best_dt = 1e300;
  MeshAxis axis;
  for (int k = 0; k < repeat; ++k) {
    double t = cpu_seconds();
    axis = mesh_medial_axis(mesh, options);
    best_axis = std::min(best_axis, cpu_seconds() - t);
    t = cpu_seconds();
    if (cgal_delaunay_cells(axis.samples) == 0) throw std::runtime_error("empty triangulation");
    best_dt = std::min(best_dt, cpu_seconds() - t);
  }
  const double peak = bench::peak_resident_mib();  // before the MedialComplex
  double complex_s = -1;
  if (complex) {
    const double t = cpu_seconds();
    MedialComplex(axis.complex).validate();
    complex_s = cpu_seconds() - t;
  }
  const BettiNumbers& s = axis.solid.betti;
  const BettiNumbers& a = axis.axis_betti;
  std::vector<double> stage(6, 0.0);
  for (const MeshAxisRound& r : axis.rounds) {
    const double x[6] = {r.sample_seconds, r.delaunay_seconds, r.classify_seconds, r.extract_seconds, r.prune_seconds, r.betti_seconds};
    for (int i = 0; i < 6; ++i) stage[i] += x[i];
  }
  std::vector<double> out{static_cast<double>(mesh.vertices.size()), static_cast<double>(axis.samples.lattice.size()), best_dt,
                          best_axis, best_axis / best_dt, peak,
                          double(s.b0), double(s.b1), double(s.b2), double(a.b0), double(a.b1), double(a.b2),
                          static_cast<double>(mesh.triangles.size()), static_cast<double>(axis.refinements()),
                          static_cast<double>(axis.complex.vertices.size()), static_cast<double>(axis.complex.triangles.size()),
                          static_cast<double>(axis.complex.segments.size())};
  out.insert(out.end(), stage.begin(), stage.end());
  out.push_back(axis.assemble_seconds);
  out.push_back(complex_s);
  out.push_back(axis.check_seconds);
  out.push_back(static_cast<double>(axis.rounds.size()));
  for (const MeshAxisRound& r : axis.rounds)
    for (double x : {static_cast<double>(r.samples), r.sample_seconds, r.delaunay_seconds, r.classify_seconds,
                     r.extract_seconds, r.prune_seconds, r.betti_seconds, r.refine_seconds})
      out.push_back(x);
  return out;
}

constexpr std::size_t kChecks = 25;  // the index of the mesh checks' seconds
constexpr std::size_t kRounds = 26;  // the index of the round count; the rounds follow it
constexpr std::size_t kPerRound = 8;

constexpr const char* kUsage =
    "usage: bench_mesh_axis [--repeat K] [--samples S] [--angle DEG] [--min-growth G] [--complex] MESH...\nthe medial axis of closed meshes against CGAL's Delaunay triangulation alone on the same sample points.\n(CSV columns and details: the header of experiments/bench_mesh_axis.cpp)\n";

int run(int argc, char** argv) {
  int repeat = 1;
  bool complex = false;
  MeshAxisOptions options;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) repeat = std::atoi(argv[++i]);
    else if (a == "--samples" && i + 1 < argc) options.samples_per_edge = std::atof(argv[++i]);
    else if (a == "--angle" && i + 1 < argc) options.angle_degrees = std::atof(argv[++i]);
    else if (a == "--min-growth" && i + 1 < argc) options.min_thickness_growth = std::atof(argv[++i]);
    else if (a == "--complex") complex = true;
    else meshes.push_back(a);
  }
  if (meshes.empty() || repeat < 1 || !(options.samples_per_edge > 0)) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  std::printf("mesh,vertices,samples,delaunay_s,axis_s,ratio,peak_mem_mb,betti_solid,betti_axis,faces,refinements,"
              "axis_vertices,axis_triangles,axis_segments,samples_s,voronoi_delaunay_s,classify_s,extract_s,prune_s,betti_s,"
              "assemble_s,complex_s,load\n");
  for (const std::string& path : meshes) {
    std::vector<double> v;
    try {
      v = bench::in_child([&] { return measure(path, options, repeat, complex); });
    } catch (const std::exception& e) {
      std::printf("# %s: no axis (%s; the child's message is above)\n", path.c_str(), e.what());
      std::fflush(stdout);
      continue;
    }
    const std::string name = base_name(path);
    std::printf("%s,%.0f,%.0f,%.4f,%.4f,%.2f,%.1f,%.0f:%.0f:%.0f,%.0f:%.0f:%.0f,%.0f,%.0f,%.0f,%.0f,%.0f", name.c_str(), v[0], v[1],
                v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12], v[13], v[14], v[15], v[16]);
    for (std::size_t i = 17; i < kChecks; ++i) std::printf(",%.4f", v[i]);
    std::printf(",%.2f\n", bench::machine_load());
    const auto rounds = static_cast<std::size_t>(v[kRounds]);
    std::printf("# %s: mesh checks (manifold, solid topology, locator) %.3f s\n", name.c_str(), v[kChecks]);
    for (std::size_t r = 0; r < rounds; ++r) {
      const double* x = &v[kRounds + 1 + kPerRound * r];
      std::printf("# %s round %zu: %.0f samples; samples %.3f s, delaunay %.3f s, classify %.3f s, extract %.3f s, "
                  "prune %.3f s, betti %.3f s, next spacing %.3f s\n",
                  name.c_str(), r, x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]);
    }
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_mesh_axis", kUsage, run);
}
