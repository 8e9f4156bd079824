// bench_burn3d_exact -- the exact burning engine (kernel/burn3/exact/) against CGAL's
// Surface_mesh_shortest_path (Epick, burn3/geodesic_smsp.h) on closed curved meshes with
// three point sources (docs/exact-engine.md).
//
// Meshes: data/meshes cube.off, octahedron.off and tripod.off, smoothed twice and
// Loop-refined by 3 to 7 levels (geometry3/refined_mesh.h: no two neighbouring faces
// coplanar): 512 to 196,608 faces (the octahedron's 131,072 is the one nearest 10^5). Sources at t0 = 0, at the exact barycentric points (1/5, 3/10, 1/2) of
// faces 0, F/3 and 2F/3 (CGAL gets the nearest doubles of these weights). Each method
// runs in a forked child (its own peak memory); times are processor seconds of the child
// (the machine is shared; wall time would count the other users):
//  - smsp_s: CGAL's Surface_mesh from the mesh, add the sources, build_sequence_tree;
//  - exact_s: the engine alone (ExactBurning: its unfolding of the complex, the sources,
//    the propagation), from an already built MedialComplex; complex_s is the
//    MedialComplex construction from the mesh (exact mpq geometry), timed separately
//    because the complex is the kernel's input structure, shared by every method;
//  - peak_mem_mb: the engine child's peak resident set (complex included);
//  - uncertified: decisions of the propagation no certification stage decided;
//  - max_diff: max over vertices of the distance from CGAL's value to the engine's
//    certified enclosure (both exact to double precision: about 1e-12 expected);
//  - ratio = exact_s / smsp_s (target of docs/benchmarks.md: <= 0.5 at 10^5 faces).
// CSV on stdout:
// mesh,faces,smsp_s,exact_s,ratio,peak_mem_mb,uncertified,complex_s,smsp_peak_mb,windows,max_diff,
// unfolding_s,propagation_s,load (load: machine_load.h, when the row was measured; exact_s split: the engine's frames and crossings of the
// complex, then the event loop; the rest is adding the sources)
// Usage: bench_burn3d_exact [--max-faces N] [--mesh NAME]   (meshes above N faces are
// skipped, default 200000; --mesh: only that file of data/meshes)
//
// With --axes (docs/exact-engine.md): medial axes burned from their border by Definition 9 (the
// junction rule on singular curves, the link rule at singular points), the exact engine
// against the discrete baseline (burn3/discrete/discrete_burning.h) at the spacing whose maximum error
// is 1% of the largest BT. Axes: the mesh axes of data/ma/real (made by the project's mesh
// builder from CGAL's meshes; data/ma/real/README.md) and the union-of-balls axis of 24
// random balls (union_alpha_complex.h random_ball_set(24, seed 2024); complex3/builders
// union_of_balls_axis). joint.ma runs with a limit of 300 processor seconds for the exact
// engine (DNF beyond; the baseline is then timed at the default spacing, error unknown).
// The spacing search starts at default_burn_spacing (1/100 of the bounding box diagonal)
// and halves it up to 5 times, stopping early when the error shrinks by less than 10% in a
// halving or the baseline takes over a minute; the error is max over vertices of
// |BT_h - BT_exact| (midpoint of the enclosure).
// Times are processor seconds in forked children, the complex built outside both.
// CSV: axis,triangles,singular_edges,exact_s,uncertified,uncertified_breaks,kinks,merges,
// quenches,unclassified,tangents (junction_points.h),max_bt,h_1pct,discrete_s,discrete_err,ratio (= exact_s /
// discrete_s at h_1pct; at the finest h tried when not reached),load (machine_load.h)
// Usage: bench_burn3d_exact --axes [--quick] [--axis NAME]   (--quick: the two smallest
// axes; --axis: only the axes whose name contains NAME)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/exact_burning.h"
#include "burn3/exact/junction_points.h"
#include "medial3/balls/union_alpha_complex.h"
#include "medial3/balls/union_of_balls_axis.h"
#include "pipeline/medial_axis_input.h"
#include "io/complex_ma.h"
#include "pipeline/burn3d.h"
#include "burn3/geodesic_smsp.h"
#include "complex3/medial_complex.h"
#include "complex3/point_location.h"
#include "geometry3/refined_mesh.h"
#include "io/mesh_io.h"
#include "cli.h"
#include "peak_memory.h"
#include "machine_load.h"

