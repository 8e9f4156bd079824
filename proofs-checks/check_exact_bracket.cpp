// check_exact_bracket.cpp -- Def. 10 on the EXACT burning time from both sides: the exact
// engine's BT must lie inside an independent bracket (burn3/bt_bracket.h) on every corpus of
// corpora3d.h, and the junction books with closed forms (burn3/junction_books.h).
//
// The bracket shares no code with burn3/exact: below, the lower bound of bt_bracket.h (the
// junction rule of Definition 9 over cells of the singular set at spacing h, Euclidean
// distances inside sheets, a Dijkstra to the least fixed point; the derivation is in the
// header); above, the discrete baseline at the same h read at the point (discrete_query.h).
// Probe points: vertices, the midpoint of every singular edge, the centroid of triangles
// (strided on large complexes). A point fails when the engine's certified enclosure misses
// [lower - 1e-9 (1 + |lower|), upper + 1e-9 (1 + |upper|)] (double rounding of the bracket),
// or when exactly one of the engine and the upper bound is infinite.
// The note gives the bracket widths (upper - lower: mean and largest over the probes) at two
// spacings, h and h / 2, so a reader sees the bracket shrink, and the lower bound's time.
// Mutants: the output mutants of mutants3d.h (bt-bump, bt-dip, bt-infinite) on the engine's
// enclosures before the row reads them, and the engine mutants (engine-..., the engine's
// own decisions broken through ExactBurningOptions::mutant).
#include <algorithm>
#include <chrono>
#include <cmath>

#include "burn3/bt_bracket.h"
#include "burn3/exact/exact_burning.h"
#include "burn3/junction_books.h"
#include "check_registry.h"
#include "complex3/point_location.h"
#include "corpora3d.h"
#include "mutants3d.h"

