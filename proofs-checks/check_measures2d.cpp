// check_measures2d.cpp -- the chapter-3 measures: the identity ET = EDF - R of 3.4.1 by
// Shaked and Bruckstein's rate pruning, the claims about the potential residue of 3.4.2,
// and the exact medial axis of a union of disks (2.1.1).
//
// Corpora: the shapes of data/shapes2d (real silhouettes) with their sampled Voronoi axis
// and their exact polygon axis; the built-in shapes (synthetic); seeded random medial
// graphs, trees and graphs with cycles, integer and geometric (generated); seeded random
// unions of disks with decimal data (generated). The engine's outputs pass through the
// context's mutant (mutants2d.h) before any row reads them. Rows:
//  - ET identity: at every node the rate-pruning time (burn2/rate_pruning.h, which never
//    reads the EDF) equals EDF - R, by an exact comparison of the two sums of graph atoms;
//    both infinite exactly together.
//  - ET maximum = EMA (3.4.1: ET and EDF share their local maxima): ET evaluated by rate
//    pruning at every node, its largest value found by exact comparisons, must be at the
//    EMA node (alone) or at an end of the EMA's edge; and the last pruning fronts must
//    meet exactly at the EMA point (same node, or same edge and equal offsets).
//  - PR from the ends inward (3.4.2, Ogniewicz and Ilg): on every path from a leaf to the
//    PR maximum, PR never decreases inside edges and at degree-2 nodes (decreases certified
//    by the enclosures), and separately at junctions, where 3.4.2 says PR is discontinuous.
//  - PR maximum unique on a simply connected shape: the local maximum regions counted
//    here from the node and edge values (count_maxima), equal to 1 and to the engine's count.
//  - Union of disks: the definition-level validation (two or more closest boundary points
//    at every node and edge midpoint, nothing closer, degrees) and the Betti numbers of the
//    axis against those of the union from the dual complex.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <random>
#include <string>

#include "burn2/closest_points.h"
#include "burn2/potential_residue.h"
#include "burn2/rate_pruning.h"
#include "check_registry.h"
#include "support/union_find.h"
#include "mutants2d.h"
#include "medial2/disks/disk_union_axis.h"
#include "medial2/disks/disk_union_validate.h"
#include "medial2/synthetic_graphs.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "io/disk_list.h"
#include "io/load_shape.h"
#include "support/cpu_clock.h"

namespace grassfire::checks {

namespace {

using Clock = std::chrono::steady_clock;

struct TimedTally : Tally {
  double seconds = 0;
};

// Count rows show the number of violations as their worst value (and not again in the note).
CheckRow row(const std::string& prop, const std::string& corpus, const std::string& reference,
             const std::string& tolerance, const Tally& t, const std::string& unit, const std::string& note) {
  Tally judged = t;
  if (unit == "count") judged.worst = static_cast<double>(t.violations);
  CheckRow r = tally_row(prop, corpus, reference, tolerance, judged, unit, note);
  if (unit == "count") r.note = note;
  return r;
}

// ET = EDF - R at every node.
void check_identity(const MedialGraph& g, const GrassfireResult& burn, const RatePruning& rp, Tally& identity) {
  ++identity.instances;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    ++identity.points;
    if (burn.is_infinite(v) != !rp.time[v]) {
      ++identity.violations;
      continue;
    }
    if (!rp.time[v]) continue;
    GraphSum et = burn.times.as_graph_sum(burn.burn[v]);
    et.add_radius(v, -1);
    if (compare(et, *rp.time[v], g) != 0) {
      ++identity.violations;
      identity.worst = std::max(identity.worst, std::fabs((et.approx(g) - rp.approx[v]).mid()));
    }
  }
}

// The nodes of `component` where ET (the pruning time) is largest, by exact comparisons.
std::vector<std::uint32_t> et_argmax(const MedialGraph& g, const RatePruning& rp, const std::vector<std::uint32_t>& comp,
                                     std::uint32_t component) {
  std::vector<std::uint32_t> best;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    if (comp[v] != component || !rp.time[v]) continue;
    const int c = best.empty() ? 1 : compare(*rp.time[v], *rp.time[best[0]], g);
    if (c > 0) best.clear();
    if (c >= 0) best.push_back(v);
  }
  return best;
}

