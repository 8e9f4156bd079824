// Pictures of pruned medial axes and the numbers of a pruning (render/svg_pruned2.h): the
// summary on a hand-built star and on blunt-sharp against hand-derived lengths and Betti
// numbers, and what draw_pruned2 puts into the SVG (one polyline per chain of kept edges,
// the faint axis, cut points, overlays, field colours, a tree shrunk to its EMA).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "burn2/extended_grassfire.h"
#include "render/svg_pruned2.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

// Centre c = 0 (R = 3) with leaves a = 1 (R = 1, edge 5), b = 2 (R = 0, edge 4) and d = 3
// (R = 2, edge 1), as in test_measures2d_pruning.cpp: EDF(c) = 4 (ignited by the fronts
// from d at 3 and b at 4), so ET(c) = 1. Along c-a, ET = 0.6 s at s from a up to the quench
// point s = 4, then 1 + 1.4 s' at s' from c; along c-b, ET = s / 4 from b; ET = 0 on c-d.
MedialGraph star() {
  return integer_graph({3, 1, 0, 2}, {{0, 1, 5}, {0, 2, 4}, {0, 3, 1}});
}

PruningThresholds thresholds(const mpq_class& et, const mpq_class& st, bool topology) {
  PruningThresholds t;
  t.erosion = et;
  t.tubularity = st;
  t.topology = topology;
  return t;
}

bool encloses(const Interval& x, double lo, double hi) {
  return x.lo >= lo && x.hi <= hi;
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
  return n;
}

std::string stroke(const Rgb& c) {
  return "stroke=\"" + to_svg_color(c) + "\"";
}

struct Pictured {
  Shape2 shape;
  Edf2dResult result;
};
Pictured exact(const std::string& name) {
  Pictured p{builtin_shape(name), {}};
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  p.result = compute_edf2d(p.shape, o);
  return p;
}

// Fig. 3.6 (e): T = 0.05 x 9 and S = 3/10 on blunt-sharp.
PrunedAxis fig_3_6e(const Pictured& p, bool topology) {
  return prune_axis(*p.result.graph, *p.result.burning, thresholds(mpq_class(9, 20), mpq_class(3, 10), topology));
}

std::string draw(const Pictured& p, const PrunedAxis& pruned, const Pruned2SvgOptions& o, std::size_t* pieces) {
  SvgCanvas c(480, 400);
  *pieces = draw_pruned2(c, 0, 0, 480, 400, p.shape, *p.result.graph, *p.result.burning, p.result.measures, pruned, o);
  return c.str();
}

}  // namespace

TEST_CASE("pruning summary of a hand-built star", "[svg_pruned2]") {
  const MedialGraph g = star();
  const GrassfireResult burn = extended_grassfire(g);
  const PruningSummary whole = pruning_summary(g, prune_axis(g, burn, thresholds(0, 0, false)));
  CHECK(whole.axis_length.contains(10));
  CHECK(whole.kept_length.contains(10));
  CHECK(whole.kept_fraction() == Approx(1));
  CHECK(whole.axis_edges == 3);
  CHECK(whole.axis_nodes == 4);
  CHECK(whole.kept_edges == 3);
  CHECK(whole.kept_nodes == 4);
  CHECK(whole.cut_points == 0);
  CHECK(whole.kept_components == 1);
  CHECK(whole.kept_cycles == 0);

  // T = 1/2: c-a kept from s = 5/6 (0.6 s = 1/2), c-b from s = 2 (s / 4 = 1/2), c-d gone.
  for (bool topology : {false, true}) {
    const PruningSummary half = pruning_summary(g, prune_axis(g, burn, thresholds(mpq_class(1, 2), 0, topology)));
    CHECK(half.kept_length.contains(37.0 / 6));
    CHECK(half.kept_length.hi - half.kept_length.lo < 1e-12);
    CHECK(half.kept_edges == 2);
    CHECK(half.kept_nodes == 3);
    CHECK(half.cut_points == 2);
    CHECK(half.kept_components == 1);
    CHECK(half.kept_fraction() == Approx(37.0 / 60));
  }
  // T = 3/2: c fails (ET 1); only the middle of c-a passes, from s = 5/2 to s' = 5/14.
  const PruningSummary high = pruning_summary(g, prune_axis(g, burn, thresholds(mpq_class(3, 2), 0, false)));
  CHECK(high.kept_length.contains(15.0 / 7));
  CHECK(high.kept_edges == 1);
  CHECK(high.kept_nodes == 2);
  CHECK(high.cut_points == 2);
  // Nothing passes: no nodes, no components, fraction 0.
  const PruningSummary none = pruning_summary(g, prune_axis(g, burn, thresholds(100, 0, false)));
  CHECK(none.kept_nodes == 0);
  CHECK(none.kept_components == 0);
  CHECK(none.kept_fraction() == 0);
}

