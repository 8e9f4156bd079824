// check_exact_burning3d.cpp -- chapter 4 on the EXACT burning time (burn3/exact, docs/exact-engine.md), on the complexes the exact engine burns (no singular edge):
//  - random planar sheets (seeded masks of grid cells: holes, reflex corners;
//    tilted; random border rules and radii), burned from the border;
//  - small closed meshes of data/meshes, Loop-refined (geometry3/refined_mesh.h), burned as
//    themselves from seeded point sources with start times t0 (no border).
// Rows per corpus:
//  - Def. 10 against an independent reference: on sheets PlanarSheetReference (the
//    visibility-graph minimum of d_sheet(x, y) + f(y), an Arb enclosure); on meshes CGAL's
//    shortest paths, BT(x) = min_i t0_i + d(s_i, x) (SmspGeodesics). Tolerance: the
//    engine's certified enclosure must meet the reference's (on meshes plus CGAL's double
//    rounding, 1e-9 (1 + T), geodesic_smsp.h); infinite on one side only fails.
//  - Prop. 4 in a sheet, with no allowance: |BT(x) - BT(y)| <= d(x, y) for every pair of
//    sample points, d independent of the engine: on sheets the straight length of xy
//    where the segment lies in the sheet (PlanarSheetReference::visible, exact), on
//    meshes CGAL's geodesic distance (a tree from every third sample point). Judged on
//    the certified enclosures: a pair fails when the lower bound of |BT(x) - BT(y)|
//    exceeds the upper bound of d (rounding of d only: 2^-48 relative on sheets, CGAL's
//    1e-9 (1 + d) on meshes). The note shows the largest |BT(x) - BT(y)| / d, so a
//    reader sees that the bound is approached, not met by a wide margin.
// Mutants: the output mutants of mutants3d.h (bt-bump, bt-dip, bt-infinite), applied to
// the engine's per-point enclosures (shifted by the mutated amount) before any row reads
// them.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "burn3/exact/exact_burning.h"
#include "burn3/geodesic_smsp.h"
#include "burn3/planar_sheet_reference.h"
#include "check_registry.h"
#include "complex3/complex_builder.h"
#include "complex3/point_location.h"
#include "geometry3/refined_mesh.h"
#include "io/mesh_io.h"
#include "mutants3d.h"

namespace grassfire::checks {
namespace {

mpq_class q(long n, long d = 1) {
  mpq_class r(n, d);
  r.canonicalize();
  return r;
}

// Random exact barycentric weights with denominator 8, each > 0.
std::array<mpq_class, 3> interior_weights(std::mt19937& rng) {
  const int a = std::uniform_int_distribution<int>(1, 6)(rng);
  const int b = std::uniform_int_distribution<int>(1, 7 - a)(rng);
  return {q(a, 8), q(b, 8), q(8 - a - b, 8)};
}

// A random mask of 3 x 3 or 4 x 3 unit cells (about one in four missing: holes, reflex
// corners, and pinches, which the engine refuses and the caller replaces), each split into 2 x 2 squares of two triangles, placed in the plane
// y' = (3/5) y, z' = (4/5) y (a rational rotation about the x axis). Border edges get a
// random rule: Linear (half), DistanceToPoint (a random point), Never; radii random per
// vertex, or one common value on every other sheet (flat plane waves).
RawComplex random_planar_sheet(std::uint32_t seed) {
  std::mt19937 rng(seed);
  const int cols = 3 + static_cast<int>(seed % 2), rows = 3, g = 2;
  std::uniform_int_distribution<int> cell(0, 3), coin(0, 9), tick(-30, 30), r2(0, 16);
  ComplexBuilder b("random planar sheet " + std::to_string(seed));
  const bool flat = seed % 2 == 1;
  const mpq_class common = q(r2(rng), 64);
  auto vertex = [&](long i, long j) {
    const mpq_class x = q(i, g), y = q(j, g);
    return b.vertex({x, q(3, 5) * y, q(4, 5) * y}, flat ? common : q(r2(rng), 64));
  };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      if (cell(rng) == 0 && !(r == 1 && c == 1)) continue;
      for (int a = 0; a < g; ++a)
        for (int d = 0; d < g; ++d) {
          const long i = c * g + a, j = r * g + d;
          b.quad(vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1));
        }
    }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : b.raw().triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  for (const auto& [e, n] : uses) {
    const int c = coin(rng);
    if (n != 1 || c < 5) continue;
    const ExactPoint3 p{q(tick(rng), 10), q(tick(rng), 10), q(tick(rng), 10)};
    b.rule(e.first, e.second, c < 8 ? IgnitionRule::DistanceToPoint : IgnitionRule::Never, p);
  }
  return b.take();
}

