// fig_3_2.cpp -- Figure 3.2: intermediate states of the extended grassfire (3.3.1) on the
// exact medial axis of the `branches` shape, from burn2/burning_state.h.
#include <cmath>
#include <cstdio>

#include "burn2/burning_state.h"
#include "figure_registry.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"

namespace grassfire::figures {
namespace {

const Rgb kBurnt{0.68, 0.68, 0.68}, kUnburnt{0, 0, 0}, kFront{1.0, 0.85, 0.0}, kFill{0.93, 0.93, 0.93};
const Rgb kIgnite{0.9, 0.1, 0.1}, kAnnihilate{0.1, 0.3, 0.95}, kQuench{0.1, 0.7, 0.2}, kBoundary{0.4, 0.4, 0.4};
constexpr double kAxisWidth = 3.2;

Rgb event_colour(BurnEventType t) {
  return t == BurnEventType::Ignite ? kIgnite : t == BurnEventType::Annihilate ? kAnnihilate : kQuench;
}

void square(SvgCanvas& c, const Point2d& p, double half, const Rgb& colour) {
  c.polygon_outline(
      {{p[0] - half, p[1] - half}, {p[0] + half, p[1] - half}, {p[0] + half, p[1] + half}, {p[0] - half, p[1] + half}},
      colour, {0, 0, 0}, 1);
}

// The edge from arc length a to b (measured from its end `from`), in canvas coordinates.
std::vector<Point2d> stretch(const Medial2Frame& f, const MedialGraph& g, std::uint32_t e, std::uint32_t from, double a,
                             double b) {
  const double w = g.edge(e).length.mid();
  const int n = g.edge(e).kind == EdgeKind::ParabolicArc ? 12 : 1;
  std::vector<double> s;
  for (int i = 0; i <= n; ++i) {
    const double si = a + (b - a) * i / n;
    s.push_back(from == g.edge(e).u ? si : w - si);
  }
  return edge_points(f, g, e, s);
}

void draw_axis(SvgCanvas& c, const Medial2Frame& f, const MedialGraph& g, const BurningState& s) {
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const MedialEdge& edge = g.edge(e);
    const EdgeBurning& b = s.edges[e];
    const double w = edge.length.mid();
    if (b.whole) {
      c.polyline(stretch(f, g, e, edge.u, 0, w), kBurnt, kAxisWidth);
      continue;
    }
    const double bu = b.from_u.mid(), bv = b.from_v.mid();
    c.polyline(stretch(f, g, e, edge.u, bu, w - bv), kUnburnt, kAxisWidth);
    if (bu > 0) c.polyline(stretch(f, g, e, edge.u, 0, bu), kBurnt, kAxisWidth);
    if (bv > 0) c.polyline(stretch(f, g, e, edge.v, 0, bv), kBurnt, kAxisWidth);
  }
}

// A yellow dot on the front and an arrow pointing along the edge, away from `from`.
void draw_front(SvgCanvas& c, const Medial2Frame& f, const MedialGraph& g, const FireFront& front) {
  const double w = g.edge(front.edge).length.mid(), s = front.offset.mid();
  const MedialGeometry& geo = g.geometry();
  const Point2d p = f(geo.point_along(g, front.edge, front.from, s));
  const double step = std::min(w - s, 0.25 * w) > 0 ? std::min(w - s, 0.25 * w) : 1e-3;
  const Point2d q = f(geo.point_along(g, front.edge, front.from, s + step));
  double dx = q[0] - p[0], dy = q[1] - p[1];
  const double len = std::hypot(dx, dy);
  if (len > 0) {
    dx /= len, dy /= len;
    const Point2d tip{p[0] + 22 * dx, p[1] + 22 * dy}, base{p[0] + 12 * dx, p[1] + 12 * dy};
    c.polyline({p, base}, {0, 0, 0}, 2.2);
    c.polygon_outline({tip, {base[0] - 5 * dy, base[1] + 5 * dx}, {base[0] + 5 * dy, base[1] - 5 * dx}}, {0, 0, 0},
                      {0, 0, 0}, 0.5);
  }
  c.circle(p, 5.5, kFront, {0, 0, 0}, 1.2);
}

void draw_state(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape, const MedialGraph& g,
                const GrassfireResult& r, double t) {
  const BurningState s = burning_state_at(g, r, t);
  const Medial2Frame f(shape, x + 14, y + 34, w - 28, h - 48);
  c.polygon_outline(shape_polygon(f, shape), kFill, kFill, 0);
  draw_boundary(c, f, shape, kBoundary, 1.2);
  draw_axis(c, f, g, s);
  for (std::size_t i : s.events) {
    const BurnEvent& ev = r.events[i];
    square(c, f(position_of(g, ev.place)), 5.5, event_colour(ev.type));
  }
  for (const FireFront& front : s.fronts) draw_front(c, f, g, front);
  char label[96];
  std::snprintf(label, sizeof label, "t = %.2f: %zu fronts, %zu events", t, s.fronts.size(), s.events.size());
  c.text({x + w / 2, y + 24}, label, 17, "middle");
}

void legend(SvgCanvas& c, double x, double y) {
  c.polyline({{x, y}, {x + 30, y}}, kUnburnt, kAxisWidth);
  c.text({x + 38, y + 5}, "unburnt", 15);
  c.polyline({{x + 120, y}, {x + 150, y}}, kBurnt, kAxisWidth);
  c.text({x + 158, y + 5}, "burnt", 15);
  c.circle({x + 228, y}, 5.5, kFront, {0, 0, 0}, 1.2);
  c.text({x + 240, y + 5}, "fire front (arrow: burning direction)", 15);
  const char* names[3] = {"ignited", "annihilated", "quenched"};
  const BurnEventType types[3] = {BurnEventType::Ignite, BurnEventType::Annihilate, BurnEventType::Quench};
  for (int i = 0; i < 3; ++i) {
    square(c, {x + 540 + 140.0 * i, y}, 5.5, event_colour(types[i]));
    c.text({x + 552 + 140.0 * i, y + 5}, names[i], 15);
  }
}

std::vector<FigureFile> fig_3_2(const FigureContext& ctx) {
  Edf2dOptions exact;
  exact.axis = AxisMethod::ExactPolygon;
  const Shape2 shape = builtin_shape("branches");
  const Edf2dResult res = compute_edf2d(shape, exact);
  const MedialGraph& g = *res.graph;
  const GrassfireResult& r = *res.burning;
  const double end = r.ema.at(0).edf.mid();
  const double fractions[6] = {0.0, 0.15, 0.3, 0.5, 0.75, 1.0};
  const double pw = 560, ph = 460;
  SvgCanvas c(3 * pw, 2 * ph + 50);
  for (int i = 0; i < 6; ++i) draw_state(c, pw * (i % 3), ph * (i / 3), pw, ph, shape, g, r, fractions[i] * end);
  legend(c, 150, 2 * ph + 25);
  c.save(ctx.out_dir + "/fig3_2.svg");
  char caption[600];
  std::snprintf(caption, sizeof caption,
                "Fig. 3.2 redone: the extended grassfire on the exact medial axis of the built-in shape 'branches' "
                "(%u nodes, %u edges) at t = 0, 0.15, 0.3, 0.5, 0.75 and 1 times the EDF of the EMA (%.3f). Burnt "
                "parts grey, unburnt black, fronts yellow with arrows for the burning direction; red, blue and green "
                "squares where fronts ignited (the leaves, at t = R = 0 for the polygon's convex corners), "
                "annihilated at junctions, and quenched. Look for fronts stopping at junctions that still have two "
                "unburnt branches, and for the last quench (the EMA, green) in the body.",
                g.node_count(), g.edge_count(), end);
  return {{"fig3_2.svg", caption}};
}

GF_REGISTER_FIGURE("fig3_2", "Figure 3.2: intermediate states of the extended grassfire", fig_3_2);

}  // namespace
}  // namespace grassfire::figures
