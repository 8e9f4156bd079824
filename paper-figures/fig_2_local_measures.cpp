// fig_2_local_measures.cpp -- see fig_2_local_measures.h.
#include "fig_2_local_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

#include "support/union_find.h"
#include "shapes/validate_shape.h"

namespace grassfire::figures {

namespace {

constexpr int kBisections = 48;
constexpr double kEndNudge = 1e-6;  // of the edge's length

Point2 mid(const IntervalPoint2& p) { return {p.x.mid(), p.y.mid()}; }
bool same(const IntervalPoint2& a, const IntervalPoint2& b) {
  return a.x.lo == b.x.lo && a.x.hi == b.x.hi && a.y.lo == b.y.lo && a.y.hi == b.y.hi;
}
double dist(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The foot at x of a generator whose feet at the edge's ends are a and b (see the header).
Point2 foot(const Point2& x, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  if (len2 == 0) return a;
  const double t = std::clamp(((x.x - a.x) * dx + (x.y - a.y) * dy) / len2, 0.0, 1.0);
  return {a.x + t * dx, a.y + t * dy};
}

// Interval vector helpers for the certified critical-point tests.
IntervalPoint2 minus(const IntervalPoint2& a, const IntervalPoint2& b) { return {a.x - b.x, a.y - b.y}; }
Interval dot(const IntervalPoint2& a, const IntervalPoint2& b) { return a.x * b.x + a.y * b.y; }
Interval cross(const IntervalPoint2& a, const IntervalPoint2& b) { return a.x * b.y - a.y * b.x; }
int sign(const Interval& v) { return v.lo > 0 ? 1 : v.hi < 0 ? -1 : 0; }

IntervalPoint2 node_enclosure(const MedialGraph& g, std::uint32_t v) {
  const Interval e(-g.node(v).position_error, g.node(v).position_error);
  return {Interval(g.node(v).position.x) + e, Interval(g.node(v).position.y) + e};
}

// +1: the node is certainly inside the convex hull of its closest points (a maximum of
// the distance function); -1: certainly not; 0: undecided. The points lie on a circle
// around x, so their angular order is their order around the hull.
int node_is_critical(const LocalMeasureShape& s, std::uint32_t v) {
  const std::vector<BoundaryPoint>& pts = s.closest.node[v];
  // A leaf at a convex vertex (R = 0) lies on the boundary, not in the open shape.
  if (pts.size() < 3 || s.graph().node(v).radius.hi <= 0) return -1;
  const Point2 x = s.graph().node(v).position;
  std::vector<const BoundaryPoint*> order;  // one per point: a reflex vertex is also the foot of its segments
  for (const BoundaryPoint& p : pts)
    if (std::none_of(order.begin(), order.end(), [&](const BoundaryPoint* q) { return same(q->position, p.position); }))
      order.push_back(&p);
  if (order.size() < 3) return -1;
  std::sort(order.begin(), order.end(), [&](const BoundaryPoint* a, const BoundaryPoint* b) {
    return std::atan2(a->position.y.mid() - x.y, a->position.x.mid() - x.x) <
           std::atan2(b->position.y.mid() - x.y, b->position.x.mid() - x.x);
  });
  const IntervalPoint2 X = node_enclosure(s.graph(), v);
  int worst = 1;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const IntervalPoint2& a = order[i]->position;
    const IntervalPoint2& b = order[(i + 1) % order.size()]->position;
    worst = std::min(worst, sign(cross(minus(b, a), minus(X, a))));
  }
  return worst;
}

// The critical point inside the edge, if any (see the header); `undecided` counts what the
// enclosures cannot settle.
void edge_critical(const LocalMeasureShape& s, std::uint32_t e, CriticalPoints& out) {
  const std::array<BoundaryPoint, 4>& gen = s.closest.edge[e];
  const bool a_fixed = same(gen[0].position, gen[2].position), b_fixed = same(gen[1].position, gen[3].position);
  const MedialGraph& g = s.graph();
  if (a_fixed && b_fixed) {
    const IntervalPoint2 m{(gen[0].position.x + gen[1].position.x) * Interval(0.5),
                           (gen[0].position.y + gen[1].position.y) * Interval(0.5)};
    const int inside = -sign(dot(minus(m, node_enclosure(g, g.edge(e).u)), minus(m, node_enclosure(g, g.edge(e).v))));
    if (inside == 0) ++out.undecided;
    if (inside > 0) out.points.push_back({mid(m), 0.5 * dist(mid(gen[0].position), mid(gen[1].position)), false});
    return;
  }
  if (!a_fixed && !b_fixed) {
    const Interval c = cross(minus(gen[2].position, gen[0].position), minus(gen[3].position, gen[1].position));
    if (sign(c) == 0) ++out.undecided;
    return;
  }
  const IntervalPoint2& p = a_fixed ? gen[0].position : gen[1].position;
  const IntervalPoint2& fu = a_fixed ? gen[1].position : gen[0].position;
  const IntervalPoint2& fv = a_fixed ? gen[3].position : gen[2].position;
  const int after_u = sign(dot(minus(p, fu), minus(fv, fu))), before_v = sign(dot(minus(p, fv), minus(fu, fv)));
  if (after_u == 0 || before_v == 0) ++out.undecided;
  if (after_u > 0 && before_v > 0) {
    const Point2 apex_foot = foot(mid(p), mid(fu), mid(fv));
    const Point2 at{0.5 * (mid(p).x + apex_foot.x), 0.5 * (mid(p).y + apex_foot.y)};
    out.points.push_back({at, 0.5 * dist(mid(p), apex_foot), false});
  }
}

double edge_value(const LocalMeasureShape& s, LocalMeasure m, std::uint32_t e, double at) {
  return edge_point(s, e, at).value(m);
}

// The arc length between `out_s` (measure below the threshold) and `in_s` (at or above)
// where the measure crosses it.
double crossing(const LocalMeasureShape& s, LocalMeasure m, std::uint32_t e, double threshold, double out_s,
                double in_s) {
  for (int i = 0; i < kBisections; ++i) {
    const double c = 0.5 * (out_s + in_s);
    (edge_value(s, m, e, c) >= threshold ? in_s : out_s) = c;
  }
  return in_s;
}

// The pieces of edge e where the measure is >= threshold.
std::vector<AxisPiece> edge_pieces(const LocalMeasureShape& s, LocalMeasure m, std::uint32_t e, double threshold) {
  const double len = s.graph().edge(e).length.mid();
  std::vector<double> at;
  std::vector<bool> in;
  for (int i = 0; i <= kEdgeSteps; ++i) {
    at.push_back(len * i / kEdgeSteps);
    // At the ends the limit from inside the edge: at a leaf (R = 0) the ratio chord / 2R
    // of the feet is 0 / 0.
    const double inside = std::clamp(at.back(), kEndNudge * len, (1 - kEndNudge) * len);
    in.push_back(edge_value(s, m, e, inside) >= threshold);
  }
  std::vector<AxisPiece> out;
  for (int i = 0; i <= kEdgeSteps; ++i) {
    if (!in[i] || (i > 0 && in[i - 1])) continue;
    int j = i;
    while (j < kEdgeSteps && in[j + 1]) ++j;
    const double s0 = i == 0 ? 0.0 : crossing(s, m, e, threshold, at[i - 1], at[i]);
    const double s1 = j == kEdgeSteps ? len : crossing(s, m, e, threshold, at[j + 1], at[j]);
    out.push_back({e, s0, s1});
  }
  return out;
}

std::vector<Point2d> piece_points(const Medial2Frame& f, const MedialGraph& g, const AxisPiece& p) {
  const double px = (p.s1 - p.s0) * f.scale();
  const int n = std::max(1, static_cast<int>(std::ceil(px / 3)));
  std::vector<double> s;
  for (int i = 0; i <= n; ++i) s.push_back(p.s0 + (p.s1 - p.s0) * i / n);
  return edge_points(f, g, p.edge, s);
}

}  // namespace

LocalMeasureShape local_measure_shape(Shape2 shape, const Edf2dOptions& options) {
  LocalMeasureShape s;
  s.shape = std::move(shape);
  s.result = compute_edf2d(s.shape, options);
  s.closest = closest_points(*s.result.graph, &s.shape, &s.result.samples);
  s.nodes = local_feature_measures(*s.result.graph, s.closest);
  return s;
}

Shape2 polygon_shape(const std::string& name, std::vector<Point2> outer) {
  Shape2 shape{name, {Ring{std::move(outer)}}};
  validate_shape(shape, name);
  return shape;
}

EdgePoint edge_point(const LocalMeasureShape& s, std::uint32_t edge, double s_from_u) {
  const MedialGraph& g = s.graph();
  const std::array<BoundaryPoint, 4>& gen = s.closest.edge[edge];
  EdgePoint p;
  p.x = g.geometry().point_along(g, edge, g.edge(edge).u, s_from_u);
  p.y1 = foot(p.x, mid(gen[0].position), mid(gen[2].position));
  p.y2 = foot(p.x, mid(gen[1].position), mid(gen[3].position));
  p.radius = 0.5 * (dist(p.x, p.y1) + dist(p.x, p.y2));
  const double chord = dist(p.y1, p.y2);
  p.feature_size = 0.5 * chord;
  p.separation_angle = p.radius > 0 ? 2 * std::asin(std::min(1.0, chord / (2 * p.radius))) : 0.0;
  return p;
}

EdgePoint nearest_edge_point(const LocalMeasureShape& s, const Point2& target, LocalMeasure m, double at_least) {
  EdgePoint best;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::uint32_t e = 0; e < s.graph().edge_count(); ++e)
    for (int i = 0; i <= kEdgeSteps; ++i) {
      const EdgePoint p = edge_point(s, e, s.graph().edge(e).length.mid() * i / kEdgeSteps);
      if (p.value(m) >= at_least && dist(p.x, target) < best_d) best_d = dist(p.x, target), best = p;
    }
  return best;
}

