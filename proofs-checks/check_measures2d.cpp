// check_measures2d.cpp -- the chapter-3 measures: the identity ET = EDF - R of 3.4.1 by
// Shaked and Bruckstein's rate pruning, the claims about the potential residue of 3.4.2,
// and the exact medial axis of a union of disks (2.1.1).
//
// Corpora: every shape of data/shapes2d (real silhouettes) with its sampled Voronoi axis
// and its exact polygon axis; the built-in shapes; seeded random medial graphs, trees and
// graphs with cycles, integer and geometric (medial2/synthetic_graphs.h); seeded random
// unions of disks with decimal data.
// Rows:
//  - ET identity: at every node the rate-pruning time (burn2/rate_pruning.h, which never
//    reads the EDF) equals EDF - R, by an exact comparison of the two sums of graph atoms;
//    both infinite exactly together.
//  - ET maximum = EMA (3.4.1: ET and EDF share their local maxima): where the last pruning
//    fronts meet is the EMA point, exactly (same node, or same edge and equal offsets).
//  - PR from the ends inward (3.4.2, Ogniewicz and Ilg): on every path from a leaf to the
//    PR maximum, PR never decreases inside edges and at degree-2 nodes (decreases certified
//    by the enclosures), and separately at junctions, where 3.4.2 says PR is discontinuous.
//  - PR maximum unique on a simply connected shape: one local maximum region.
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
#include "medial2/disk_union_axis.h"
#include "medial2/disk_union_validate.h"
#include "medial2/synthetic_graphs.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "shapes/load_shape.h"

namespace grassfire::checks {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Tally {
  std::uint64_t instances = 0, points = 0, violations = 0;
  double worst = 0;
  double seconds = 0;
};

CheckRow row(const std::string& prop, const std::string& corpus, const Tally& t, const std::string& unit,
             const std::string& note) {
  CheckRow r;
  r.proposition = prop;
  r.corpus = corpus;
  r.instances = t.instances;
  r.points = t.points;
  r.worst_violation = unit == "count" ? static_cast<double>(t.violations) : t.worst;
  r.unit = unit;
  r.pass = t.violations == 0;
  r.note = note;
  return r;
}

// ET = EDF - R at every node, and the last pruning quench at the EMA.
void check_rate_pruning(const MedialGraph& g, const GrassfireResult& burn, Tally& identity, Tally& maximum) {
  const auto t0 = Clock::now();
  const RatePruning rp = rate_pruning(g);
  identity.seconds += seconds_since(t0);
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
  ++maximum.instances;
  for (const PruningQuench& q : rp.last_quench) {
    ++maximum.points;
    const auto ema = std::find_if(burn.ema.begin(), burn.ema.end(),
                                  [&](const ExtendedMedialAxis& e) { return e.component == q.component; });
    if (ema == burn.ema.end() || ema->kind != ExtendedMedialAxis::Kind::Point || ema->point.at_node != q.at_node) {
      ++maximum.violations;
      continue;
    }
    if (q.at_node) {
      maximum.violations += ema->point.node != q.node;
      continue;
    }
    if (ema->point.edge != q.edge) {
      ++maximum.violations;
      continue;
    }
    // The EMA offset (w + T_other - T_from) / 2 from ema.from, compared from q.from.
    GraphSum offset = burn.times.as_graph_sum(ema->sent_other) - burn.times.as_graph_sum(ema->sent_from);
    offset.add_length(q.edge).divide(2);
    if (ema->point.from != q.from) offset = GraphSum().add_length(q.edge) - offset;
    if (compare(offset, q.offset, g) != 0) ++maximum.violations;
  }
}

struct ResidueTallies {
  Tally regular, junction, unique;
};

void check_residue(const MedialGraph& g, const ClosestPoints& cp, ResidueTallies& t) {
  const auto t0 = Clock::now();
  const PotentialResidue pr = potential_residue(g, cp);
  t.unique.seconds += seconds_since(t0);
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
  ++t.unique.instances;
  ++t.unique.points;
  t.unique.violations += pr.local_maxima != 1;
  t.unique.worst = std::max<double>(t.unique.worst, pr.local_maxima);
}

std::vector<Shape2> real_shapes(const CheckContext& ctx) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(ctx.data_dir + "/shapes2d"))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  if (ctx.quick) files.resize(std::min<std::size_t>(files.size(), 12));
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
  Tally identity, maximum;
  ResidueTallies residue;
  bool residue_checked = false;
};