// Where the EMA of a tree component is against where ET is largest and where the last
// pruning fronts meet.
bool ema_matches(const MedialGraph& g, const GrassfireResult& burn, const RatePruning& rp,
                 const std::vector<std::uint32_t>& comp, const PruningQuench& q) {
  std::vector<const ExtendedMedialAxis*> found;
  for (const ExtendedMedialAxis& e : burn.ema)
    if (e.component == q.component) found.push_back(&e);
  if (found.size() != 1 || found[0]->kind != ExtendedMedialAxis::Kind::Point) return false;
  const ExtendedMedialAxis& ema = *found[0];
  const std::vector<std::uint32_t> top = et_argmax(g, rp, comp, q.component);
  if (ema.point.at_node) {
    if (top.size() != 1 || top[0] != ema.point.node) return false;
    return q.at_node && q.node == ema.point.node;
  }
  const MedialEdge& edge = g.edge(ema.point.edge);
  for (std::uint32_t v : top)
    if (v != edge.u && v != edge.v) return false;
  if (q.at_node || q.edge != ema.point.edge) return false;
  // The EMA offset (w + T_other - T_from) / 2 from ema.from, compared from q.from.
  GraphSum offset = burn.times.as_graph_sum(ema.sent_other) - burn.times.as_graph_sum(ema.sent_from);
  offset.add_length(q.edge).divide(2);
  if (ema.point.from != q.from) offset = GraphSum().add_length(q.edge) - offset;
  return compare(offset, q.offset, g) == 0;
}

void check_rate_pruning(const MedialGraph& g, const GrassfireResult& burn, TimedTally& identity, Tally& maximum) {
  const auto t0 = Clock::now();
  const RatePruning rp = rate_pruning(g);
  identity.seconds += wall_seconds_since(t0);
  check_identity(g, burn, rp, identity);
  ++maximum.instances;
  const std::vector<std::uint32_t> comp = g.component_of_nodes();
  for (const PruningQuench& q : rp.last_quench) {
    ++maximum.points;
    maximum.violations += !ema_matches(g, burn, rp, comp, q);
  }
}

int compare_residue(const ResidueValue& a, const ResidueValue& b) {
  if (a.value.is_infinite() || b.value.is_infinite())
    return a.value.is_infinite() == b.value.is_infinite() ? 0 : (a.value.is_infinite() ? 1 : -1);
  if (a.sample_steps >= 0 && b.sample_steps >= 0 && a.ring == b.ring)
    return (a.sample_steps > b.sample_steps) - (a.sample_steps < b.sample_steps);
  if (a.value.hi < b.value.lo) return -1;
  if (b.value.hi < a.value.lo) return 1;
  return a.exact && b.exact ? sign(*a.exact - *b.exact) : 0;  // undecided counts as equal, as in the engine
}

// Local maximum regions of PR from its values: each peak inside an edge, and each set of
// nodes joined by constant edges at their top value from which no edge rises.
std::uint32_t count_maxima(const MedialGraph& g, const PotentialResidue& pr) {
  UnionFind plateau(g.node_count());
  std::vector<bool> rises(g.node_count(), false);
  std::uint32_t maxima = 0;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const std::uint32_t u = g.edge(e).u, v = g.edge(e).v;
    const EdgeResidue& r = pr.edge[e];
    const bool top_u = compare_residue(r.at_u, pr.node[u]) >= 0, top_v = compare_residue(r.at_v, pr.node[v]) >= 0;
    if (r.peak) {  // a maximum inside the edge: PR rises from both ends
      ++maxima;
      rises[u] = rises[u] || top_u;
      rises[v] = rises[v] || top_v;
      continue;
    }
    const int c = compare_residue(r.at_v, r.at_u);
    if (c == 0 && top_u && top_v) {
      plateau.unite(u, v);
      continue;
    }
    // Rising from u to v, or level up to a node v that is higher still: u is no maximum.
    if (c >= 0 && top_u) rises[u] = true;
    if (c <= 0 && top_v) rises[v] = true;
  }
  std::vector<bool> spoiled(g.node_count(), false);
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (rises[v]) spoiled[plateau.find(v)] = true;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) maxima += plateau.find(v) == v && !spoiled[v];
  return maxima;
}

struct ResidueTallies {
  Tally regular, junction;
  TimedTally unique;
};

