// fig_1_2.cpp -- Figure 1.2: the medial axis of a rectangle and of the same rectangle with
// a very small bump (the instability of the medial axis, 1.2).
#include <cstdio>

#include "figure_registry.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"

namespace grassfire::figures {
namespace {

const Rgb kAxis{0.1, 0.25, 0.8}, kBoundary{0.15, 0.15, 0.15}, kFill{0.92, 0.92, 0.92};

double axis_length(const MedialGraph& g) {
  double total = 0;
  for (const MedialEdge& e : g.edges()) total += e.length.mid();
  return total;
}

// One panel: the shape and its exact medial axis in one colour, with a label under it;
// `frame` is the shape whose bounding box fills the panel (the same for both: one scale).
void panel(SvgCanvas& c, double x, double y, double w, double h, const Shape2& frame, const Shape2& shape,
           const MedialGraph& g, const std::string& label) {
  const Medial2Frame f(frame, x + 20, y + 20, w - 40, h - 70);
  c.polygon_outline(shape_polygon(f, shape), kFill, kFill, 0);
  draw_boundary(c, f, shape, kBoundary, 1.8);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    std::vector<Point2d> pts;
    for (const Point2& p : g.geometry().polyline(g, e)) pts.push_back(f(p));
    c.polyline(pts, kAxis, 3);
  }
  c.text({x + w / 2, y + h - 22}, label, 17, "middle");
}

std::vector<FigureFile> fig_1_2(const FigureContext& ctx) {
  Edf2dOptions exact;
  exact.axis = AxisMethod::ExactPolygon;
  const Shape2 plain = builtin_shape("rectangle"), bump = builtin_shape("rectangle-bump");
  const Edf2dResult a = compute_edf2d(plain, exact), b = compute_edf2d(bump, exact);
  SvgCanvas c(1400, 380);
  char label[160];
  std::snprintf(label, sizeof label, "(a) rectangle: %u medial edges, length %.2f", a.graph->edge_count(),
                axis_length(*a.graph));
  panel(c, 0, 0, 700, 380, bump, plain, *a.graph, label);
  std::snprintf(label, sizeof label, "(b) with a 0.25-high bump: %u edges, length %.2f", b.graph->edge_count(),
                axis_length(*b.graph));
  panel(c, 700, 0, 700, 380, bump, bump, *b.graph, label);
  c.save(ctx.out_dir + "/fig1_2.svg");
  return {{"fig1_2.svg",
           "Fig. 1.2 redone: the exact medial axis (segment Voronoi diagram of the polygon) of a 10 x 4 rectangle (a) "
           "and of the same rectangle with a bump 0.25 high and 0.5 wide on its top side (b). Look for the long new "
           "branch that the tiny bump adds, reaching from the bump down to the central segment: the medial axis is "
           "unstable under small boundary changes."}};
}

GF_REGISTER_FIGURE("fig1_2", "Figure 1.2: instability of the medial axis", fig_1_2);

}  // namespace
}  // namespace grassfire::figures
