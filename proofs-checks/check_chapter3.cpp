// check_chapter3.cpp -- Propositions 1, 2 and 3 of chapter 3 on real and generated axes.
//
// Corpora: every shape of data/shapes2d (real silhouettes) and the built-in shapes, each
// with its sampled Voronoi axis and its exact polygon axis, plus seeded random medial
// graphs with and without cycles (medial2/synthetic_graphs.h). For each axis the exact
// extended grassfire runs once (then the context's mutant, mutants2d.h); the rows compare
// its output with independent computations:
//  - Prop 1: EDF >= R at every node, with equality exactly at the leaves (certified
//    comparisons with the input's R), and EDF infinite exactly on the 2-core, computed
//    here by an independent peeling.
//  - Prop 2: at every node the incident branches split into one with directional
//    gradient +1 (none on the EMA), at least one with gradient -1 continuous at the node,
//    the rest with gradient -1 strictly below EDF(x). The engine's split (from its fronts)
//    must be a valid one and equal the split of the definition-level oracle
//    (edf_definition.h: reach of each branch against the second largest, exactly); and
//    the EDF a quarter and three quarters along every finite edge, read from the engine's
//    fronts, must lie in the oracle's min(s + A_i, w - s + A_j) (disjoint enclosures are
//    a violation; worst = the gap).
//  - Prop 3: the EMA has the Betti numbers of the medial axis (union-find on the axis).
//  - The sampled axis has the shape's topology (its rings), a property of the builder.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numeric>
#include <string>

#include "burn2/edf_definition.h"
#include "burn2/extended_grassfire.h"
#include "check_registry.h"
#include "mutants2d.h"
#include "medial2/polygon/polygon_axis.h"
#include "medial2/synthetic_graphs.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"

namespace grassfire::checks {

namespace {

struct Tallies {
  Tally prop1, prop2, prop3, topology;
};

std::vector<bool> peel_two_core(const MedialGraph& g) {
  std::vector<std::uint32_t> degree(g.node_count());
  std::vector<bool> alive(g.node_count(), true);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if ((degree[v] = g.degree(v)) <= 1) stack.push_back(v);
  while (!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    if (!alive[v]) continue;
    alive[v] = false;
    g.for_each_incident(v, [&](std::uint32_t e) {
      const std::uint32_t w = g.other_end(e, v);
      if (alive[w] && --degree[w] <= 1) stack.push_back(w);
    });
  }
  return alive;
}

void check_prop1(const MedialGraph& g, const GrassfireResult& r, Tally& t) {
  const std::vector<bool> core = peel_two_core(g);
  ++t.instances;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    ++t.points;
    if (r.is_infinite(v) != core[v]) {
      ++t.violations;
      continue;
    }
    if (core[v]) continue;
    const int c = compare(r.times.as_graph_sum(r.burn[v]), GraphSum().add_radius(v), g);
    const bool ok = g.degree(v) <= 1 ? c == 0 : c > 0;
    if (!ok) {
      ++t.violations;
      t.worst = std::max(t.worst, std::max(0.0, g.node(v).radius.mid() - r.edf(v).mid()));
    }
  }
}

TimeId sent_from(const GrassfireResult& r, const MedialGraph& g, std::uint32_t e, std::uint32_t v) {
  return g.edge(e).u == v ? r.fire[e].from_u : r.fire[e].from_v;
}

bool on_ema_node(const GrassfireResult& r, std::uint32_t v) {
  for (const ExtendedMedialAxis& e : r.ema)
    if (e.kind == ExtendedMedialAxis::Kind::Point && e.point.at_node && e.point.node == v) return true;
  return false;
}

enum class Branch { Up, Continuous, Below, Bad };

// The engine's class of the branch through e at v, from its fronts: the fire v sent, and
// the front from the other end k (reaching v at T_k + w).
Branch engine_branch(const MedialGraph& g, const GrassfireResult& r, std::uint32_t v, std::uint32_t e) {
  const std::uint32_t k = g.other_end(e, v);
  const bool v_sent = sent_from(r, g, e, v) == r.burn[v];
  const TimeId from_k = sent_from(r, g, e, k);
  if (!v_sent && from_k == kNoTime) return Branch::Bad;  // a finite node next to an edge that never burns
  int arrival = 1;  // no front from k: as if it arrived later
  if (from_k != kNoTime) {
    GraphSum a = r.times.as_graph_sum(from_k);
    a.add_length(e);
    arrival = compare(a, r.times.as_graph_sum(r.burn[v]), g);
  }
  if (v_sent && arrival > 0) return Branch::Up;
  if (arrival == 0) return Branch::Continuous;
  return arrival < 0 && !v_sent ? Branch::Below : Branch::Bad;
}

// The oracle's class: the branch's reach against EDF(v) (exact).
Branch definition_branch(const MedialGraph& g, const DefinitionalEdf& d, std::uint32_t v, const BranchReach& b) {
  if (!b.reach) return Branch::Up;  // an infinite branch at a finite node is its only way up
  const int c = compare(*b.reach, *d.edf[v], g);
  return c > 0 ? Branch::Up : c == 0 ? Branch::Continuous : Branch::Below;
}

// A_v(e): the largest reach at v over the branches other than e, R(v) at a leaf; nullopt
// when infinite.
std::optional<GraphSum> away_reach(const MedialGraph& g, const DefinitionalEdf& d, std::uint32_t v, std::uint32_t e) {
  if (g.degree(v) == 1) return GraphSum().add_radius(v);
  std::optional<GraphSum> best;
  bool first = true;
  for (const BranchReach& b : d.branches[v]) {
    if (b.edge == e) continue;
    if (!b.reach) return std::nullopt;
    if (first || compare(*b.reach, *best, g) > 0) best = b.reach;
    first = false;
  }
  return best;
}

// Prop 2's split at a node: valid, and equal to the oracle's branch by branch.
bool split_agrees(const MedialGraph& g, const GrassfireResult& r, const DefinitionalEdf& d, std::uint32_t v) {
  int up = 0, continuous = 0;
  bool ok = true;
  for (const BranchReach& b : d.branches[v]) {
    const Branch engine = engine_branch(g, r, v, b.edge);
    ok = ok && engine != Branch::Bad && engine == definition_branch(g, d, v, b);
    up += engine == Branch::Up;
    continuous += engine == Branch::Continuous;
  }
  if (g.degree(v) == 1) return ok && (up == 1 || on_ema_node(r, v));
  if (on_ema_node(r, v)) return ok && up == 0 && continuous >= 2;
  return ok && up == 1 && continuous >= 1;
}

// The engine's EDF a quarter and three quarters along e against the oracle's.
void probe_edge(const MedialGraph& g, const GrassfireResult& r, const DefinitionalEdf& d, std::uint32_t e, Tally& t) {
  const std::uint32_t i = g.edge(e).u, j = g.edge(e).v;
  const std::optional<GraphSum> ai = away_reach(g, d, i, e), aj = away_reach(g, d, j, e);
  if (!d.edf[i] || !d.edf[j] || !ai || !aj) return;
  const Interval w = g.edge(e).length, a = ai->approx(g), b = aj->approx(g);
  for (double f : {0.25, 0.75}) {
    const double s = f * w.mid();
    const Interval up = Interval(s) + a, down = w - Interval(s) + b;
    const Interval oracle(std::fmin(up.lo, down.lo), std::fmin(up.hi, down.hi));
    const Interval engine = r.edf_along(e, i, s);
    ++t.points;
    const double gap = std::max(engine.lo - oracle.hi, oracle.lo - engine.hi);
    if (gap > 0) ++t.violations, t.worst = std::max(t.worst, gap);
  }
}

void check_prop2(const MedialGraph& g, const GrassfireResult& r, const DefinitionalEdf& d, Tally& t) {
  ++t.instances;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    ++t.points;
    if (r.is_infinite(v)) {
      // Prop 2.4: infinite on two or more branches (the 2-core edges at v).
      int infinite_branches = 0;
      g.for_each_incident(v, [&](std::uint32_t e) {
        infinite_branches += r.fire[e].from_u == kNoTime && r.fire[e].from_v == kNoTime;
      });
      t.violations += infinite_branches < 2 || d.edf[v].has_value();
      continue;
    }
    if (g.degree(v) == 0) continue;  // an isolated point has no branches
    if (!d.edf[v] || !split_agrees(g, r, d, v)) ++t.violations;
  }
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) probe_edge(g, r, d, e, t);
}

