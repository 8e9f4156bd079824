// fig_2_4.cpp -- Figure 2.4 (2.2.1, after Sud et al.): (a) the separation angle theta(x)
// at a medial point x, between the rays to its two closest boundary points y1, y2, on a
// shape whose medial axis is coloured by theta; (b) the same axis pruned naively to the
// points with theta >= pi/2; (c) a rectangle with a small blunt bump whose axis, pruned
// naively to theta >= pi/3, falls apart. Measures along edges: fig_2_local_measures.h.
#include <algorithm>
#include <cmath>
#include <string>

#include "fig_2_local_measures.h"
#include "figure_registry.h"
#include "io/load_shape.h"

namespace grassfire::figures {
namespace {

const char* kShapeA = "/shapes2d/shoe-1.json";
constexpr std::size_t kSamplesA = 1500;
const Point2 kTargetA{0.405, 0.18};  // where the annotated medial point x is looked for
constexpr double kBumpRadius = 0.8, kRectangleHeight = 4;
constexpr double kTinyShare = 0.02;  // components shorter than this share of the kept axis get a ring

// The rectangle 10 x 4 with a half-disc bump (a half 8-gon, vertices rounded to 3
// decimals) on the middle of its top side.
Shape2 bump_shape() {
  std::vector<Point2> outer{{0, 0}, {10, 0}, {10, kRectangleHeight}};
  constexpr int kSides = 8;
  auto rounded = [](double v) { return std::round(1000 * v) / 1000; };
  for (int k = 0; k <= kSides; ++k) {
    const double a = kPi * k / kSides;
    outer.push_back({rounded(5 + kBumpRadius * std::cos(a)), rounded(kRectangleHeight + kBumpRadius * std::sin(a))});
  }
  outer.push_back({0, kRectangleHeight});
  return polygon_shape("rectangle with a blunt bump", outer);
}

std::string degrees(double radians) { return fixed(radians * 180 / kPi, 1) + "\xc2\xb0"; }

// The rays x -> y1, x -> y2, the angle's arc and the labels.
void draw_separation_angle(SvgCanvas& c, const Medial2Frame& f, const EdgePoint& p) {
  const Point2d x = f(p.x), y1 = f(p.y1), y2 = f(p.y2);
  c.polyline({x, y1}, kBlack, 2);
  c.polyline({x, y2}, kBlack, 2);
  const double a1 = std::atan2(y1[1] - x[1], y1[0] - x[0]), a2 = std::atan2(y2[1] - x[1], y2[0] - x[0]);
  const double delta = std::remainder(a2 - a1, 2 * kPi), arc = 0.3 * f.scale() * p.radius;
  std::vector<Point2d> pts;
  for (int i = 0; i <= 40; ++i) {
    const double a = a1 + delta * i / 40;
    pts.push_back({x[0] + arc * std::cos(a), x[1] + arc * std::sin(a)});
  }
  c.polyline(pts, kBlack, 1.6);
  const double bisector = a1 + 0.5 * delta, label_at = arc + 24;
  boxed_text(c, {x[0] + label_at * std::cos(bisector), x[1] + label_at * std::sin(bisector) + 6}, "\xce\xb8(x)", 17);
  auto offset = [&](const Point2d& y) {  // the label beyond the point, away from x
    const double d = std::hypot(y[0] - x[0], y[1] - x[1]);
    return Point2d{18 * (y[0] - x[0]) / d, 18 * (y[1] - x[1]) / d + 6};
  };
  labelled_dot(c, y1, kRed, "y\xe2\x82\x81", offset(y1));
  labelled_dot(c, y2, kRed, "y\xe2\x82\x82", offset(y2));
  labelled_dot(c, x, kBlack, "x", {-16 * std::cos(bisector), -16 * std::sin(bisector) + 6});
}

// Kept length per component of a threshold axis.
std::vector<double> component_lengths(const ThresholdAxis& t) {
  std::vector<double> len(t.components, 0.0);
  for (std::size_t i = 0; i < t.pieces.size(); ++i) len[t.piece_component[i]] += t.pieces[i].s1 - t.pieces[i].s0;
  return len;
}

double axis_length(const MedialGraph& g) {
  double total = 0;
  for (const MedialEdge& e : g.edges()) total += e.length.mid();
  return total;
}

// A ring around every component too short to be seen, at its first piece or node.
void ring_tiny_components(SvgCanvas& c, const Medial2Frame& f, const LocalMeasureShape& s, const ThresholdAxis& t) {
  const std::vector<double> len = component_lengths(t);
  const double total = std::max(1e-300, *std::max_element(len.begin(), len.end()));
  std::vector<bool> done(t.components, false);
  auto ring = [&](std::uint32_t comp, const Point2& at) {
    if (done[comp] || len[comp] >= kTinyShare * total) return;
    done[comp] = true;
    circle_outline(c, f(at), 9, component_palette()[comp % component_palette().size()], 1.6);
  };
  for (std::size_t i = 0; i < t.pieces.size(); ++i)
    ring(t.piece_component[i], edge_point(s, t.pieces[i].edge, t.pieces[i].s0).x);
  for (std::uint32_t v = 0; v < s.graph().node_count(); ++v)
    if (t.node_kept[v]) ring(t.node_component[v], s.graph().node(v).position);
}

// "the largest 0.677 long (91% of the kept length, theta up to 179.9°), then 0.0675 (up to
// 178.8°), ...": components by decreasing length, with the largest theta met on each.
std::string describe_components(const LocalMeasureShape& s, const ThresholdAxis& t) {
  const std::vector<double> len = component_lengths(t);
  std::vector<double> top(t.components, 0.0);
  for (std::size_t i = 0; i < t.pieces.size(); ++i)
    for (int k = 0; k <= 8; ++k) {
      const AxisPiece& q = t.pieces[i];
      const double th = edge_point(s, q.edge, q.s0 + (q.s1 - q.s0) * k / 8).separation_angle;
      top[t.piece_component[i]] = std::max(top[t.piece_component[i]], th);
    }
  std::vector<std::uint32_t> order(t.components);
  for (std::uint32_t k = 0; k < t.components; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return len[a] > len[b]; });
  double total = 0;
  for (double l : len) total += l;
  std::string out;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::uint32_t k = order[i];
    out += i == 0 ? "the largest " + fixed(len[k], 3) + " long (" + fixed(100 * len[k] / total, 1) +
                        "% of the kept length, theta up to " + degrees(top[k]) + ")"
                  : (i == 1 ? ", then " : ", ") + fixed(len[k], 4) + " (up to " + degrees(top[k]) + ")";
  }
  return out;
}

