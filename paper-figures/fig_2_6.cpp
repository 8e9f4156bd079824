// fig_2_6.cpp -- Figure 2.6 (2.2.1, Chazal and Lieutier's lambda-medial axis, after
// Attali et al.): (a) a dumbbell's exact medial axis with an annotated medial point x, its
// medial circle (red, radius R = rho(x)) and the smallest circle enclosing its closest
// points (blue, radius r(x)), and the critical points of the distance function (hollow);
// (b) its lambda-medial axis {r(x) >= lambda} for lambda slightly above the weak feature
// size wfs, the smallest r at a critical point, which has lost the shape's topology.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fig_2_local_measures.h"
#include "figure_registry.h"

namespace grassfire::figures {
namespace {

constexpr double kLambdaOverWfs = 1.05;
const Point2 kTarget{-3.05, 0.75};  // where the annotated medial point x is looked for

struct Lobe {
  double cx, radius, attach_angle;  // the neck leaves the lobe at +-attach_angle (towards the other lobe)
  int vertices;
};

double rounded(double v) { return std::round(100 * v) / 100; }

// The lobe's vertices on its circle, counter-clockwise from one attachment of the neck
// round to the other, the neck side left open; `facing` is +1 when the neck is on the
// lobe's right.
std::vector<Point2> lobe_arc(const Lobe& l, int facing) {
  std::vector<Point2> pts;
  const double start = facing > 0 ? l.attach_angle : kPi + l.attach_angle;
  const double span = 2 * kPi - 2 * l.attach_angle;
  for (int k = 0; k < l.vertices; ++k) {
    const double a = start + span * k / (l.vertices - 1);
    pts.push_back({rounded(l.cx + l.radius * std::cos(a)), rounded(l.radius * std::sin(a))});
  }
  return pts;
}

// Two polygonal lobes joined by a neck pinched at (0, +-kPinch) between two reflex vertices.
constexpr double kPinch = 0.35;
Shape2 dumbbell() {
  const Lobe left{-3.0, 2.0, std::asin(0.4), 10}, right{2.6, 1.6, std::asin(0.5), 9};
  std::vector<Point2> outer{{0, -kPinch}};
  for (const Point2& p : lobe_arc(right, -1)) outer.push_back(p);
  outer.push_back({0, kPinch});
  for (const Point2& p : lobe_arc(left, 1)) outer.push_back(p);
  return polygon_shape("dumbbell", outer);
}

std::string number(double v) { return fixed(v, 3); }

// x, its closest points, the red medial circle and the blue smallest enclosing circle.
void draw_feature_size(SvgCanvas& c, const Medial2Frame& f, const EdgePoint& p) {
  const Point2d x = f(p.x), y1 = f(p.y1), y2 = f(p.y2);
  const Point2d m{0.5 * (y1[0] + y2[0]), 0.5 * (y1[1] + y2[1])};
  circle_outline(c, x, f.scale() * p.radius, kRed, 2.2);
  circle_outline(c, m, f.scale() * p.feature_size, kBlue, 2.2);
  c.polyline({y1, y2}, kBlue, 1.2, "5,4");
  c.polyline({x, y1}, kRed, 1.2, "5,4");
  c.polyline({x, y2}, kRed, 1.2, "5,4");
  labelled_dot(c, y1, kRed, "", {0, 0});
  labelled_dot(c, y2, kRed, "", {0, 0});
  labelled_dot(c, x, kBlack, "x", {-16, 6});
}

void draw_critical(SvgCanvas& c, const Medial2Frame& f, const CriticalPoints& cp, bool labels) {
  for (const CriticalPoint& q : cp.points) {
    c.circle(f(q.at), 7, kWhite, kBlack, 2.2);
    if (labels) boxed_text(c, {f(q.at)[0], f(q.at)[1] + 27}, "r = " + number(q.radius), 14);
  }
}

double weak_feature_size(const CriticalPoints& cp) {
  double wfs = std::numeric_limits<double>::infinity();
  for (const CriticalPoint& q : cp.points) wfs = std::min(wfs, q.radius);
  return wfs;
}

// The free ends of kept pieces nearest the critical point `at`, on its left and right.
std::pair<double, double> gap_around(const LocalMeasureShape& s, const ThresholdAxis& t, const Point2& at) {
  double left = -std::numeric_limits<double>::infinity(), right = -left;
  for (const AxisPiece& p : t.pieces)
    for (double end : {p.s0, p.s1}) {
      const double px = edge_point(s, p.edge, end).x.x;
      if (px < at.x) left = std::max(left, px);
      if (px > at.x) right = std::min(right, px);
    }
  return {left, right};
}

struct Dumbbell {
  LocalMeasureShape s;
  CriticalPoints crit;
  double wfs = 0, lambda = 0;
  ThresholdAxis t;
  EdgePoint x;
};

std::string caption(const Dumbbell& d) {
  const MedialGraph& g = d.s.graph();
  std::string crit;
  const CriticalPoint* weakest = nullptr;
  std::vector<CriticalPoint> sorted = d.crit.points;
  std::sort(sorted.begin(), sorted.end(),
            [](const CriticalPoint& a, const CriticalPoint& b) { return a.at.x < b.at.x; });
  auto shown = [](double v) { return std::fabs(v) < 5e-3 ? 0.0 : v; };  // no "-0.00"
  for (const CriticalPoint& q : sorted) {
    crit += printf_string("%s(%.2f, %.2f) with r = R = %.3f", crit.empty() ? "" : ", ", shown(q.at.x), shown(q.at.y),
                          q.radius);
    crit += (q.at_node ? " (a maximum, at a node)" : " (a saddle, inside an edge)");
    if (q.radius == d.wfs) weakest = &q;
  }
  const auto [left, right] = gap_around(d.s, d.t, weakest ? weakest->at : Point2{});
  return printf_string(
      "Fig. 2.6 redone (Chazal and Lieutier's lambda-medial axis, 2.2.1; the dissertation's picture is from Attali "
      "et al.). A hand-made dumbbell: two polygonal lobes (10 and 9 vertices, on circles of radius 2 and 1.6) "
      "joined by a neck pinched between the reflex vertices (0, +-%.2f); exact polygon medial axis (segment "
      "Voronoi diagram, %u nodes, %u edges, %u component, %llu cycles). (a) At the medial point x = (%.2f, %.2f) "
      "the medial circle (red) has radius rho(x) = R = %.3f, while the smallest circle enclosing the two closest "
      "boundary points (red dots; blue) has radius r(x) = %.3f = R sin(theta / 2), theta = %.1f degrees. Hollow: the "
      "%zu critical points of the distance "
      "function (x in the convex hull of its closest points), %s; decided by interval tests on the kernel's "
      "certified closest points (%u undecided). wfs = %.3f, the smallest r at a critical point. (b) The "
      "lambda-medial axis {r(x) >= lambda} for lambda = %.2f wfs = %.4f: %u components, %llu cycles (coloured "
      "apart), against %u for the shape. Look for the gap around the saddle, from x = %.3f to %.3f, "
      "where r(x) is below lambda (on the edge between the pinch vertices r = %.2f throughout), and for the lobes' "
      "branches cut where r = R sin(theta / 2) drops below lambda. r along edges is computed from the two "
      "closest points of each edge point in double precision, cuts by bisection (display values); node values "
      "are the kernel's certified ones (burn2/feature_size.h).",
      kPinch, g.node_count(), g.edge_count(), g.component_count(), static_cast<unsigned long long>(g.cycle_rank()),
      d.x.x.x, d.x.x.y, d.x.radius, d.x.feature_size, d.x.separation_angle * 180 / kPi, d.crit.points.size(),
      crit.c_str(), d.crit.undecided, d.wfs, kLambdaOverWfs, d.lambda, d.t.components,
      static_cast<unsigned long long>(d.t.cycles), g.component_count(), left, right, kPinch);
}

std::vector<FigureFile> fig_2_6(const FigureContext& ctx) {
  Edf2dOptions exact;
  exact.axis = AxisMethod::ExactPolygon;
  Dumbbell d{local_measure_shape(dumbbell(), exact), {}, 0, 0, {}, {}};
  d.crit = critical_points(d.s);
  d.wfs = weak_feature_size(d.crit);
  d.lambda = kLambdaOverWfs * d.wfs;
  d.t = threshold_axis(d.s, LocalMeasure::FeatureSize, d.lambda);
  d.x = nearest_edge_point(d.s, kTarget, LocalMeasure::FeatureSize, 0);
  const MedialGraph& g = d.s.graph();
  const double pw = 600, ph = 320;
  SvgCanvas c(2 * pw, ph + 80);
  const Medial2Frame fa = shape_panel(c, 0, 0, pw, ph, d.s.shape,
                                      "(a) medial axis: " + std::to_string(g.component_count()) + " component, " +
                                          std::to_string(g.cycle_rank()) + " cycles");
  draw_axis(c, fa, g, {0.15, 0.15, 0.15}, 2);
  draw_feature_size(c, fa, d.x);
  draw_critical(c, fa, d.crit, true);
  legend_row(c, 40, ph + 22, Mark::Line, kRed, "medial circle at x: \xcf\x81(x) = R = " + number(d.x.radius));
  legend_row(c, 40, ph + 46, Mark::Line, kBlue,
             "smallest circle around its closest points (red dots): r(x) = " + number(d.x.feature_size));
  legend_row(c, 40, ph + 70, Mark::Hollow, kBlack, "critical points (r = R there); wfs = " + number(d.wfs));
  const std::vector<Rgb> palette(component_palette().begin() + 2, component_palette().end());
  const Medial2Frame fb = shape_panel(c, pw, 0, pw, ph, d.s.shape,
                                      "(b) \xce\xbb-medial axis: " + std::to_string(d.t.components) + " components, " +
                                          std::to_string(d.t.cycles) + " cycles");
  draw_axis(c, fb, g, kDropped, 1.2);
  draw_threshold_axis(c, fb, d.s, d.t, palette, 3);
  draw_critical(c, fb, d.crit, false);
  legend_row(c, pw + 40, ph + 22, Mark::Line, palette[0],
             "r(x) \xe2\x89\xa5 \xce\xbb = " + fixed(kLambdaOverWfs, 2) + " wfs = " + fixed(d.lambda, 4) +
                 " (one colour per component)");
  legend_row(c, pw + 40, ph + 46, Mark::Line, kDropped, "r(x) < \xce\xbb");
  c.save(ctx.out_dir + "/fig2_6.svg");
  return {{"fig2_6.svg", caption(d)}};
}

GF_REGISTER_FIGURE("fig2_6", "Figure 2.6: the lambda-medial axis and the weak feature size", fig_2_6);

}  // namespace
}  // namespace grassfire::figures