double node_value(const LocalMeasureShape& s, LocalMeasure m, std::uint32_t node) {
  return (m == LocalMeasure::SeparationAngle ? s.nodes.separation_angle : s.nodes.feature_size)[node].mid();
}

ThresholdAxis threshold_axis(const LocalMeasureShape& s, LocalMeasure m, double threshold) {
  const MedialGraph& g = s.graph();
  ThresholdAxis t;
  t.node_kept.assign(g.node_count(), false);
  for (std::uint32_t v = 0; v < g.node_count(); ++v) t.node_kept[v] = node_value(s, m, v) >= threshold;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    for (const AxisPiece& p : edge_pieces(s, m, e, threshold)) t.pieces.push_back(p);
  // Elements: nodes 0..n-1, then pieces. A piece reaching an end contains that node (the
  // node's closest points include the edge's, so its measure is at least the limit).
  UnionFind uf(g.node_count() + t.pieces.size());
  std::uint64_t vertices = 0;
  for (std::size_t i = 0; i < t.pieces.size(); ++i) {
    const AxisPiece& p = t.pieces[i];
    const auto id = static_cast<std::uint32_t>(g.node_count() + i);
    const bool at_u = p.s0 == 0.0, at_v = p.s1 == g.edge(p.edge).length.mid();
    if (at_u) uf.unite(id, g.edge(p.edge).u), t.node_kept[g.edge(p.edge).u] = true;
    if (at_v) uf.unite(id, g.edge(p.edge).v), t.node_kept[g.edge(p.edge).v] = true;
    vertices += !at_u + !at_v;
  }
  std::vector<std::uint32_t> compact(uf.parent.size(), ThresholdAxis::kNone);
  auto component = [&](std::uint32_t id) {
    std::uint32_t& c = compact[uf.find(id)];
    if (c == ThresholdAxis::kNone) c = t.components++;
    return c;
  };
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    t.node_component.push_back(t.node_kept[v] ? component(v) : ThresholdAxis::kNone);
    vertices += t.node_kept[v];
  }
  for (std::size_t i = 0; i < t.pieces.size(); ++i)
    t.piece_component.push_back(component(static_cast<std::uint32_t>(g.node_count() + i)));
  t.cycles = t.pieces.size() + t.components - vertices;
  return t;
}