// The engine's enclosures at the sample points, with the context's output mutant applied
// (mutants3d.h; every sample point lies in a sheet, none in a closed subcomplex that the
// mutants could pick).
void mutate(const CheckContext& ctx, std::vector<Interval>& bt) {
  mutate_enclosures(ctx, bt, [](std::size_t) { return true; }, [](std::size_t) { return false; });
}

struct ExactTallies {
  Tally def10, prop4;
  double width = 0;       // widest engine enclosure
  double steepest = 0;    // largest |BT(x) - BT(y)| / d over the pairs
  std::uint64_t uncertified = 0;
};

// Def. 10: the engine's enclosure e meets the reference's [r.lo - slack, r.hi + slack].
void compare(const Interval& e, const Interval& r, double slack, ExactTallies& t) {
  ++t.def10.points;
  if (e.is_infinite() || r.is_infinite()) {
    if (e.is_infinite() != r.is_infinite()) ++t.def10.violations, t.def10.worst = INFINITY;
    return;
  }
  t.width = std::max(t.width, e.hi - e.lo);
  const double gap = std::max(e.lo - r.hi, r.lo - e.hi) - slack;
  if (gap > 0) ++t.def10.violations, t.def10.worst = std::max(t.def10.worst, gap);
}

// Prop. 4 on one pair: the lower bound of |BT(x) - BT(y)| against d_hi >= d(x, y).
void lipschitz(const Interval& x, const Interval& y, double d, double d_hi, ExactTallies& t) {
  ++t.prop4.points;
  if (x.is_infinite() || y.is_infinite()) {
    if (x.is_infinite() != y.is_infinite()) ++t.prop4.violations, t.prop4.worst = INFINITY;
    return;
  }
  const double lower = std::max({0.0, x.lo - y.hi, y.lo - x.hi});
  if (d > 0) t.steepest = std::max(t.steepest, lower / d);
  if (lower > d_hi) ++t.prop4.violations, t.prop4.worst = std::max(t.prop4.worst, lower - d_hi);
}

// Pairs farther apart than one unit cell are left out of Prop. 4 on sheets: the bound is
// tight only between near points (where BT changes along xy), and far pairs cost walks.
constexpr double kNearPair = 1.0;

