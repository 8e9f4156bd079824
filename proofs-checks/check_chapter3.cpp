// check_chapter3.cpp -- Propositions 1, 2 and 3 of chapter 3 on real and generated axes.
//
// Corpus: every shape of data/shapes2d (real silhouettes) and the built-in shapes, each
// with its sampled Voronoi axis and its exact polygon axis, plus seeded random medial
// graphs with and without cycles (medial2/synthetic_graphs.h). For each axis the exact
// extended grassfire runs once; the checks then read its output:
//  - Prop 1: EDF >= R at every node, with equality exactly at the leaves (certified
//    comparisons of the exact values), and EDF infinite exactly on the 2-core, which is
//    computed here by an independent peeling.
//  - Prop 2: at every node the incident branches split into: one with directional
//    gradient +1 (none on the EMA), at least one with gradient -1 continuous at the node,
//    the rest with gradient -1 strictly below EDF(x) (certified). The piecewise-linear EDF
//    is also probed a quarter along every incident edge: EDF(s) - EDF(x) must be +-s.
//  - Prop 3: the EMA has the Betti numbers of the medial axis (per component: a point for
//    a tree, the 2-core with the same cycle rank otherwise).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numeric>
#include <string>

#include "burn2/extended_grassfire.h"
#include "check_registry.h"
#include "medial2/polygon_axis.h"
#include "medial2/synthetic_graphs.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "shapes/load_shape.h"

namespace grassfire::checks {

namespace {

struct Tally {
  std::uint64_t instances = 0, points = 0;
  std::uint64_t violations = 0;
  double worst = 0;  // length
};

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

void check_prop2(const MedialGraph& g, const GrassfireResult& r, Tally& t) {
  ++t.instances;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    ++t.points;
    if (r.is_infinite(v)) {
      // Prop 2.4: infinite on two or more branches (the 2-core edges at v).
      int infinite_branches = 0;
      g.for_each_incident(v, [&](std::uint32_t e) {
        infinite_branches += r.fire[e].from_u == kNoTime && r.fire[e].from_v == kNoTime;
      });
      if (infinite_branches < 2) ++t.violations;
      continue;
    }
    if (g.degree(v) == 0) continue;  // an isolated point has no branches
    int up = 0, down_continuous = 0, down_below = 0, bad = 0;
    const GraphSum t_v = r.times.as_graph_sum(r.burn[v]);
    g.for_each_incident(v, [&](std::uint32_t e) {
      const std::uint32_t k = g.other_end(e, v);
      const double w = g.edge(e).length.mid();
      const bool v_sent = sent_from(r, g, e, v) == r.burn[v];
      const TimeId from_k = sent_from(r, g, e, k);
      if (!v_sent && from_k == kNoTime) {
        ++bad;  // a finite node next to an edge that never burns
        return;
      }
      // The front from k reaches v at T_k + w; compare it with EDF(v).
      int arrival = 1;  // no front from k: as if it arrived later
      if (from_k != kNoTime) {
        GraphSum a = r.times.as_graph_sum(from_k);
        a.add_length(e);
        arrival = compare(a, t_v, g);
      }
      double s = w / 4;  // probe inside the part of e next to v where the EDF is linear
      if (v_sent && from_k != kNoTime) s = std::max(0.0, (w + r.times.approx(from_k).mid() - r.edf(v).mid()) / 4);
      const Interval probe = r.edf_along(e, v, s) - r.edf(v);
      if (v_sent && arrival > 0) {  // the EDF rises along e (up to a quench inside it)
        ++up;
        t.worst = std::max(t.worst, std::max(0.0, std::fabs(probe.mid() - s) - probe.radius()));
        return;
      }
      // Gradient -1 towards v: EDF(s) = T_k + w - s, a jump below EDF(v) unless continuous.
      const Interval expected = r.times.approx(from_k) + g.edge(e).length - r.edf(v) - Interval(s);
      const Interval deviation = probe - expected;
      t.worst = std::max(t.worst, std::max(0.0, std::fabs(deviation.mid()) - deviation.radius()));
      if (arrival == 0)
        ++down_continuous;
      else if (arrival < 0 && !v_sent)
        ++down_below;
      else
        ++bad;
    });
    const bool leaf = g.degree(v) == 1;
    bool ok = bad == 0;
    if (leaf)
      ok = ok && (up == 1 || on_ema_node(r, v));
    else if (on_ema_node(r, v))
      ok = ok && up == 0 && down_continuous >= 2;
    else
      ok = ok && up == 1 && down_continuous >= 1;
    if (!ok) ++t.violations;
  }
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

void check_axis(const MedialGraph& g, Tallies& t) {
  const GrassfireResult r = extended_grassfire(g);
  check_prop1(g, r, t.prop1);
  check_prop2(g, r, t.prop2);
  check_prop3(g, r, t.prop3);
}

// The sampled axis has the shape's topology: one component, one cycle per hole.
void check_topology(const Shape2& s, const MedialGraph& g, Tally& t) {
  ++t.instances;
  ++t.points;
  if (g.component_count() != 1 || g.cycle_rank() != s.rings.size() - 1) ++t.violations;
}

std::vector<Shape2> corpus(const CheckContext& ctx) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(ctx.data_dir + "/shapes2d"))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  if (ctx.quick) files.resize(std::min<std::size_t>(files.size(), 30));
  std::vector<Shape2> shapes;
  for (const std::string& f : files) shapes.push_back(load_shape(f));
  for (const BuiltinShapeInfo& b : builtin_shape_list()) shapes.push_back(builtin_shape(b.name));
  return shapes;
}