CriticalPoints critical_points(const LocalMeasureShape& s) {
  CriticalPoints out;
  const MedialGraph& g = s.graph();
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const int c = node_is_critical(s, v);
    if (c == 0) ++out.undecided;
    if (c > 0) out.points.push_back({g.node(v).position, g.node(v).radius.mid(), true});
  }
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) edge_critical(s, e, out);
  return out;
}

// ---- drawing ------------------------------------------------------------------------------

Medial2Frame shape_panel(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape,
                         const std::string& title) {
  const Medial2Frame f(shape, x + 16, y + 40, w - 32, h - 56);
  c.polygon_outline(shape_polygon(f, shape), kShapeFill, kShapeFill, 0);
  draw_boundary(c, f, shape, kShapeBoundary, 1.6);
  c.text({x + w / 2, y + 24}, title, 17, "middle");
  return f;
}

void draw_axis(SvgCanvas& c, const Medial2Frame& f, const MedialGraph& g, const Rgb& colour, double width,
               const std::string& dash) {
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    std::vector<Point2d> pts;
    for (const Point2& p : g.geometry().polyline(g, e)) pts.push_back(f(p));
    c.polyline(pts, colour, width, dash);
  }
}

void draw_measure_axis(SvgCanvas& c, const Medial2Frame& f, const LocalMeasureShape& s, LocalMeasure m, double lo,
                       double hi, double width) {
  const MedialGraph& g = s.graph();
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const double len = g.edge(e).length.mid();
    const int n = std::max(1, static_cast<int>(std::ceil(len * f.scale() / 3)));
    for (int i = 0; i < n; ++i) {
      const double s0 = len * i / n, s1 = len * (i + 1) / n;
      const double v = edge_value(s, m, e, 0.5 * (s0 + s1));
      c.polyline(edge_points(f, g, e, {s0, s1}), heat_color((v - lo) / (hi - lo)), width);
    }
  }
}