std::vector<CheckRow> run_measures2d(const CheckContext& ctx) {
  const std::vector<Shape2> shapes = real_shapes(ctx);
  const std::size_t samples = ctx.quick ? 800 : kDefaultSamples;
  const std::string real = "shapes2d (" + std::to_string(shapes.size()) + " real)";
  AxisCorpus sampled{real + ", sampled axis (" + std::to_string(samples) + " samples)", {}, {}, {}, true};
  AxisCorpus exact{real + ", exact polygon axis", {}, {}, {}, true};
  for (const Shape2& shape : shapes) {
    Edf2dOptions o;
    o.samples = samples;
    for (AxisCorpus* c : {&sampled, &exact}) {
      o.axis = c == &exact ? AxisMethod::ExactPolygon : AxisMethod::Sampled;
      const Edf2dResult r = compute_edf2d(shape, o);
      check_rate_pruning(*r.graph, *r.burning, c->identity, c->maximum);
      check_residue(*r.graph, closest_points(*r.graph, &shape, &r.samples), c->residue);
    }
  }
  AxisCorpus builtin{"built-in shapes, both axes", {}, {}, {}, false};
  for (const BuiltinShapeInfo& info : builtin_shape_list()) {
    const Shape2 shape = builtin_shape(info.name);
    for (AxisMethod m : {AxisMethod::Sampled, AxisMethod::ExactPolygon}) {
      Edf2dOptions o;
      o.axis = m;
      o.samples = samples;
      const Edf2dResult r = compute_edf2d(shape, o);
      check_rate_pruning(*r.graph, *r.burning, builtin.identity, builtin.maximum);
    }
  }
  const std::uint32_t graphs = ctx.quick ? 60 : 240;
  AxisCorpus synthetic{std::to_string(graphs) + " random graphs (trees and cycles, integer and geometric)",
                       {}, {}, {}, false};
  for (std::uint32_t k = 0; k < graphs; ++k) {
    const MedialGraph g = random_medial_graph(3100 + k, 5 + k % 60, k % 3 == 0 ? k % 5 : 0,
                                              k % 2 ? SyntheticFamily::Integer : SyntheticFamily::Geometric);
    check_rate_pruning(g, extended_grassfire(g), synthetic.identity, synthetic.maximum);
  }
  const int unions = ctx.quick ? 8 : 40;
  AxisCorpus disks{std::to_string(unions) + " random unions of 5-40 disks", {}, {}, {}, false};
  Tally disk_axis;
  std::mt19937 rng(2001);
  for (int k = 0; k < unions; ++k) {
    const DiskList list = random_union(rng, 5 + k % 36);
    DiskUnionAxisReport report;
    const MedialGraph g = disk_union_axis(list, &report);
    const DiskAxisValidation v = validate_disk_union_axis(g, report);
    ++disk_axis.instances;
    disk_axis.points += v.nodes_checked + v.edges_checked;
    disk_axis.violations += v.failures.size();
    check_rate_pruning(g, extended_grassfire(g), disks.identity, disks.maximum);
  }
  std::vector<CheckRow> rows;
  for (const AxisCorpus* c : {&sampled, &exact, &builtin, &synthetic, &disks}) {
    char note[96];
    std::snprintf(note, sizeof note, "rate pruning %.2f s in all", c->identity.seconds);
    rows.push_back(row("ET = EDF - R by rate pruning (3.4.1)", c->name, c->identity, "count", note));
    rows.push_back(row("ET maximum = EMA (3.4.1)", c->name, c->maximum, "count", "last pruning quench vs EMA, exact"));
  }
  for (const AxisCorpus* c : {&sampled, &exact}) {
    rows.push_back(row("PR non-decreasing from the ends inward, away from junctions (3.4.2)", c->name,
                       c->residue.regular, "of PR max",
                       "inside edges and at degree-2 nodes, on paths from the leaves to the PR maximum"));
    rows.push_back(row("PR non-decreasing across junctions (3.4.2 says PR jumps there)", c->name,
                       c->residue.junction, "of PR max", "parent-branch limit vs child-branch limit at junctions"));
    char note[96];
    std::snprintf(note, sizeof note, "largest count of local maxima; PR computed in %.2f s in all",
                  c->residue.unique.seconds);
    rows.push_back(row("PR maximum unique (3.4.2, Ogniewicz and Ilg)", c->name, c->residue.unique, "maxima", note));
  }
  rows.push_back(row("Union of disks: >= 2 closest points, Betti numbers of the union (2.1.1)", disks.name,
                     disk_axis, "count", "definition-level validation of nodes and edge midpoints"));
  return rows;
}

}  // namespace

GF_REGISTER_CHECK("measures2d", run_measures2d);

}  // namespace grassfire::checks