TEST_CASE("pruning summary of blunt-sharp: hand-derived kept length, topology kept", "[svg_pruned2]") {
  const Pictured p = exact("blunt-sharp");
  // Only the centre line y = 2 survives: from (2, 2), where EDF = 2 sqrt(2) and R = 2, ST
  // reaches 3/10 after 20/7 - 2 sqrt(2), to the ET cut 7.75 + 0.4 sqrt(2) in the thin
  // rectangle; the arcs round the bump's junction (3, 2.005) add about 1.3e-4.
  const double straight = 7.75 + 0.4 * std::sqrt(2.0) - (2 + 20.0 / 7 - 2 * std::sqrt(2.0));
  for (bool topology : {false, true}) {
    const PruningSummary s = pruning_summary(*p.result.graph, fig_3_6e(p, topology));
    CHECK(encloses(s.kept_length, straight, straight + 2e-4));
    CHECK(s.kept_components == 1);
    CHECK(s.kept_cycles == 0);
    CHECK(s.cut_points == 2);
    CHECK(s.axis_components == 1);
    CHECK(s.axis_cycles == 0);
  }
  // ST >= 3/10 alone also keeps the tip of the bump (ST 1 - 0.8 / sqrt(1.64) = 0.375 there):
  // two components, joined again by the topology-preserving variant.
  const MedialGraph& g = *p.result.graph;
  const PruningSummary plain = pruning_summary(g, prune_axis(g, *p.result.burning, thresholds(0, mpq_class(3, 10), false)));
  const PruningSummary kept = pruning_summary(g, prune_axis(g, *p.result.burning, thresholds(0, mpq_class(3, 10), true)));
  CHECK(plain.kept_components == 2);
  CHECK(kept.kept_components == 1);
  CHECK(kept.kept_length.lo > plain.kept_length.hi);
}

TEST_CASE("topology-preserving pruning of the hole keeps its cycle in the summary", "[svg_pruned2]") {
  const Shape2 hole = builtin_shape("hole");
  const Edf2dResult r = compute_edf2d(hole);
  const PrunedAxis p = prune_axis(*r.graph, *r.burning, thresholds(mpq_class(3, 10), mpq_class(1, 2), true));
  const PruningSummary s = pruning_summary(*r.graph, p);
  CHECK(s.axis_cycles == 1);
  CHECK(s.kept_cycles == 1);
  CHECK(s.kept_components == 1);
  CHECK(s.kept_fraction() > 0);
  CHECK(s.kept_fraction() < 1);
}