using namespace grassfire;

namespace {

double cpu_seconds_since(std::clock_t start) { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; }

const std::array<mpq_class, 3> kWeights = {mpq_class(1, 5), mpq_class(3, 10), mpq_class(1, 2)};

std::vector<std::uint32_t> source_faces(const TriangleMesh3& m) {
  const auto f = static_cast<std::uint32_t>(m.triangles.size());
  return {0, f / 3, 2 * f / 3};
}

// The first face and corner of every vertex.
std::vector<MeshPoint> vertex_points(const TriangleMesh3& m) {
  std::vector<MeshPoint> at(m.vertices.size());
  for (std::uint32_t f = m.triangles.size(); f-- > 0;)
    for (int i = 0; i < 3; ++i) {
      at[m.triangles[f][i]] = {f, {0, 0, 0}};
      at[m.triangles[f][i]].barycentric[i] = 1;
    }
  return at;
}

// [seconds, T at every vertex]
std::vector<double> run_smsp(const TriangleMesh3& m) {
  const std::clock_t start = std::clock();
  SmspGeodesics g(m);
  for (std::uint32_t f : source_faces(m))
    g.add_source({f, {kWeights[0].get_d(), kWeights[1].get_d(), kWeights[2].get_d()}}, 0);
  g.build();
  std::vector<double> out = {cpu_seconds_since(start)};
  for (const MeshPoint& p : vertex_points(m)) out.push_back(g.distance(p));
  return out;
}

// [complex seconds, engine seconds, uncertified, windows, unfolding seconds, propagation
//  seconds, then lo, hi per vertex]
std::vector<double> run_exact(const TriangleMesh3& m) {
  const std::clock_t start = std::clock();
  const MedialComplex mc(mesh_as_complex(m), false);
  const double complex_s = cpu_seconds_since(start);
  const std::clock_t engine_start = std::clock();
  ExactBurning eb(mc);
  const double unfolding_s = cpu_seconds_since(engine_start);
  for (std::uint32_t f : source_faces(m)) {
    ExactPoint3 p{0, 0, 0};
    for (int i = 0; i < 3; ++i) p = p + kWeights[i] * mc.vertex(m.triangles[f][i]).exact;
    eb.add_point_source(f, p, 0);
  }
  const std::clock_t run_start = std::clock();
  eb.run();
  const double propagation_s = cpu_seconds_since(run_start);
  const double engine_s = cpu_seconds_since(engine_start);
  std::vector<double> out = {complex_s, engine_s, static_cast<double>(eb.certification().uncertified),
                             static_cast<double>(eb.propagation().stats().windows), unfolding_s, propagation_s};
  for (const Interval& bt : eb.vertex_burn_times()) out.push_back(bt.lo), out.push_back(bt.hi);
  return out;
}

// [seconds, uncertified, uncertified breaks, kinks, merges, quenches, unclassified, tangents, mid
//  per vertex]
std::vector<double> run_exact_axis(const MedialComplex& mc) {
  const std::clock_t start = std::clock();
  ExactBurning eb(mc);
  eb.add_border_ignition();
  eb.run();
  const double seconds = cpu_seconds_since(start);
  const JunctionPoints j = junction_points(eb);
  std::vector<double> out = {seconds,
                             static_cast<double>(eb.certification().uncertified),
                             static_cast<double>(eb.propagation().stats().uncertified_breaks),
                             static_cast<double>(j.kinks.size()),
                             static_cast<double>(j.merges.size()),
                             static_cast<double>(j.quenches.size()),
                             static_cast<double>(j.unclassified),
                             static_cast<double>(j.tangents.size())};
  for (const Interval& bt : eb.vertex_burn_times()) out.push_back(bt.is_infinite() ? INFINITY : bt.mid());
  return out;
}
constexpr std::size_t kExactHeader = 8;

// [seconds, BT_h per vertex]
std::vector<double> run_discrete_axis(const MedialComplex& mc, double h) {
  const std::clock_t start = std::clock();
  DiscreteBurningOptions o;
  o.spacing = h;
  const DiscreteBurning d = burn_discrete(mc, o);
  std::vector<double> out = {cpu_seconds_since(start)};
  out.insert(out.end(), d.vertex_bt.begin(), d.vertex_bt.end());
  return out;
}

double max_error(const std::vector<double>& exact, const std::vector<double>& discrete) {
  double err = 0;
  for (std::size_t v = 0; v + kExactHeader + 1 < exact.size(); ++v) {  // the last value is the peak memory
    const double a = exact[kExactHeader + v], b = discrete[1 + v];
    if (std::isinf(a) || std::isinf(b)) {
      if (std::isinf(a) != std::isinf(b)) return INFINITY;
      continue;
    }
    err = std::max(err, std::fabs(a - b));
  }
  return err;
}

int bench_axes(bool quick, const std::string& only) {
  std::printf("axis,triangles,singular_edges,exact_s,uncertified,uncertified_breaks,kinks,merges,quenches,unclassified,"
              "tangents,max_bt,h_1pct,discrete_s,discrete_err,ratio,load\n");
  struct Axis {
    std::string name;
    RawComplex raw;
    long cpu_limit_s;
  };
  const std::string data = GF_PROJECT_DATA;
  std::vector<Axis> axes;
  for (const char* f : {"pipe.ma", "tripod.ma", "tripod-s2.ma"})
    axes.push_back({std::string("ma/real/") + f + " (mesh axis)", read_ma(data + "/ma/real/" + f), 0});
  if (!quick) {
    axes.push_back({"24 random balls (seed 2024; union-of-balls axis)", union_of_balls_axis(random_ball_set(24, 2024)).complex, 0});
    axes.push_back({"ma/real/joint.ma (mesh axis)", read_ma(data + "/ma/real/joint.ma"), 300});
  } else {
    axes.resize(2);
  }
  int failures = 0;
  for (const Axis& a : axes) {
    if (!only.empty() && a.name.find(only) == std::string::npos) continue;
    const MedialComplex mc(a.raw);
    mc.validate();
    std::vector<double> exact;
    try {
      exact = bench::in_child([&] { return run_exact_axis(mc); }, a.cpu_limit_s);
    } catch (const std::runtime_error&) {  // killed at the limit
      const std::vector<double> d = bench::in_child([&] { return run_discrete_axis(mc, default_burn_spacing(mc)); });
      std::printf("%s,%zu,%zu,DNF (>%ld s),,,,,,,,,,%.3f,,,%.2f\n", a.name.c_str(), mc.triangle_count(),
                  mc.count(EdgeStratum::Singular), a.cpu_limit_s, d[0], bench::machine_load());
      std::fflush(stdout);
      continue;
    }
    double max_bt = 0;
    for (std::size_t v = kExactHeader; v + 1 < exact.size(); ++v)
      if (std::isfinite(exact[v])) max_bt = std::max(max_bt, exact[v]);
    double h = default_burn_spacing(mc), err = INFINITY, discrete_s = 0;
    bool reached = false;
    for (int halvings = 0; halvings <= 5; ++halvings, h /= 2) {
      const std::vector<double> d = bench::in_child([&] { return run_discrete_axis(mc, h); });
      const double previous = err;
      discrete_s = d[0];
      err = max_error(exact, d);
      reached = err <= 0.01 * max_bt;
      // Stop when reached, when the error no longer shrinks, or past a minute of baseline time.
      if (reached || !std::isfinite(err) || err > 0.9 * previous || discrete_s > 60) break;
    }
    if (exact[1] != 0) ++failures;
    std::printf("%s,%zu,%zu,%.3f,%.0f,%.0f,%.0f,%.0f,%.0f,%.0f,%.0f,%.4g,%s,%.3f,%.3g,%.3f,%.2f\n", a.name.c_str(), mc.triangle_count(),
                mc.count(EdgeStratum::Singular), exact[0], exact[1], exact[2], exact[3], exact[4], exact[5], exact[6], exact[7],
                max_bt,
                reached ? std::to_string(h).c_str() : ("not reached (" + std::to_string(h) + ")").c_str(), discrete_s, err,
                exact[0] / discrete_s, bench::machine_load());
    std::fflush(stdout);
  }
  return failures == 0 ? 0 : 1;
}

constexpr const char* kUsage =
    "usage: bench_burn3d_exact [--max-faces N] [--mesh NAME] | --axes [--quick] [--axis NAME]\nthe exact burning engine against CGAL's Surface_mesh_shortest_path on Loop-refined closed meshes with three point sources; with --axes, against the discrete baseline at its 1% spacing on medial axes burned by Definition 9 (mesh axes, 24 random balls, joint.ma with a 300 s limit).\n(CSV columns and details: the header of experiments/bench_burn3d_exact.cpp)\n";

int run(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--axes")) {
      bool quick = false;
      std::string only;
      for (int j = 1; j < argc; ++j) {
        quick = quick || !std::strcmp(argv[j], "--quick");
        if (!std::strcmp(argv[j], "--axis") && j + 1 < argc) only = argv[j + 1];
      }
      return bench_axes(quick, only);
    }
  std::size_t max_faces = 200000;  // CGAL needs about 5 GB at 2 10^5 faces
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--max-faces")) max_faces = std::strtoull(argv[i + 1], nullptr, 10);
    if (!std::strcmp(argv[i], "--mesh")) only = argv[i + 1];
  }
  std::printf("mesh,faces,smsp_s,exact_s,ratio,peak_mem_mb,uncertified,complex_s,smsp_peak_mb,windows,max_diff,"
              "unfolding_s,propagation_s,load\n");
  int failures = 0;
  for (const char* name : {"cube.off", "octahedron.off", "tripod.off"}) {
    if (!only.empty() && only != name) continue;
    const TriangleMesh3 coarse = read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name);
    for (int levels = 3; levels <= 7; ++levels) {
      if (coarse.triangles.size() << (2 * levels) > max_faces) break;
      const TriangleMesh3 m = loop_subdivided(coarse, levels, 2);
      const std::vector<double> smsp = bench::in_child([&] { return run_smsp(m); });
      const std::vector<double> exact = bench::in_child([&] { return run_exact(m); });
      double diff = 0;
      for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        const double t = smsp[1 + v], lo = exact[6 + 2 * v], hi = exact[7 + 2 * v];
        diff = std::max(diff, std::max(lo - t, t - hi));
      }
      if (!(diff < 1e-9) || exact[2] != 0) ++failures;
      std::printf("%s,%zu,%.3f,%.3f,%.3f,%.1f,%.0f,%.3f,%.1f,%.0f,%.3g,%.3f,%.3f,%.2f\n", name, m.triangles.size(), smsp[0],
                  exact[1], exact[1] / smsp[0], exact.back(), exact[2], exact[0], smsp.back(), exact[3], diff, exact[4],
                  exact[5], bench::machine_load());
      std::fflush(stdout);
    }
  }
  // A disagreement with CGAL beyond double precision, or an uncertified decision, fails the run.
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_burn3d_exact", kUsage, run);
}
