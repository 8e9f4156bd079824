// fig_3_6.cpp -- Figure 3.6: ET and ST over the medial axis of a shape with blunt and sharp
// protrusions and a small bump (the built-in `blunt-sharp`), and pruning by (c) a low ET
// threshold, (d) a high one, (e) the low one combined with an ST threshold (3.5.1).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "fig_3_pruning.h"
#include "figure_registry.h"
#include "io/load_shape.h"

namespace grassfire::figures {
namespace {

constexpr double kLowEt = 0.05, kHighEt = 0.15;  // fractions of the shape's dimension
constexpr double kPanelW = 480;

Chapter3Shape exact_shape(const std::string& name) {
  Chapter3Shape s;
  s.shape = load_shape(name);
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  s.result = compute_edf2d(s.shape, o);
  return s;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// (a) ET and (b) ST on the axis, centred in the top row.
void measure_row(SvgCanvas& c, double y, double h, const Chapter3Shape& s) {
  const char* titles[] = {"(a) ET = EDF - R", "(b) ST = 1 - R / EDF"};
  const Medial2Field fields[] = {Medial2Field::Et, Medial2Field::St};
  for (int i = 0; i < 2; ++i) {
    Medial2SvgOptions o;
    o.field = fields[i];
    o.title = titles[i];
    if (fields[i] == Medial2Field::St) o.range_lo = 0, o.range_hi = 1;  // ST's whole range [0, 1]
    draw_medial2(c, kPanelW * (0.5 + i), y, kPanelW, h, s.shape, *s.result.graph, *s.result.burning,
                 s.result.measures, o);
  }
}

// The right end of the kept axis: where the thin rectangle's centre axis is cut.
double kept_tip(const PrunedShape& p) {
  double x = -INFINITY;
  for (const PrunedNode& n : p.axis.nodes) x = std::max(x, n.position.x);
  return x;
}

// p = {low ET, high ET, low ET and ST, ST alone}.
std::string caption(const Chapter3Shape& s, const std::vector<const PrunedShape*>& p) {
  const PruningSummary& a = p[0]->summary;
  const double size = shape_dimension(s.shape);
  const double t_low = p[0]->thresholds.erosion.get_d(), t_high = p[1]->thresholds.erosion.get_d();
  return "Fig. 3.6 redone on the built-in 'blunt-sharp' (a 6 x 4 rectangle with blunt right-angled corners, a 3 x "
         "0.8 rectangle attached to its right side as a sharp protrusion, a bump 0.25 high on its top side as noise), "
         "with its exact medial axis (segment Voronoi diagram: " +
         std::to_string(a.axis_edges) + " edges, length " + number(a.axis_length.mid()) +
         "). (a) ET and (b) ST along the axis (blue low, red high). Look for ET treating the diagonal branches into "
         "the big rectangle's corners like the centre axis of the thin rectangle, while ST stays at 1 - 1/sqrt(2) = "
         "0.293 (or just below, on the arcs near the thin rectangle) all along each corner branch and rises far "
         "higher along the thin rectangle. ST is also high on the tip of the bump (0.375, its apex half-angle being "
         "atan(0.8)); ST >= 0.3 alone: " +
         kept_summary(p[3]->summary, false) +
         ", the bump's tip among them. Pruning (thick black: kept; thin grey: the whole axis; white dots: cut "
         "points, where a threshold is crossed inside an edge). The shape's dimension is the larger side of its "
         "bounding box, " +
         number(size) + ". (c) ET >= 0.05 x " + number(size) + " = " + number(t_low) + ": " +
         kept_summary(p[0]->summary, false) +
         "; the bump's branch is gone, the diagonal branches stay. (d) ET >= " + number(kHighEt) + " x " +
         number(size) + " = " + number(t_high) + ": " + kept_summary(p[1]->summary, false) +
         "; the diagonals are gone, and the thin rectangle's axis now ends at x = " + number(kept_tip(*p[1])) +
         " instead of " + number(kept_tip(*p[0])) + " (the rectangle spans x = 6 to 9). (e) ET >= " + number(t_low) +
         " and ST >= 0.3 (just above 1 - 1/sqrt(2), which removes the corner branches exactly): " +
         kept_summary(p[2]->summary, false) + "; the diagonals are gone and the thin rectangle's axis ends at x = " +
         number(kept_tip(*p[2])) + ", as in (c). (c)-(e) are plain pruning: every passing point is kept, the topology is not enforced (Fig. 3.7 does that).";
}

std::vector<FigureFile> fig_3_6(const FigureContext& ctx) {
  const Chapter3Shape s = exact_shape("blunt-sharp");
  const PrunedShape low = prune_shape(s, relative_thresholds(s.shape, kLowEt, 0, false));
  const PrunedShape high = prune_shape(s, relative_thresholds(s.shape, kHighEt, 0, false));
  const PrunedShape both = prune_shape(s, relative_thresholds(s.shape, kLowEt, tubularity_threshold(), false));
  const double t_low = low.thresholds.erosion.get_d(), t_high = high.thresholds.erosion.get_d();

  Medial2SvgOptions mo;
  mo.title = "title";
  const double top_h = medial2_panel_height(s.shape, mo, kPanelW);
  Pruned2SvgOptions po;
  po.title = "title";
  po.note = "note";
  const double bottom_h = pruned2_panel_height(s.shape, po, kPanelW);
  SvgCanvas c(3 * kPanelW, top_h + bottom_h);
  measure_row(c, 0, top_h, s);
  const PrunedShape* panels[] = {&low, &high, &both};
  const std::string ge = " \xe2\x89\xa5 ";  // the sign >=
  const std::string titles[] = {"(c) ET" + ge + number(t_low), "(d) ET" + ge + number(t_high),
                                "(e) ET" + ge + number(t_low) + " and ST" + ge + "0.3"};
  for (int i = 0; i < 3; ++i) {
    po.title = titles[i];
    po.note = kept_summary(panels[i]->summary, false);
    pruned_panel(c, kPanelW * i, top_h, kPanelW, bottom_h, s, *panels[i], po);
  }
  c.save(ctx.out_dir + "/fig3_6.svg");

  const PrunedShape st_only = prune_shape(s, relative_thresholds(s.shape, 0, tubularity_threshold(), false));
  return {{"fig3_6.svg", caption(s, {&low, &high, &both, &st_only})}};
}

GF_REGISTER_FIGURE("fig3_6", "Figure 3.6: ET and ST, and pruning by ET and ST thresholds", fig_3_6);

}  // namespace
}  // namespace grassfire::figures