// Returns false (nothing checked) where the planar reference does not apply: a pinch
// vertex splits the sheet (the engine burns it by the link rule since the junction rule (docs/exact-engine.md), but the
// reference needs one planar sheet).
bool check_sheet(const CheckContext& ctx, std::uint32_t seed, ExactTallies& t) {
  const MedialComplex mc(random_planar_sheet(seed));
  mc.validate();
  if (mc.sheets().size() != 1 || !mc.sheets()[0].planar) return false;
  std::mt19937 rng(seed);
  std::vector<ComplexPoint> points;
  const ComplexLocator locator(mc);
  const std::uint32_t vertex_stride = ctx.tiny() ? 3 : ctx.quick() ? 2 : 1, triangle_stride = 2 * (vertex_stride + 1);
  for (std::uint32_t v = 0; v < mc.vertex_count(); v += vertex_stride) points.push_back(locator.locate(mc.vertex(v).exact));
  for (std::uint32_t f = 0; f < mc.triangle_count(); f += triangle_stride)
    points.push_back(point_in_triangle(mc, f, interior_weights(rng)));
  ExactBurning eb(mc, engine_options(ctx));
  eb.add_border_ignition();
  eb.run();
  t.uncertified += eb.certification().uncertified;
  std::vector<Interval> bt;
  for (const ComplexPoint& p : points) bt.push_back(eb.burn_time(p));
  mutate(ctx, bt);
  const PlanarSheetReference ref(mc);
  ++t.def10.instances, ++t.prop4.instances;
  for (std::size_t i = 0; i < points.size(); ++i) compare(bt[i], ref.burning_time(points[i]), 0.0, t);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const double d = std::sqrt(squared_distance(points[i].point, points[j].point).get_d());
      if (d > kNearPair || !ref.visible(points[i], points[j])) continue;
      lipschitz(bt[i], bt[j], d, d * (1 + 0x1p-48), t);
    }
  return true;
}

MeshPoint as_mesh_point(std::uint32_t f, const std::array<mpq_class, 3>& w) {
  return {f, {w[0].get_d(), w[1].get_d(), w[2].get_d()}};
}

// CGAL's double rounding of a geodesic value T (geodesic_smsp.h).
double cgal_slack(double value) { return 1e-9 * (1 + value); }

void check_mesh(const CheckContext& ctx, const std::string& name, std::uint32_t seed, ExactTallies& t) {
  const TriangleMesh3 mesh = refined_mesh(read_triangle_mesh(ctx.data_dir + "/meshes/" + name), 300);
  const MedialComplex mc(mesh_as_complex(mesh));
  mc.validate();
  const ComplexLocator locator(mc);
  std::mt19937 rng(seed);
  const auto faces = static_cast<std::uint32_t>(mesh.triangles.size());
  std::uniform_int_distribution<std::uint32_t> face(0, faces - 1);
  ExactBurning eb(mc, engine_options(ctx));
  SmspGeodesics reference(mesh);
  // Sources inside a face, inside an edge and at a vertex, each with its t0 in [0, 3/4].
  const int k = std::uniform_int_distribution<int>(1, 7)(rng);
  const std::array<std::array<mpq_class, 3>, 3> where = {interior_weights(rng), std::array<mpq_class, 3>{q(k, 8), q(8 - k, 8), 0},
                                                         std::array<mpq_class, 3>{0, 0, 1}};
  for (const auto& w : where) {
    const MeshPoint s = as_mesh_point(face(rng), w);
    const mpq_class t0 = q(std::uniform_int_distribution<int>(0, 3)(rng), 4);
    eb.add_point_source(locator.locate(exact_mesh_point(mesh, s)), t0);
    reference.add_source(s, t0.get_d());
  }
  eb.run();
  reference.build();
  t.uncertified += eb.certification().uncertified;
  // Sample points: a vertex of every 8th face, and an interior point of every 8th face
  // and of its neighbour in the index order (close pairs make Prop. 4 tight).
  std::vector<MeshPoint> samples;
  const std::uint32_t stride = ctx.tiny() ? 24 : ctx.quick() ? 12 : 8;
  for (std::uint32_t f = 0; f + 1 < faces; f += stride) {
    samples.push_back(as_mesh_point(f, {1, 0, 0}));
    samples.push_back(as_mesh_point(f, interior_weights(rng)));
    samples.push_back(as_mesh_point(f + 1, interior_weights(rng)));
  }
  std::vector<Interval> bt;
  for (const MeshPoint& p : samples) bt.push_back(eb.burn_time(locator.locate(exact_mesh_point(mesh, p))));
  mutate(ctx, bt);
  ++t.def10.instances, ++t.prop4.instances;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double r = reference.distance(samples[i]);
    compare(bt[i], std::isinf(r) ? Interval::infinity() : Interval(r), cgal_slack(r), t);
  }
  // One tree per group (from its interior point of face f): every sample point has a near
  // partner among the anchors, so Prop. 4 is tested where it is tight.
  for (std::size_t i = 1; i < samples.size(); i += 3) {
    SmspGeodesics from_x(mesh);
    from_x.add_source(samples[i], 0);
    from_x.build();
    for (std::size_t j = 0; j < samples.size(); ++j) {
      if (j == i) continue;
      const double d = from_x.distance(samples[j]);
      lipschitz(bt[i], bt[j], d, d + cgal_slack(d), t);
    }
  }
}

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::vector<CheckRow> corpus_rows(const std::string& corpus, const std::string& reference, const std::string& distance,
                                  const std::string& rounding, const ExactTallies& t) {
  const std::string counts = "; widest engine enclosure " + fixed(t.width) + ", uncertified decisions " +
                             std::to_string(t.uncertified);
  return {tally_row("Def. 10 on the exact BT against an independent reference", corpus, reference,
                    "the engine's certified enclosure meets the reference's" + rounding, t.def10, "length",
                    "exact engine (burn3/exact)" + counts),
          tally_row("Prop 4 in a sheet on the exact BT (|BT(x) - BT(y)| <= d, no allowance)", corpus, distance,
                    "the engine's certified enclosures; rounding of d only" + rounding, t.prop4, "length",
                    "pairs of sample points; largest |BT(x) - BT(y)| / d = " + fixed(t.steepest) + counts)};
}