CheckRow row(const std::string& prop, const std::string& corpus_name, const Tally& t, const std::string& unit,
             double worst, const std::string& note) {
  CheckRow r;
  r.proposition = prop;
  r.corpus = corpus_name;
  r.instances = t.instances;
  r.points = t.points;
  r.worst_violation = worst;
  r.unit = unit;
  r.pass = t.violations == 0 && t.instances > 0;
  r.note = note + (t.violations ? " (" + std::to_string(t.violations) + " violations)" : "");
  return r;
}

std::vector<CheckRow> run_chapter3(const CheckContext& ctx) {
  const std::vector<Shape2> shapes = corpus(ctx);
  Tallies sampled, exact, generated;
  Tally topology;
  const std::size_t samples = ctx.quick ? 800 : kDefaultSamples;
  for (const Shape2& s : shapes) {
    Edf2dOptions o;
    o.samples = samples;
    const Edf2dResult r = compute_edf2d(s, o);
    check_axis(*r.graph, sampled);
    check_topology(s, *r.graph, topology);
    check_axis(exact_polygon_axis(s), exact);
  }
  const std::uint64_t graphs = ctx.quick ? 100 : 400;
  for (std::uint64_t seed = 0; seed < graphs; ++seed) {
    const SyntheticFamily family = seed % 2 ? SyntheticFamily::Geometric : SyntheticFamily::Integer;
    check_axis(random_medial_graph(1000 + seed, 2 + static_cast<std::uint32_t>(seed % 80),
                                   static_cast<std::uint32_t>(seed % 4), family),
               generated);
  }
  const std::string real = std::to_string(shapes.size()) + " shapes";
  const std::string s_name = real + ", sampled axis (" + std::to_string(samples) + " samples)";
  const std::string e_name = real + ", exact polygon axis";
  const std::string g_name = std::to_string(graphs) + " random graphs (with and without cycles)";
  std::vector<CheckRow> rows;
  for (const auto& [name, t] : {std::pair<std::string, const Tallies*>{s_name, &sampled}, {e_name, &exact},
                                {g_name, &generated}}) {
    rows.push_back(row("Prop 1: EDF >= R, equal exactly at leaves; EDF = inf exactly on the 2-core", name, t->prop1,
                       "length", t->prop1.worst, "certified comparisons"));
    rows.push_back(row("Prop 2: one +1 branch (none on the EMA), >= 1 continuous -1, rest strictly below", name,
                       t->prop2, "length", t->prop2.worst, "worst: abs(EDF(x+s) - EDF(x) -+ s) beyond its enclosure"));
    rows.push_back(row("Prop 3: EMA has the Betti numbers of M", name, t->prop3, "count", double(t->prop3.violations),
                       "b0 and b1 per graph"));
  }
  rows.push_back(row("Sampled axis has the shape's topology (1 component, 1 cycle per hole)", s_name, topology,
                     "count", double(topology.violations), "property of the Voronoi axis, not of the EDF"));
  return rows;
}

}  // namespace

GF_REGISTER_CHECK("chapter3", run_chapter3);

}  // namespace grassfire::checks