namespace grassfire::checks {
namespace {

constexpr std::size_t kMaxSingularEdges = 450;  // as check_exact_chapter4.cpp (the engine's cost)
constexpr std::uint64_t kMaxCells = 6000;        // the lower bound is quadratic in its cells

struct Widths {
  double sum = 0, largest = 0;
  std::uint64_t n = 0;
  void add(double w) {
    if (!std::isfinite(w)) return;
    sum += w, largest = std::max(largest, w), ++n;
  }
};

struct BracketRun {
  Tally t;
  Widths coarse, fine;
  double seconds_lower = 0, seconds_upper = 0, spacing = 0;
  std::uint64_t uncertified = 0;
  std::size_t refused = 0;
};

std::vector<ComplexPoint> probe_points(const CheckContext& ctx, const MedialComplex& mc, const ComplexLocator& locator) {
  std::vector<ComplexPoint> r;
  const bool small = mc.vertex_count() <= 200;
  const std::uint32_t stride = small ? 1 : ctx.tiny() ? 8 : ctx.quick() ? 4 : 2;
  for (std::uint32_t v = 0; v < mc.vertex_count(); v += stride)
    if (!mc.vertex_triangles(v).empty()) r.push_back(locator.locate(mc.vertex(v).exact));
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    if (mc.edge(e).stratum == EdgeStratum::Singular) {
      const ExactPoint3 &a = mc.vertex(mc.edge(e).v[0]).exact, &b = mc.vertex(mc.edge(e).v[1]).exact;
      r.push_back(locator.locate(mpq_class(1, 2) * (a + b)));
    }
  for (std::uint32_t f = 0; f < mc.triangle_count(); f += 2 * stride) {
    const auto& v = mc.triangle(f).v;
    r.push_back(locator.locate(mpq_class(1, 3) * (mc.vertex(v[0]).exact + mc.vertex(v[1]).exact + mc.vertex(v[2]).exact)));
  }
  return r;
}

double slack(double v) { return 1e-9 * (1 + std::abs(v)); }

// The spacing: the instance's, coarsened until the singular set has at most kMaxCells / 2 cells.
double bracket_spacing(const MedialComplex& mc, double h) {
  double sigma = 0;
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    if (mc.edge(e).stratum == EdgeStratum::Singular || mc.edge(e).stratum == EdgeStratum::Dangling)
      sigma += mc.edge(e).length;
  const double edges = static_cast<double>(mc.count(EdgeStratum::Singular) + mc.count(EdgeStratum::Dangling));
  while (sigma / h + edges + mc.vertex_count() > kMaxCells / 2.0) h *= 2;
  return h;
}

void judge(const std::vector<Interval>& engine, const std::vector<Interval>& bracket, Tally& t, Widths& w) {
  for (std::size_t i = 0; i < engine.size(); ++i) {
    const Interval &e = engine[i], &b = bracket[i];
    ++t.points;
    w.add(b.hi - b.lo);
    if (e.is_infinite() || std::isinf(b.hi)) {
      if (e.is_infinite() != std::isinf(b.hi)) ++t.violations, t.worst = INFINITY;
      continue;
    }
    const double gap = std::max(b.lo - slack(b.lo) - e.hi, e.lo - b.hi - slack(b.hi));
    if (gap > 0) ++t.violations, t.worst = std::max(t.worst, gap);
  }
}

// One complex: the engine (border ignition and `sources`) against the bracket at h and h / 2.
void run(const CheckContext& ctx, const MedialComplex& mc, double h, const std::vector<PointSource>& sources,
         const std::vector<ComplexPoint>& points, BracketRun& r) {
  ExactBurning eb(mc, engine_options(ctx));
  for (const PointSource& s : sources) eb.add_point_source(s.location, s.t0);
  eb.add_border_ignition();
  eb.run();
  r.uncertified += eb.certification().uncertified;
  std::vector<Interval> engine;
  for (const ComplexPoint& x : points) engine.push_back(eb.burn_time(x));
  mutate_enclosures(ctx, engine, [](std::size_t) { return true; }, [](std::size_t) { return false; });
  ++r.t.instances;
  r.spacing = std::max(r.spacing, h);
  for (int k = 0; k < 2; ++k) {
    const BtBracket bracket(mc, k == 0 ? h : h / 2, sources);
    r.seconds_lower += bracket.lower().seconds();
    r.seconds_upper += bracket.seconds_upper();
    std::vector<Interval> b;
    for (const ComplexPoint& x : points) b.push_back(bracket.at(x));
    Tally t;
    judge(engine, b, t, k == 0 ? r.coarse : r.fine);
    r.t.points += t.points, r.t.violations += t.violations, r.t.worst = std::max(r.t.worst, t.worst);
  }
}

std::string g3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

CheckRow row(const std::string& corpus, const BracketRun& r) {
  auto widths = [](const Widths& w) { return "mean " + g3(w.n ? w.sum / w.n : 0) + ", largest " + g3(w.largest); };
  return tally_row("Def. 10 on the exact BT from both sides (inside an independent bracket)", corpus,
                   "bt_bracket.h: lower = junction rule over singular-set cells (Euclidean sheet distances, Dijkstra "
                   "to the least fixed point); upper = the discrete baseline at the same h",
                   "the engine's certified enclosure meets [lower, upper] widened by 1e-9 (1 + |value|) (double "
                   "rounding of the bracket)",
                   r.t, "length",
                   "bracket width at h (up to " + g3(r.spacing) + "): " + widths(r.coarse) + "; at h/2: " +
                       widths(r.fine) + "; reference time: lower " + g3(r.seconds_lower) + " s, upper " +
                       g3(r.seconds_upper) + " s; " + std::to_string(r.refused) +
                       " instances refused (more than " + std::to_string(kMaxSingularEdges) +
                       " singular edges); uncertified decisions " + std::to_string(r.uncertified));
}

std::vector<CheckRow> check_exact_bracket(const CheckContext& ctx) {
  std::vector<CheckRow> rows;
  {  // the junction books (burn3/junction_books.h), with their sources
    BracketRun r;
    for (const JunctionBook& b : junction_books()) {
      const MedialComplex mc(junction_book_complex(b));
      const ComplexLocator locator(mc);
      std::vector<PointSource> sources;
      for (const JunctionBookSource& s : b.sources)
        sources.push_back({locator.locate(junction_book_point(b, {sgn(s.s) > 0 ? 'A' : 'N', s.x, s.s})), s.t0});
      std::vector<ComplexPoint> points = probe_points(ctx, mc, locator);
      for (const JunctionBookPoint& p : b.checks) points.push_back(locator.locate(junction_book_point(b, p)));
      run(ctx, mc, 0.05, sources, points, r);
      if (ctx.tiny()) break;
    }
    rows.push_back(row("junction books (burn3/junction_books.h: dips 1e-6 to 1e-2, double crossings, tangency, "
                       "near-degenerate angles, sources on N)",
                       r));
  }
  for (const Corpus3& corpus : burning_corpora(ctx)) {
    if (corpus.instances.empty()) continue;
    BracketRun r;
    for (const Instance3& in : corpus.instances) {
      if (in.mc.count(EdgeStratum::Singular) > kMaxSingularEdges) {
        ++r.refused;
        continue;
      }
      const ComplexLocator locator(in.mc);
      run(ctx, in.mc, bracket_spacing(in.mc, in.spacing), {}, probe_points(ctx, in.mc, locator), r);
    }
    rows.push_back(row(corpus.name, r));
  }
  return rows;
}

MutantList bracket_mutants() {
  MutantList output;
  for (const MutantInfo& m : burning_mutants())
    if (m.name == "bt-bump" || m.name == "bt-dip" || m.name == "bt-infinite") output.push_back(m);
  for (const MutantInfo& m : engine_mutants()) output.push_back(m);
  return output;
}

GF_REGISTER_CHECK("exact-bracket", check_exact_bracket, bracket_mutants());

}  // namespace
}  // namespace grassfire::checks
