// bench_smsp_baseline -- the peers of the exact engine on closed meshes of 10^3 .. 10^5
// faces: CGAL Surface_mesh_shortest_path (Epick, burn3/geodesic_smsp.h) and the discrete
// baseline with point sources (burn3/discrete/discrete_burning.h), on the same meshes.
//
// Meshes: data/meshes cube.off and tripod.off, smoothed and Loop-refined to about 10^3,
// 10^4, 10^5 faces (geometry3/refined_mesh.h). Three point sources, all at t0 = 0, at the
// points (0.2, 0.3, 0.5) of faces 0, F/3 and 2F/3. The discrete spacing h is the mean edge
// length (about one Steiner point per edge). Each method runs in a forked child (its own
// peak memory); its times are processor seconds of the child (the machine is shared, so
// wall time would measure the other users), for the build of its data plus the whole
// propagation (CGAL: the Surface_mesh and build_sequence_tree; discrete: the MedialComplex
// from the mesh, without the embedding check, then burn_discrete, whose own seconds are
// the column burn_s). Then per vertex: gap = BT_discrete - T_cgal (the baseline is
// an upper bound, so gap >= 0 up to CGAL's rounding). CSV on stdout:
// mesh,faces,smsp_s,smsp_peak_mb,spacing,discrete_s,burn_s,discrete_peak_mb,gap_min,gap_mean,gap_max,
// load (the 1-minute load average when the row was measured, machine_load.h)
// Usage: bench_smsp_baseline [--quick]   (--quick: 10^3 and 10^4 only)
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/geodesic_smsp.h"
#include "complex3/medial_complex.h"
#include "complex3/point_location.h"
#include "geometry3/refined_mesh.h"
#include "io/mesh_io.h"
#include "peak_memory.h"
#include "cli.h"
#include "machine_load.h"

using namespace grassfire;

namespace {

double cpu_seconds_since(std::clock_t start) { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; }

std::vector<MeshPoint> source_points(const TriangleMesh3& m) {
  const std::uint32_t f = static_cast<std::uint32_t>(m.triangles.size());
  return {{0, {0.2, 0.3, 0.5}}, {f / 3, {0.2, 0.3, 0.5}}, {2 * f / 3, {0.2, 0.3, 0.5}}};
}

MeshPoint at_vertex(const TriangleMesh3& /*mesh*/, const std::vector<std::pair<std::uint32_t, int>>& corner, std::uint32_t v) {
  MeshPoint p{corner[v].first, {0, 0, 0}};
  p.barycentric[corner[v].second] = 1;
  return p;
}

// [seconds, T at every vertex]
std::vector<double> run_smsp(const TriangleMesh3& m) {
  const std::clock_t start = std::clock();
  SmspGeodesics g(m);
  for (const MeshPoint& s : source_points(m)) g.add_source(s, 0);
  g.build();
  std::vector<double> out = {cpu_seconds_since(start)};
  std::vector<std::pair<std::uint32_t, int>> corner(m.vertices.size());
  for (std::uint32_t f = 0; f < m.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i) corner[m.triangles[f][i]] = {f, i};
  for (std::uint32_t v = 0; v < m.vertices.size(); ++v) out.push_back(g.distance(at_vertex(m, corner, v)));
  return out;
}

// [seconds, burn seconds, BT at every vertex]
std::vector<double> run_discrete(const TriangleMesh3& m, double h) {
  const std::clock_t start = std::clock();
  const MedialComplex mc(mesh_as_complex(m), false);
  const ComplexLocator locator(mc);
  DiscreteBurningOptions o;
  o.spacing = h;
  for (const MeshPoint& s : source_points(m)) {
    ExactPoint3 p{0, 0, 0};
    for (int i = 0; i < 3; ++i) {
      const auto& v = m.vertices[m.triangles[s.face][i]];
      p = p + mpq_class(s.barycentric[i]) * ExactPoint3{mpq_class(v[0]), mpq_class(v[1]), mpq_class(v[2])};
    }
    o.sources.push_back({locator.locate(p), 0});
  }
  const std::clock_t burn_start = std::clock();
  const DiscreteBurning d = burn_discrete(mc, o);
  std::vector<double> out = {cpu_seconds_since(start), cpu_seconds_since(burn_start)};
  out.insert(out.end(), d.vertex_bt.begin(), d.vertex_bt.end());
  return out;
}

double mean_edge_length(const TriangleMesh3& m) {
  double sum = 0;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      const auto& a = m.vertices[t[i]];
      const auto& b = m.vertices[t[(i + 1) % 3]];
      sum += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    }
  return sum / (3.0 * m.triangles.size());
}

constexpr const char* kUsage =
    "usage: bench_smsp_baseline [--quick]\nthe peers of the exact engine on closed meshes of 10^3 .. 10^5 faces: CGAL Surface_mesh_shortest_path (Epick, burn3/geodesic_smsp.h) and the discrete baseline with point sources (burn3/discrete/discrete_burning.h), on the same meshes.\n(CSV columns and details: the header of experiments/bench_smsp_baseline.cpp)\n";

int run(int argc, char** argv) {
  const bool quick = argc > 1 && !std::strcmp(argv[1], "--quick");
  std::printf("mesh,faces,smsp_s,smsp_peak_mb,spacing,discrete_s,burn_s,discrete_peak_mb,gap_min,gap_mean,gap_max,load\n");
  for (const char* name : {"cube.off", "tripod.off"})
    for (std::size_t target : {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}}) {
      if (quick && target > 10000) continue;
      const TriangleMesh3 m = refined_mesh(read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name), target);
      const double h = mean_edge_length(m);
      const std::vector<double> smsp = bench::in_child([&] { return run_smsp(m); });
      const std::vector<double> discrete = bench::in_child([&] { return run_discrete(m, h); });
      double lo = 1e300, hi = -1e300, sum = 0;
      for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const double gap = discrete[2 + v] - smsp[1 + v];
        lo = std::min(lo, gap), hi = std::max(hi, gap), sum += gap;
      }
      std::printf("%s,%zu,%.3f,%.1f,%.5g,%.3f,%.3f,%.1f,%.3g,%.3g,%.3g,%.2f\n", name, m.triangles.size(), smsp[0], smsp.back(),
                  h, discrete[0], discrete[1], discrete.back(), lo, sum / m.vertices.size(), hi, bench::machine_load());
      std::fflush(stdout);
    }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_smsp_baseline", kUsage, run);
}
