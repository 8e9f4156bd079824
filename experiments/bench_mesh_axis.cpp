// bench_mesh_axis -- the medial axis of closed meshes against CGAL's Delaunay triangulation
// alone on the same sample points.
//
// usage: bench_mesh_axis [--repeat K] [--samples S] MESH...
// For each mesh (in its own child process, so that peak memory is that mesh's VmHWM):
// build the axis (mesh_axis.h: solid topology, every sampling round, inner Voronoi
// complex, pruning, Betti check, exact assembly), then time CGAL Delaunay_triangulation_3
// alone on the samples of the last round. Times are process CPU seconds (the machine is
// shared; CPU time is what load does not inflate), the best of K repetitions. CSV on stdout:
//   mesh,vertices,samples,delaunay_s,axis_s,ratio,peak_mem_mb,betti_solid,betti_axis
// with Betti numbers written b0:b1:b2, and, as comment lines, each round's stage times.
// A mesh whose axis cannot reach the solid's Betti numbers is reported on a comment line.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "complex3/builders/cpu_clock.h"
#include "complex3/builders/inner_voronoi.h"
#include "complex3/builders/mesh_axis.h"
#include "io/mesh_io.h"
#include "peak_memory.h"

using namespace grassfire;

namespace {

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return name.substr(0, name.find_last_of('.'));
}

std::vector<double> betti_values(const BettiNumbers& b) {
  return {static_cast<double>(b.b0), static_cast<double>(b.b1), static_cast<double>(b.b2)};
}

// axis_s, delaunay_s, vertices, samples, betti solid (3), betti axis (3), rounds, then per
// round: samples, sample, delaunay, classify, extract, prune, betti seconds.
std::vector<double> measure(const std::string& path, const MeshAxisOptions& options, int repeat) {
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
  std::vector<double> out{best_axis, best_dt, static_cast<double>(mesh.vertices.size()),
                          static_cast<double>(axis.samples.lattice.size())};
  for (double b : betti_values(axis.solid.betti)) out.push_back(b);
  for (double b : betti_values(axis.axis_betti)) out.push_back(b);
  out.push_back(static_cast<double>(axis.rounds.size()));
  for (const MeshAxisRound& r : axis.rounds)
    for (double x : {static_cast<double>(r.samples), r.sample_seconds, r.delaunay_seconds, r.classify_seconds,
                     r.extract_seconds, r.prune_seconds, r.betti_seconds})
      out.push_back(x);
  out.push_back(axis.assemble_seconds);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 1;
  MeshAxisOptions options;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) repeat = std::atoi(argv[++i]);
    else if (a == "--samples" && i + 1 < argc) options.samples_per_edge = std::atof(argv[++i]);
    else meshes.push_back(a);
  }
  if (meshes.empty() || repeat < 1) {
    std::fprintf(stderr, "usage: bench_mesh_axis [--repeat K] [--samples S] MESH...\n");
    return 2;
  }
  std::printf("mesh,vertices,samples,delaunay_s,axis_s,ratio,peak_mem_mb,betti_solid,betti_axis\n");
  for (const std::string& path : meshes) {
    std::vector<double> v;
    try {
      v = bench::in_child([&] { return measure(path, options, repeat); });
    } catch (const std::exception& e) {
      std::printf("# %s: no axis (%s; the child's message is above)\n", path.c_str(), e.what());
      std::fflush(stdout);
      continue;
    }
    std::printf("%s,%.0f,%.0f,%.4f,%.4f,%.2f,%.1f,%.0f:%.0f:%.0f,%.0f:%.0f:%.0f\n", base_name(path).c_str(), v[2], v[3], v[1],
                v[0], v[0] / v[1], v.back(), v[4], v[5], v[6], v[7], v[8], v[9]);
    const auto rounds = static_cast<std::size_t>(v[10]);
    for (std::size_t r = 0; r < rounds; ++r) {
      const double* x = &v[11 + 7 * r];
      std::printf("# %s round %zu: %.0f samples; samples %.3f s, delaunay %.3f s, classify %.3f s, extract %.3f s, "
                  "prune %.3f s, betti %.3f s\n",
                  base_name(path).c_str(), r, x[0], x[1], x[2], x[3], x[4], x[5], x[6]);
    }
    std::printf("# %s: assemble (exact vertices) %.3f s\n", base_name(path).c_str(), v[11 + 7 * rounds]);
    std::fflush(stdout);
  }
  return 0;
}