void draw_threshold_axis(SvgCanvas& c, const Medial2Frame& f, const LocalMeasureShape& s, const ThresholdAxis& t,
                         const std::vector<Rgb>& palette, double width) {
  const MedialGraph& g = s.graph();
  std::vector<bool> has_piece(g.node_count(), false);
  for (std::size_t i = 0; i < t.pieces.size(); ++i) {
    const AxisPiece& p = t.pieces[i];
    c.polyline(piece_points(f, g, p), palette[t.piece_component[i] % palette.size()], width);
    if (p.s0 == 0.0) has_piece[g.edge(p.edge).u] = true;
    if (p.s1 == g.edge(p.edge).length.mid()) has_piece[g.edge(p.edge).v] = true;
  }
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (t.node_kept[v] && !has_piece[v])
      c.circle(f(g.node(v).position), 1.3 * width, palette[t.node_component[v] % palette.size()], kBlack, 0.8);
}

void heat_bar(SvgCanvas& c, double x, double y, double w, double lo, double hi, const std::string& name,
              const std::vector<double>& ticks, const std::vector<std::string>& labels) {
  c.text({x, y + 13}, name, 16, "start");
  const double bx = x + 34, bw = w - 34;
  constexpr int kSwatches = 96;
  for (int i = 0; i < kSwatches; ++i)
    c.rect(bx + bw * i / kSwatches, y, bw / kSwatches + 0.5, 14, heat_color((i + 0.5) / kSwatches));
  for (std::size_t k = 0; k < ticks.size(); ++k) {
    const double tx = bx + bw * (ticks[k] - lo) / (hi - lo);
    c.polyline({{tx, y + 14}, {tx, y + 19}}, kBlack, 1);
    c.text({tx, y + 34}, labels.at(k), 14, "middle");
  }
}

void circle_outline(SvgCanvas& c, const Point2d& centre, double radius, const Rgb& colour, double width,
                    const std::string& dash) {
  std::vector<Point2d> pts;
  constexpr int kSides = 120;
  for (int i = 0; i <= kSides; ++i) {
    const double a = 2 * kPi * i / kSides;
    pts.push_back({centre[0] + radius * std::cos(a), centre[1] + radius * std::sin(a)});
  }
  c.polyline(pts, colour, width, dash);
}

void boxed_text(SvgCanvas& c, const Point2d& p, const std::string& text, double size, const Rgb& colour) {
  std::size_t glyphs = 0;
  for (unsigned char ch : text) glyphs += (ch & 0xc0) != 0x80;  // UTF-8: count the lead bytes
  const double w = 0.56 * size * static_cast<double>(glyphs) + 6;
  c.rect(p[0] - w / 2, p[1] - 0.85 * size, w, 1.1 * size, kWhite);
  c.text(p, text, size, "middle", colour);
}

void labelled_dot(SvgCanvas& c, const Point2d& p, const Rgb& colour, const std::string& label,
                  const Point2d& label_offset, double size) {
  c.circle(p, 5, colour, kWhite, 1.5);
  if (!label.empty()) boxed_text(c, {p[0] + label_offset[0], p[1] + label_offset[1]}, label, size, colour);
}

void legend_row(SvgCanvas& c, double x, double y, Mark mark, const Rgb& colour, const std::string& text) {
  if (mark == Mark::Line) c.polyline({{x, y - 5}, {x + 28, y - 5}}, colour, 2.6);
  if (mark == Mark::Hollow) c.circle({x + 14, y - 5}, 7, kWhite, kBlack, 2.2);
  if (mark == Mark::Ring) circle_outline(c, {x + 14, y - 5}, 9, colour, 1.6);
  c.text({x + 40, y}, text, 15, "start");
}

const std::vector<Rgb>& component_palette() {
  static const std::vector<Rgb> palette{{0.1, 0.3, 0.9},   {0.85, 0.1, 0.1}, {0.1, 0.6, 0.2}, {0.9, 0.55, 0.0},
                                        {0.55, 0.2, 0.7},  {0.0, 0.6, 0.7},  {0.7, 0.4, 0.2}, {0.9, 0.3, 0.6},
                                        {0.45, 0.45, 0.1}, {0.3, 0.3, 0.3}};
  return palette;
}

std::string fixed(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string printf_string(const char* format, ...) {
  va_list args, copy;
  va_start(args, format);
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string out(static_cast<std::size_t>(std::max(n, 0)) + 1, '\0');
  std::vsnprintf(out.data(), out.size(), format, args);
  va_end(args);
  out.resize(out.size() - 1);
  return out;
}

}  // namespace grassfire::figures