struct Panels {
  LocalMeasureShape a, bump;
  EdgePoint x;
  ThresholdAxis half, third;
};

// The pruned stretch of (c): from the junction node of the bump's branch (the largest R)
// up to the lowest point of the other components.
std::pair<double, double> pruned_stretch(const LocalMeasureShape& s, const ThresholdAxis& t) {
  const MedialGraph& g = s.graph();
  std::uint32_t junction = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (g.node(v).radius.mid() > g.node(junction).radius.mid()) junction = v;
  double lowest = kRectangleHeight;
  for (std::size_t i = 0; i < t.pieces.size(); ++i)
    if (t.piece_component[i] != t.node_component[junction])
      lowest = std::min(lowest, edge_point(s, t.pieces[i].edge, t.pieces[i].s0).x.y);
  return {g.node(junction).position.y, lowest};
}

std::string caption(const Panels& p) {
  const MedialGraph& g = p.a.graph();
  double kept = 0;
  for (double l : component_lengths(p.half)) kept += l;
  const std::string head = printf_string(
      "Fig. 2.4 redone (Sud et al.'s separation angle, 2.2.1). (a) shoe-1 (2D Shape Structure dataset) and "
      "its medial axis from %zu boundary samples (Voronoi, %u nodes, %u edges) coloured by the separation "
      "angle theta, blue 0 to red pi; at the medial point x = (%.3f, %.3f), R = %.4f, the rays to its "
      "closest boundary points y1, y2 make theta(x) = %s. (b) The naive pruning to theta >= pi/2 keeps "
      "%.1f%% of the axis length, in %u components: ",
      kSamplesA, g.node_count(), g.edge_count(), p.x.x.x, p.x.x.y, p.x.radius, degrees(p.x.separation_angle).c_str(),
      100 * kept / axis_length(g), p.half.components);
  const auto [from, to] = pruned_stretch(p.bump, p.third);
  const std::string tail = printf_string(
      " (rings mark the short ones). Look for the branches into the polygon's many blunt vertices (blue "
      "in (a)) vanishing together with the stretch where the shoe widens at the toe (green in (a)), the "
      "sharp spike on top keeping a branch of its own, cut off from the rest, and "
      "short specks. (c) A 10 x 4 rectangle with a half-disc bump of radius %.1f (a half 8-gon) on its "
      "top side, exact polygon medial axis (segment Voronoi diagram, %u nodes, %u edges, %u component). "
      "Pruned naively to theta >= pi/3 it has %u components (coloured "
      "apart): the rectangle's axis (theta = pi on the middle segment, pi/2 on the corner branches), and "
      "the bump's centre with the top of the branch below it. On that branch the closest points are the "
      "bump's two foot corners, theta = 2 atan(%.1f / (4 - y)), below pi/3 under y = 4 - %.1f sqrt 3 = "
      "%.3f: the pruned stretch (grey) runs from the junction node at y = %.3f (the largest R) up to y = "
      "%.3f. As 2.2.1 "
      "says, the bump's small feature gets separation angles as large as the rectangle's big ones. Theta "
      "along edges is computed from the two closest points of each edge point in double precision and "
      "the cuts are found by bisection (display values); node values are the kernel's certified ones "
      "(burn2/feature_size.h).",
      kBumpRadius, p.bump.graph().node_count(), p.bump.graph().edge_count(), p.bump.graph().component_count(),
      p.third.components, kBumpRadius, kBumpRadius, kRectangleHeight - kBumpRadius * std::sqrt(3.0), from, to);
  return head + describe_components(p.a, p.half) + tail;
}