void check_residue(const CheckContext& ctx, const MedialGraph& g, const ClosestPoints& cp, ResidueTallies& t) {
  const auto t0 = Clock::now();
  PotentialResidue pr = potential_residue(g, cp);
  t.unique.seconds += wall_seconds_since(t0);
  mutate_residue(ctx, g, pr);
  const ResidueMonotonicity m = residue_monotonicity(g, pr);
  const double scale = pr.maximum.value.value.mid();
  ++t.regular.instances;
  t.regular.points += m.edges_checked + m.regular_nodes;
  t.regular.violations += m.edge_decreases + m.regular_decreases;
  t.regular.worst = std::max(t.regular.worst, m.worst_regular_drop / scale);
  ++t.junction.instances;
  t.junction.points += m.junctions;
  t.junction.violations += m.junction_decreases;
  t.junction.worst = std::max(t.junction.worst, m.worst_junction_drop / scale);
  const std::uint32_t maxima = count_maxima(g, pr);
  ++t.unique.instances;
  ++t.unique.points;
  t.unique.violations += maxima != 1 || pr.local_maxima != maxima;
  t.unique.worst = std::max<double>(t.unique.worst, maxima);
}

std::vector<Shape2> real_shapes(const CheckContext& ctx) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(ctx.data_dir + "/shapes2d"))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  if (ctx.quick()) files.resize(std::min<std::size_t>(files.size(), ctx.tiny() ? 2 : 12));
  std::vector<Shape2> shapes;
  for (const std::string& f : files) shapes.push_back(load_shape(f));
  return shapes;
}

DiskList random_union(std::mt19937& rng, int disks) {
  std::uniform_int_distribution<int> coord(0, 1000), radius(40, 160);
  std::string text;
  for (int i = 0; i < disks; ++i)
    text += std::to_string(coord(rng)) + "e-2 " + std::to_string(coord(rng)) + "e-2 " +
            std::to_string(radius(rng)) + "e-2\n";
  return parse_disk_list(text, "random union");
}

struct AxisCorpus {
  std::string name;
  TimedTally identity;
  Tally maximum;
  ResidueTallies residue;
};

// The pipeline on one shape and axis, its burning mutated, then every row of the corpus.
void check_shape(const CheckContext& ctx, const Shape2& shape, AxisMethod method, std::size_t samples, AxisCorpus& c,
                 bool residue) {
  Edf2dOptions o;
  o.axis = method;
  o.samples = samples;
  Edf2dResult r = compute_edf2d(shape, o);
  mutate_grassfire(ctx, *r.graph, *r.burning);
  check_rate_pruning(*r.graph, *r.burning, c.identity, c.maximum);
  // PR never reads the burning: a mutant of the burning cannot reach its rows.
  const bool residue_mutant = ctx.mutant.rfind("pr-", 0) == 0;
  if (residue && (ctx.mutant.empty() || residue_mutant))
    check_residue(ctx, *r.graph, closest_points(*r.graph, &shape, &r.samples), c.residue);
}

std::vector<CheckRow> residue_rows(const AxisCorpus& c) {
  std::vector<CheckRow> rows;
  const std::string reference = "PR compared point by point along every leaf-to-maximum path (residue_monotonicity)";
  rows.push_back(row("PR non-decreasing from the ends inward, away from junctions (3.4.2)", c.name, reference,
                     "certified by the enclosures", c.residue.regular, "of PR max",
                     "inside edges and at degree-2 nodes, on paths from the leaves to the PR maximum"));
  rows.push_back(row("PR non-decreasing across junctions (3.4.2 says PR jumps there)", c.name, reference,
                     "certified by the enclosures", c.residue.junction, "of PR max",
                     "parent-branch limit vs child-branch limit at junctions"));
  char note[128];
  std::snprintf(note, sizeof note, "largest count of local maxima; PR computed in %.2f s in all",
                c.residue.unique.seconds);
  rows.push_back(row("PR maximum unique (3.4.2, Ogniewicz and Ilg)", c.name,
                     "local maximum regions counted from the PR values (count_maxima), = the engine's count",
                     "exact where the enclosures overlap", c.residue.unique, "maxima", note));
  return rows;
}