std::uint32_t find(std::vector<std::uint32_t>& p, std::uint32_t x) {
  while (p[x] != x) x = p[x] = p[p[x]];
  return x;
}

void check_prop3(const MedialGraph& g, const GrassfireResult& r, Tally& t) {
  ++t.instances;
  // Betti numbers of M per component, from a union-find of its own.
  std::vector<std::uint32_t> parent(g.node_count());
  std::iota(parent.begin(), parent.end(), 0u);
  for (const MedialEdge& e : g.edges()) parent[find(parent, e.u)] = find(parent, e.v);
  std::uint64_t b0 = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) b0 += find(parent, v) == v;
  const std::uint64_t b1 = g.edge_count() + b0 - g.node_count();
  // Betti numbers of the EMA: points count one component each; cycles contribute the
  // components and cycle rank of the 2-core.
  std::uint64_t ema_b0 = 0, ema_b1 = 0;
  for (const ExtendedMedialAxis& e : r.ema) {
    ++t.points;
    if (e.kind == ExtendedMedialAxis::Kind::Point) {
      ++ema_b0;
      continue;
    }
    std::vector<std::uint32_t> p(g.node_count());
    std::iota(p.begin(), p.end(), 0u);
    for (std::uint32_t k : e.edges) p[find(p, g.edge(k).u)] = find(p, g.edge(k).v);
    std::uint64_t comps = 0;
    for (std::uint32_t v : e.nodes) comps += find(p, v) == v;
    ema_b0 += comps;
    ema_b1 += e.edges.size() + comps - e.nodes.size();
  }
  if (ema_b0 != b0 || ema_b1 != b1) ++t.violations;
}