TEST_CASE("draw_pruned2: one polyline per kept edge over the faint axis, cut points, texts", "[svg_pruned2]") {
  const Pictured p = exact("blunt-sharp");
  const PrunedAxis pruned = fig_3_6e(p, false);
  Pruned2SvgOptions o;
  o.title = "(e) title";
  o.note = "a note";
  std::size_t pieces = 0;
  const std::string svg = draw(p, pruned, o, &pieces);
  // The 6 kept edges form one path (their inner nodes have degree 2 in the pruned axis);
  // the 16 axis edges form 10 chains, joined through the 6 nodes of degree 2.
  REQUIRE(pruned.edges.size() == 6);
  CHECK(pieces == 1);
  CHECK(count(svg, stroke(o.colour)) == 1);
  CHECK(count(svg, stroke({0.62, 0.62, 0.62})) == 10);
  CHECK(count(svg, "<circle") == pruned.cut_points);
  CHECK(count(svg, ">(e) title</text>") == 1);
  CHECK(count(svg, ">a note</text>") == 1);

  o.show_axis = false;
  o.mark_cuts = false;
  const std::string bare = draw(p, pruned, o, &pieces);
  CHECK(count(bare, stroke({0.62, 0.62, 0.62})) == 0);
  CHECK(count(bare, "<circle") == 0);

  o.max_piece = 0;
  CHECK_THROWS_AS(draw(p, pruned, o, &pieces), std::invalid_argument);
}

TEST_CASE("draw_pruned2: field colours, overlays and a tree shrunk to its EMA", "[svg_pruned2]") {
  const Pictured p = exact("blunt-sharp");
  const PrunedAxis kept = fig_3_6e(p, true);
  Pruned2SvgOptions o;
  o.show_axis = false;
  o.colour_by_field = true;
  o.range_lo = 0, o.range_hi = 1e9;  // every ET on the axis maps to the low end of the scale
  std::size_t pieces = 0;
  const std::string coloured = draw(p, kept, o, &pieces);
  CHECK(pieces > kept.edges.size());  // the 6 edges are long: several 4 px pieces each
  CHECK(count(coloured, stroke(heat_color(0))) == pieces);
  CHECK(count(coloured, stroke(o.colour)) == 0);

  // Plain pruning of ST alone drawn over the topology-preserving result.
  const MedialGraph& g = *p.result.graph;
  const PrunedAxis topo = prune_axis(g, *p.result.burning, thresholds(0, mpq_class(3, 10), true));
  const PrunedAxis plain = prune_axis(g, *p.result.burning, thresholds(0, mpq_class(3, 10), false));
  Pruned2SvgOptions layered;
  layered.colour = {0.95, 0.45, 0};
  layered.overlay = &plain;
  // The topology-preserving result joins the bump's tip to the centre line at the bump's
  // junction: 3 chains; plain pruning has 2 components, one chain each.
  const std::string both = draw(p, topo, layered, &pieces);
  CHECK(pieces == 3 + 2);
  CHECK(count(both, stroke(layered.colour)) == 3);
  CHECK(count(both, stroke(layered.overlay_colour)) == 2);

  // A rectangle pruned with a threshold nothing passes keeps only its EMA point: one dot.
  const Pictured rect = exact("rectangle");
  const PrunedAxis ema =
      prune_axis(*rect.result.graph, *rect.result.burning, thresholds(100, 0, true));
  REQUIRE(ema.nodes.size() == 1);
  const std::string dot = draw(rect, ema, Pruned2SvgOptions{}, &pieces);
  CHECK(pieces == 0);
  CHECK(count(dot, "<circle") == 1);
  CHECK(count(dot, "fill=\"" + to_svg_color(Pruned2SvgOptions{}.colour) + "\"") == 1);
}

TEST_CASE("pruned2_panel_height fits the shape, the title and the note", "[svg_pruned2]") {
  const Shape2 s = builtin_shape("blunt-sharp");  // 9 x 4.25
  Pruned2SvgOptions o;
  const double plot = (480 - 24) * 4.25 / 9;
  CHECK(pruned2_panel_height(s, o, 480) == Approx(plot + 24));
  o.title = "t";
  o.note = "n";
  CHECK(pruned2_panel_height(s, o, 480) == Approx(plot + 24 + 30 + 28));
}
