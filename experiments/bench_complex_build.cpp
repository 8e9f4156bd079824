// bench_complex_build -- building, validating and locating on the exact MedialComplex of
// closed meshes of 10^3 .. 2 10^5 faces.
//
// Meshes: data/meshes cube.off and tripod.off, smoothed and Loop-refined
// (geometry3/refined_mesh.h), taken as complexes themselves (mesh_as_complex: exact
// rationals, the doubles read). Each configuration runs in a forked child (its own peak
// memory); times are processor seconds of the child (the machine is shared). Columns:
//  - build_s: MedialComplex(raw) with its embedding check; validate_s: validate();
//  - locate_s: ComplexLocator construction plus `queries` seeded queries (a vertex of the
//    mesh moved by up to 1% of the bounding box diagonal: most are off the complex and
//    need the nearest-point search); queries: their number;
//  - peak_mem_mb: the child's peak resident memory;
//  - ref_decisions_s: the all-rational reference of the predicate decisions
//    (complex3/medial_complex_reference.h: every angular order around an edge, every
//    sheet's planarity, as the construction before the filter made them), measured in the
//    same child; mismatches: edges and sheets where the reference and the build differ
//    (must be 0);
//  - fast_ms_per_query, scan_ms_per_query: the indexed locate and the scan of every cell
//    (locate_by_scan, the previous method) on the first `--scan-queries` queries, with a
//    check that both return the same point (scan_mismatches).
// Skipped beyond --baseline-faces (default 50,000): the reference columns (NAN).
// CSV on stdout: mesh,faces,build_s,validate_s,locate_s,queries,peak_mem_mb,ref_decisions_s,
//                mismatches,fast_ms_per_query,scan_ms_per_query,scan_mismatches,load
//                (load: the 1-minute load average when the row was measured, machine_load.h)
// Usage: bench_complex_build [--quick] [--faces N] [--baseline-faces N] [--queries Q]
//                            [--scan-queries S]
//   --quick: about 10^3 faces only (the CTest run); --faces N: only the target N.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "complex3/medial_complex.h"
#include "complex3/medial_complex_reference.h"
#include "complex3/point_location.h"
#include "geometry3/refined_mesh.h"
#include "io/mesh_io.h"
#include "peak_memory.h"
#include "cli.h"
#include "machine_load.h"

using namespace grassfire;

namespace {

double cpu_seconds_since(std::clock_t start) { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; }

// Seeded queries: a vertex of the mesh moved by up to 1% of the bounding box diagonal.
std::vector<ExactPoint3> queries_near(const TriangleMesh3& m, std::size_t count) {
  std::mt19937_64 rng(20240607);
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const auto& p : m.vertices)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  const double scale = 0.01 * std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  std::uniform_int_distribution<std::size_t> pick(0, m.vertices.size() - 1);
  std::uniform_real_distribution<double> offset(-scale, scale);
  std::vector<ExactPoint3> out;
  for (std::size_t i = 0; i < count; ++i) {
    const auto& p = m.vertices[pick(rng)];
    out.push_back({mpq_class(p[0] + offset(rng)), mpq_class(p[1] + offset(rng)), mpq_class(p[2] + offset(rng))});
  }
  return out;
}