void check_axis(const CheckContext& ctx, const MedialGraph& g, Tallies& t) {
  GrassfireResult r = extended_grassfire(g);
  mutate_grassfire(ctx, g, r);
  const DefinitionalEdf d = edf_by_definition(g);
  check_prop1(g, r, t.prop1);
  check_prop2(g, r, d, t.prop2);
  check_prop3(g, r, t.prop3);
}

// The sampled axis has the shape's topology: one component, one cycle per hole.
void check_topology(const CheckContext& ctx, const Shape2& s, const MedialGraph& axis, Tally& t) {
  const MedialGraph g = mutate_axis(ctx, axis);
  ++t.instances;
  ++t.points;
  if (g.component_count() != 1 || g.cycle_rank() != s.rings.size() - 1) ++t.violations;
}

struct Shapes {
  std::vector<Shape2> shapes;
  std::size_t real = 0;  // the first `real` come from data/shapes2d, the rest are built in
};

Shapes corpus(const CheckContext& ctx) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(ctx.data_dir + "/shapes2d"))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  if (ctx.quick()) files.resize(std::min<std::size_t>(files.size(), ctx.tiny() ? 3 : 30));
  Shapes out;
  for (const std::string& f : files) out.shapes.push_back(load_shape(f));
  out.real = out.shapes.size();
  for (const BuiltinShapeInfo& b : builtin_shape_list())
    if (!ctx.tiny() || b.name == "hole") out.shapes.push_back(builtin_shape(b.name));
  return out;
}

CheckRow row(const std::string& prop, const std::string& corpus_name, const std::string& reference,
             const std::string& tolerance, const Tally& t, const std::string& unit, double worst, const std::string& note) {
  Tally judged = t;
  judged.worst = worst;
  return tally_row(prop, corpus_name, reference, tolerance, judged, unit, note);
}

std::vector<CheckRow> run_chapter3(const CheckContext& ctx) {
  const Shapes corpus_shapes = corpus(ctx);
  Tallies sampled, exact, generated;
  Tally topology;
  // The oracle of Prop 2 costs O(n^2) per axis: 1000 samples keep the full run to minutes.
  const std::size_t samples = ctx.tiny() ? 400 : ctx.quick() ? 800 : 1000;
  for (const Shape2& s : corpus_shapes.shapes) {
    Edf2dOptions o;
    o.samples = samples;
    const Edf2dResult r = compute_edf2d(s, o);
    check_axis(ctx, *r.graph, sampled);
    check_topology(ctx, s, *r.graph, topology);
    check_axis(ctx, exact_polygon_axis(s), exact);
  }
  const std::uint64_t graphs = ctx.tiny() ? 16 : ctx.quick() ? 100 : 400;
  for (std::uint64_t seed = 0; seed < graphs; ++seed) {
    const SyntheticFamily family = seed % 2 ? SyntheticFamily::Geometric : SyntheticFamily::Integer;
    check_axis(ctx,
               random_medial_graph(1000 + seed, 2 + static_cast<std::uint32_t>(seed % 80),
                                   static_cast<std::uint32_t>(seed % 4), family),
               generated);
  }
  const std::string shapes = "real: " + std::to_string(corpus_shapes.real) + " shapes of data/shapes2d, and " +
                             std::to_string(corpus_shapes.shapes.size() - corpus_shapes.real) + " synthetic built-ins";
  const std::string s_name = shapes + "; sampled axis (" + std::to_string(samples) + " samples)";
  const std::string e_name = shapes + "; exact polygon axis";
  const std::string g_name = "generated: " + std::to_string(graphs) + " seeded random graphs (with and without cycles)";
  std::vector<CheckRow> rows;
  for (const auto& [name, t] : {std::pair<std::string, const Tallies*>{s_name, &sampled}, {e_name, &exact},
                                {g_name, &generated}}) {
    rows.push_back(row("Prop 1: EDF >= R, equal exactly at leaves; EDF = inf exactly on the 2-core", name,
                       "R of the input; the 2-core by an independent peeling", "exact", t->prop1, "length",
                       t->prop1.worst, "certified comparisons; worst: R - EDF where EDF < R"));
    rows.push_back(row("Prop 2: one +1 branch (none on the EMA), >= 1 continuous -1, rest strictly below", name,
                       "the definition-level oracle (edf_definition.h): each branch's reach, EDF along each edge",
                       "exact split; EDF probes: disjoint enclosures", t->prop2, "length", t->prop2.worst,
                       "engine's split = oracle's at every node; worst: gap between the engine's and the oracle's "
                       "EDF a quarter and three quarters along the edges"));
    rows.push_back(row("Prop 3: EMA has the Betti numbers of M", name, "b0, b1 of M by union-find", "exact", t->prop3,
                       "count", double(t->prop3.violations), "b0 and b1 per graph"));
  }
  rows.push_back(row("Sampled axis has the shape's topology (1 component, 1 cycle per hole)", s_name,
                     "the shape's rings", "exact", topology, "count", double(topology.violations),
                     "property of the Voronoi axis builder, not of the EDF"));
  return rows;
}

}  // namespace

GF_REGISTER_CHECK("chapter3", run_chapter3, grassfire_mutants());

}  // namespace grassfire::checks