constexpr double kPanelW = 600, kRowA = 290, kBarStrip = 50, kRowC = 330;

void panels_ab(SvgCanvas& c, const Panels& p) {
  const Medial2Frame fa = shape_panel(c, 0, 0, kPanelW, kRowA, p.a.shape,
                                      "(a) the separation angle: \xce\xb8(x) = " + degrees(p.x.separation_angle));
  draw_measure_axis(c, fa, p.a, LocalMeasure::SeparationAngle, 0, kPi, 2.2);
  draw_separation_angle(c, fa, p.x);
  heat_bar(c, 60, kRowA, kPanelW - 120, 0, kPi, "\xce\xb8", {0, kPi / 4, kPi / 2, 3 * kPi / 4, kPi},
           {"0", "\xcf\x80/4", "\xcf\x80/2", "3\xcf\x80/4", "\xcf\x80"});
  const Medial2Frame fb =
      shape_panel(c, kPanelW, 0, kPanelW, kRowA, p.a.shape,
                  "(b) \xce\xb8 \xe2\x89\xa5 \xcf\x80/2: " + std::to_string(p.half.components) + " components");
  draw_axis(c, fb, p.a.graph(), kDropped, 1.2);
  draw_threshold_axis(c, fb, p.a, p.half, component_palette(), 2.6);
  ring_tiny_components(c, fb, p.a, p.half);
}

// (c) below (a), with the legend of the pruned pictures on its right.
void panel_c(SvgCanvas& c, const Panels& p, double y) {
  const Medial2Frame fc =
      shape_panel(c, 0, y, kPanelW, kRowC, p.bump.shape,
                  "(c) \xce\xb8 \xe2\x89\xa5 \xcf\x80/3: " + std::to_string(p.bump.graph().component_count()) +
                      " \xe2\x86\x92 " + std::to_string(p.third.components) + " components");
  draw_axis(c, fc, p.bump.graph(), kDropped, 1.4);
  draw_threshold_axis(c, fc, p.bump, p.third, component_palette(), 3);
  ring_tiny_components(c, fc, p.bump, p.third);
  const auto [from, to] = pruned_stretch(p.bump, p.third);
  const Point2d label = fc({5.0, 0.5 * (from + to)});
  c.polyline({{label[0] + 6, label[1]}, {label[0] + 40, label[1]}}, kBlack, 1);
  boxed_text(c, {label[0] + 82, label[1] + 5}, "\xce\xb8 < \xcf\x80/3", 16);
  const double lx = kPanelW + 40, ly = y + 90;
  c.text({lx, ly - 36}, "(b), (c): naive pruning by \xce\xb8", 17, "start");
  legend_row(c, lx, ly, Mark::Line, component_palette()[0], "kept: \xce\xb8 \xe2\x89\xa5 the threshold,");
  c.text({lx + 40, ly + 22}, "one colour per connected component", 15, "start");
  legend_row(c, lx, ly + 56, Mark::Line, kDropped, "pruned: \xce\xb8 below the threshold");
  legend_row(c, lx, ly + 92, Mark::Ring, component_palette()[1], "a ring, in its colour: a component too short to see");
  c.text({lx, ly + 140}, "(a), (b): Voronoi axis of " + std::to_string(kSamplesA) + " samples", 15, "start");
  c.text({lx, ly + 164}, "(c): exact axis of the polygon", 15, "start");
}

std::vector<FigureFile> fig_2_4(const FigureContext& ctx) {
  Edf2dOptions sampled;
  sampled.samples = kSamplesA;
  Edf2dOptions exact;
  exact.axis = AxisMethod::ExactPolygon;
  Panels p{local_measure_shape(load_shape(ctx.data_dir + kShapeA), sampled),
           local_measure_shape(bump_shape(), exact),
           {},
           {},
           {}};
  p.x = nearest_edge_point(p.a, kTargetA, LocalMeasure::SeparationAngle, kPi / 2);
  p.half = threshold_axis(p.a, LocalMeasure::SeparationAngle, kPi / 2);
  p.third = threshold_axis(p.bump, LocalMeasure::SeparationAngle, kPi / 3);
  SvgCanvas c(2 * kPanelW, kRowA + kBarStrip + kRowC);
  panels_ab(c, p);
  panel_c(c, p, kRowA + kBarStrip);
  c.save(ctx.out_dir + "/fig2_4.svg");
  return {{"fig2_4.svg", caption(p)}};
}

GF_REGISTER_FIGURE("fig2_4", "Figure 2.4: the separation angle and naive pruning by it", fig_2_4);

}  // namespace
}  // namespace grassfire::figures