std::vector<CheckRow> run_measures2d(const CheckContext& ctx) {
  const std::vector<Shape2> shapes = real_shapes(ctx);
  const std::size_t samples = ctx.tiny() ? 400 : ctx.quick() ? 800 : kDefaultSamples;
  const std::string real = "real: " + std::to_string(shapes.size()) + " shapes of data/shapes2d";
  AxisCorpus sampled{real + "; sampled axis (" + std::to_string(samples) + " samples)", {}, {}, {}};
  AxisCorpus exact{real + "; exact polygon axis", {}, {}, {}};
  for (const Shape2& shape : shapes) {
    check_shape(ctx, shape, AxisMethod::Sampled, samples, sampled, true);
    check_shape(ctx, shape, AxisMethod::ExactPolygon, samples, exact, true);
  }
  AxisCorpus builtin{"synthetic: the built-in shapes, both axes", {}, {}, {}};
  for (const BuiltinShapeInfo& info : builtin_shape_list())
    for (AxisMethod m : {AxisMethod::Sampled, AxisMethod::ExactPolygon})
      if (!ctx.tiny() || info.name == "hole" || info.name == "branches") check_shape(ctx, builtin_shape(info.name), m, samples, builtin, false);
  const std::uint32_t graphs = ctx.tiny() ? 16 : ctx.quick() ? 60 : 240;
  AxisCorpus synthetic{"generated: " + std::to_string(graphs) + " seeded random graphs (trees and cycles)", {}, {}, {}};
  for (std::uint32_t k = 0; k < graphs; ++k) {
    const MedialGraph g = random_medial_graph(3100 + k, 5 + k % 60, k % 3 == 0 ? k % 5 : 0,
                                              k % 2 ? SyntheticFamily::Integer : SyntheticFamily::Geometric);
    GrassfireResult burn = extended_grassfire(g);
    mutate_grassfire(ctx, g, burn);
    check_rate_pruning(g, burn, synthetic.identity, synthetic.maximum);
  }
  const int unions = ctx.tiny() ? 3 : ctx.quick() ? 8 : 40;
  AxisCorpus disks{"generated: " + std::to_string(unions) + " seeded random unions of 5-40 disks", {}, {}, {}};
  Tally disk_axis;
  std::mt19937 rng(2001);
  for (int k = 0; k < unions; ++k) {
    const DiskList list = random_union(rng, 5 + k % 36);
    DiskUnionAxisReport report;
    const MedialGraph g = disk_union_axis(list, &report);
    const DiskAxisValidation v = validate_disk_union_axis(mutate_axis(ctx, g), report);
    ++disk_axis.instances;
    disk_axis.points += v.nodes_checked + v.edges_checked;
    disk_axis.violations += v.failures.size();
    GrassfireResult burn = extended_grassfire(g);
    mutate_grassfire(ctx, g, burn);
    check_rate_pruning(g, burn, disks.identity, disks.maximum);
  }
  std::vector<CheckRow> rows;
  for (const AxisCorpus* c : {&sampled, &exact, &builtin, &synthetic, &disks}) {
    char note[96];
    std::snprintf(note, sizeof note, "rate pruning %.2f s in all", c->identity.seconds);
    rows.push_back(row("ET = EDF - R by rate pruning (3.4.1)", c->name,
                       "rate pruning (Shaked and Bruckstein; never reads the EDF)", "exact", c->identity, "count", note));
    rows.push_back(row("ET maximum = EMA (3.4.1)", c->name,
                       "ET by rate pruning: its largest node value, and where its last fronts meet", "exact",
                       c->maximum, "count", "EMA node = the unique ET argmax, or the argmax is an end of the EMA's edge"));
  }
  for (const AxisCorpus* c : {&sampled, &exact})
    if (c->residue.unique.instances > 0)
      for (CheckRow& r : residue_rows(*c)) rows.push_back(std::move(r));
  rows.push_back(row("Union of disks: >= 2 closest points, Betti numbers of the union (2.1.1)", disks.name,
                     "brute force over every corner and arc of the union; Betti numbers from the dual complex", "exact",
                     disk_axis, "count", "definition-level validation of nodes and edge midpoints"));
  return rows;
}

MutantList measures_mutants() {
  MutantList m = grassfire_mutants();
  for (MutantInfo& r : residue_mutants()) m.push_back(std::move(r));
  return m;
}

}  // namespace

GF_REGISTER_CHECK("measures2d", run_measures2d, measures_mutants());

}  // namespace grassfire::checks