std::vector<CheckRow> check_exact_burning3d(const CheckContext& ctx) {
  const int sheets = ctx.tiny() ? 2 : ctx.quick() ? 4 : 12;
  ExactTallies s;
  int refused = 0;
  for (std::uint32_t seed = 2026, done = 0; done < static_cast<std::uint32_t>(sheets) && seed < 2026u + 4u * static_cast<std::uint32_t>(sheets); ++seed)
    check_sheet(ctx, seed, s) ? ++done : ++refused;
  std::vector<CheckRow> rows = corpus_rows(
      "random planar sheets (seeded grid masks: holes, reflex corners; tilted; random border rules and radii)",
      "PlanarSheetReference (visibility graph, min over the border of d_sheet + f)",
      "straight length of xy where the segment lies in the sheet (exact visibility walk; pairs at most 1 apart)",
      "", s);
  rows[0].note += "; " + std::to_string(refused) + " sheets refused by the engine (pinches) and replaced";
  std::vector<std::string> meshes = {"octahedron.off", "cube.off", "tripod.off", "cross.off"};
  meshes.resize(ctx.tiny() ? 1 : ctx.quick() ? 2 : 4);
  ExactTallies m;
  for (std::size_t i = 0; i < meshes.size(); ++i) check_mesh(ctx, meshes[i], 8 + static_cast<std::uint32_t>(i), m);
  for (CheckRow& r : corpus_rows("closed meshes of data/meshes, Loop-refined to ~300 faces, seeded point sources",
                                 "CGAL shortest paths: min_i t0_i + d(s_i, x) (SmspGeodesics)",
                                 "CGAL geodesic distance (a shortest-path tree from every third sample point to all others)",
                                 " (+ CGAL's double rounding 1e-9 (1 + value), geodesic_smsp.h)", m))
    rows.push_back(std::move(r));
  return rows;
}

MutantList exact_mutants() {
  MutantList all = burning_mutants(), output;
  for (const MutantInfo& m : all)
    if (m.name == "bt-bump" || m.name == "bt-dip" || m.name == "bt-infinite") output.push_back(m);
  for (const MutantInfo& m : engine_mutants()) output.push_back(m);
  return output;
}

GF_REGISTER_CHECK("exact-burning3d", check_exact_burning3d, exact_mutants());

}  // namespace
}  // namespace grassfire::checks
