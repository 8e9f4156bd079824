// bench_complex_build -- building, validating and locating on the exact MedialComplex of
// closed meshes of 10^3 .. 2 10^5 faces.
//
// Meshes: data/meshes cube.off and tripod.off, smoothed and Loop-refined
// (complex3/refined_mesh.h), taken as complexes themselves (mesh_as_complex: exact
// rationals, the doubles read). Each configuration runs in a forked child (its own peak
// memory); times are processor seconds of the child (the machine is shared). Columns:
//  - build_s: MedialComplex(raw) with its embedding check; validate_s: validate();
//  - locate_s_per_1000: ComplexLocator construction is included in the first query batch;
//    the queries are seeded points near the surface (a vertex plus a small offset), so
//    most are off the complex and need the nearest-point search;
//  - old_build_s, old_validate_s, old_locate_s_per_1000 (baseline mode, in the same run):
//    the definition-level references of complex3/medial_complex_reference.h (the previous
//    implementation's exact rational decisions, and the brute-force cell scan for
//    location), skipped beyond --baseline-faces (default 20,000) where they take minutes.
// CSV on stdout: mesh,faces,build_s,validate_s,locate_s_per_1000,peak_mem_mb,old_build_s,
//                old_validate_s,old_locate_s_per_1000
// Usage: bench_complex_build [--quick] [--faces N] [--baseline-faces N] [--queries Q]
//   --quick: 10^3 and 10^4 only; --faces N: only the target N (for profiling).
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
#include "complex3/refined_mesh.h"
#include "io/mesh_io.h"
#include "peak_memory.h"

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

// [build_s, validate_s, locate_s_per_1000]
std::vector<double> run_fast(const RawComplex& raw, const std::vector<ExactPoint3>& queries) {
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
  const double locate = cpu_seconds_since(start) * 1000.0 / static_cast<double>(queries.size());
  if (!(checksum >= 0)) std::fprintf(stderr, "bad checksum\n");
  return {build, validate, locate};
}

// [old_build_s, old_validate_s, old_locate_s_per_1000]
std::vector<double> run_reference(const RawComplex& raw, const std::vector<ExactPoint3>& queries) {
  std::clock_t start = std::clock();
  const ReferenceComplex ref = reference_complex(raw);
  const double build = cpu_seconds_since(start);
  const MedialComplex mc(raw);
  start = std::clock();
  reference_validate(mc);
  const double validate = cpu_seconds_since(start);
  start = std::clock();
  double checksum = 0;
  for (const ExactPoint3& q : queries) checksum += reference_locate(mc, q).snap();
  const double locate = cpu_seconds_since(start) * 1000.0 / static_cast<double>(queries.size());
  if (!(checksum >= 0) || ref.edge_triangles.empty()) std::fprintf(stderr, "bad checksum\n");
  return {build, validate, locate};
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::size_t only = 0, baseline_faces = 20000, query_count = 1000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--faces") && i + 1 < argc) only = std::strtoul(argv[++i], nullptr, 10);
    else if (!std::strcmp(argv[i], "--baseline-faces") && i + 1 < argc) baseline_faces = std::strtoul(argv[++i], nullptr, 10);
    else if (!std::strcmp(argv[i], "--queries") && i + 1 < argc) query_count = std::strtoul(argv[++i], nullptr, 10);
    else {
      std::fprintf(stderr, "usage: bench_complex_build [--quick] [--faces N] [--baseline-faces N] [--queries Q]\n");
      return 2;
    }
  }
  std::printf("mesh,faces,build_s,validate_s,locate_s_per_1000,peak_mem_mb,old_build_s,old_validate_s,old_locate_s_per_1000\n");
  std::vector<std::size_t> targets = {1000, 10000, 100000, 200000};
  if (quick) targets = {1000, 10000};
  if (only) targets = {only};
  for (const char* name : {"cube.off", "tripod.off"})
    for (std::size_t target : targets) {
      const TriangleMesh3 m = refined_mesh(read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name), target);
      const RawComplex raw = mesh_as_complex(m);
      const std::vector<ExactPoint3> queries = queries_near(m, query_count);
      const std::vector<double> fast = bench::in_child([&] { return run_fast(raw, queries); });
      std::vector<double> old = {NAN, NAN, NAN};
      if (m.triangles.size() <= baseline_faces) old = bench::in_child([&] { return run_reference(raw, queries); });
      std::printf("%s,%zu,%.4f,%.4f,%.4f,%.1f,%.4f,%.4f,%.4f\n", name, m.triangles.size(), fast[0], fast[1], fast[2],
                  fast[3], old[0], old[1], old[2]);
      std::fflush(stdout);
    }
  return 0;
}