// [build_s, validate_s, locate_s, ref_decisions_s, mismatches, fast_ms, scan_ms, scan_mismatches]
std::vector<double> run(const RawComplex& raw, const std::vector<ExactPoint3>& queries, bool reference,
                        std::size_t scan_queries) {
  std::clock_t start = std::clock();
  const MedialComplex mc(raw);
  const double build = cpu_seconds_since(start);
  start = std::clock();
  mc.validate();
  const double validate = cpu_seconds_since(start);
  start = std::clock();
  const ComplexLocator locator(mc);
  double checksum = 0;
  for (const ExactPoint3& q : queries) checksum += locator.locate(q).snap();
  const double locate = cpu_seconds_since(start);
  if (!(checksum >= 0)) std::fprintf(stderr, "bad checksum\n");
  std::vector<double> out = {build, validate, locate, NAN, NAN, NAN, NAN, NAN};
  if (!reference) return out;
  start = std::clock();
  const ReferenceDecisions ref = reference_decisions(mc);
  out[3] = cpu_seconds_since(start);
  out[4] = static_cast<double>(reference_mismatches(mc, ref));
  const std::size_t s = std::min(scan_queries, queries.size());
  std::vector<ComplexPoint> fast(s), scan(s);
  start = std::clock();
  for (std::size_t i = 0; i < s; ++i) fast[i] = locator.locate(queries[i]);
  out[5] = cpu_seconds_since(start) * 1000.0 / static_cast<double>(s);
  start = std::clock();
  for (std::size_t i = 0; i < s; ++i) scan[i] = locator.locate_by_scan(queries[i]);
  out[6] = cpu_seconds_since(start) * 1000.0 / static_cast<double>(s);
  out[7] = 0;
  for (std::size_t i = 0; i < s; ++i)
    out[7] += !(fast[i].kind == scan[i].kind && fast[i].id == scan[i].id && fast[i].snap_squared == scan[i].snap_squared);
  return out;
}

constexpr const char* kUsage =
    "usage: bench_complex_build [--quick] [--faces N] [--baseline-faces N] [--queries Q] [--scan-queries S]\nbuilding, validating and locating on the exact MedialComplex of closed meshes of 10^3 .. 2 10^5 faces.\n(CSV columns and details: the header of experiments/bench_complex_build.cpp)\n";

int run(int argc, char** argv) {
  bool quick = false;
  std::size_t only = 0, baseline_faces = 50000, query_count = 10000, scan_queries = 200;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--faces") && i + 1 < argc) only = std::strtoul(argv[++i], nullptr, 10);
    else if (!std::strcmp(argv[i], "--baseline-faces") && i + 1 < argc) baseline_faces = std::strtoul(argv[++i], nullptr, 10);
    else if (!std::strcmp(argv[i], "--queries") && i + 1 < argc) query_count = std::strtoul(argv[++i], nullptr, 10);
    else if (!std::strcmp(argv[i], "--scan-queries") && i + 1 < argc) scan_queries = std::strtoul(argv[++i], nullptr, 10);
    else {
      std::fputs(kUsage, stderr);
      return 2;
    }
  }
  if (query_count == 0 || scan_queries == 0) {
    std::fprintf(stderr, "bench_complex_build: --queries and --scan-queries must be positive\n");
    return 2;
  }
  std::printf("mesh,faces,build_s,validate_s,locate_s,queries,peak_mem_mb,ref_decisions_s,mismatches,"
              "fast_ms_per_query,scan_ms_per_query,scan_mismatches,load\n");
  std::vector<std::size_t> targets = {1000, 10000, 50000, 100000, 200000};
  if (quick) targets = {1000}, query_count = std::min<std::size_t>(query_count, 1000);
  if (only) targets = {only};
  for (const char* name : {"cube.off", "tripod.off"})
    for (std::size_t target : targets) {
      const TriangleMesh3 m = refined_mesh(read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name), target);
      const RawComplex raw = mesh_as_complex(m);
      const std::vector<ExactPoint3> queries = queries_near(m, query_count);
      const bool reference = m.triangles.size() <= baseline_faces;
      const std::vector<double> r = bench::in_child([&] { return run(raw, queries, reference, scan_queries); });
      std::printf("%s,%zu,%.4f,%.4f,%.4f,%zu,%.1f,%.4f,%.0f,%.4f,%.4f,%.0f,%.2f\n", name, m.triangles.size(), r[0], r[1], r[2],
                  queries.size(), r[8], r[3], r[4], r[5], r[6], r[7], bench::machine_load());
      std::fflush(stdout);
      if (r[4] > 0 || r[7] > 0) {
        std::fprintf(stderr, "bench_complex_build: %s: the build or the locator disagrees with its reference\n", name);
        return 1;
      }
    }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_complex_build", kUsage, run);
}
