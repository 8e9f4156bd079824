// svg_pruned2.cpp -- see svg_pruned2.h.
#include "render/svg_pruned2.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "support/union_find.h"

namespace grassfire {

namespace {

constexpr double kMargin = 12;      // px around the shape
constexpr double kTitleStrip = 30;  // px
constexpr double kNoteStrip = 28;   // px
const Rgb kFill{0.92, 0.92, 0.92}, kBoundary{0.15, 0.15, 0.15}, kFaintAxis{0.62, 0.62, 0.62}, kWhite{1, 1, 1};

double font_size(double width) {
  return std::clamp(width / 45, 12.0, 18.0);
}

std::uint64_t component_count(std::size_t nodes, const std::vector<PrunedEdge>& edges) {
  UnionFind sets(nodes);
  std::uint64_t components = nodes;
  for (const PrunedEdge& e : edges)
    if (sets.find(e.u) != sets.find(e.v)) sets.unite(e.u, e.v), --components;
  return components;
}

// Arc lengths from `a` to `b` in steps no longer than `step` (at least `min_steps` of them).
std::vector<double> subdivide(double a, double b, double step, int min_steps) {
  const int n = std::max(min_steps, static_cast<int>(std::ceil(std::fabs(b - a) / step)));
  std::vector<double> s;
  for (int i = 0; i <= n; ++i) s.push_back(a + (b - a) * i / n);
  return s;
}

struct PanelStyle {
  const Medial2Frame& frame;
  double axis_width;
  Medial2FieldRange range;
};

// A polyline from node a to node b (of the medial graph, or of a pruned axis).
struct Stroke {
  std::uint32_t a = 0, b = 0;
  std::vector<Point2d> points;
};

// Joins strokes end to end through the nodes where exactly two of them meet, so that a
// sampled axis (thousands of short edges in chains) is drawn as a few long polylines.
std::vector<std::vector<Point2d>> chains(const std::vector<Stroke>& strokes, std::size_t nodes) {
  std::vector<std::vector<std::uint32_t>> at(nodes);
  for (std::uint32_t i = 0; i < strokes.size(); ++i) at[strokes[i].a].push_back(i), at[strokes[i].b].push_back(i);
  std::vector<bool> used(strokes.size(), false);
  std::vector<std::vector<Point2d>> out;
  auto walk = [&](std::uint32_t i, std::uint32_t node) {
    std::vector<Point2d> line;
    while (!used[i]) {
      used[i] = true;
      const Stroke& s = strokes[i];
      const bool forward = s.a == node;
      std::vector<Point2d> pts = s.points;
      if (!forward) std::reverse(pts.begin(), pts.end());
      line.insert(line.end(), pts.begin() + (line.empty() ? 0 : 1), pts.end());
      node = forward ? s.b : s.a;
      if (at[node].size() != 2) break;
      i = at[node][0] == i ? at[node][1] : at[node][0];
    }
    out.push_back(std::move(line));
  };
  for (std::uint32_t v = 0; v < nodes; ++v)
    if (at[v].size() != 2)
      for (std::uint32_t i : at[v])
        if (!used[i]) walk(i, v);
  for (std::uint32_t i = 0; i < strokes.size(); ++i)  // what is left lies on cycles of degree-2 nodes
    if (!used[i]) walk(i, strokes[i].a);
  return out;
}

// The kept stretches of a pruned axis as strokes (curved edges followed).
std::vector<Stroke> kept_strokes(const PanelStyle& st, const MedialGraph& g, const PrunedAxis& p,
                                 const Pruned2SvgOptions& o) {
  std::vector<Stroke> strokes;
  for (const PrunedEdge& e : p.edges) {
    const int min_steps = e.kind == EdgeKind::ParabolicArc ? 8 : 1;
    const std::vector<double> s = subdivide(e.from.mid(), e.to.mid(), 4 * o.max_piece / st.frame.scale(), min_steps);
    strokes.push_back({e.u, e.v, edge_points(st.frame, g, e.source_edge, s)});
  }
  return strokes;
}

std::vector<Stroke> axis_strokes(const Medial2Frame& f, const MedialGraph& g) {
  std::vector<Stroke> strokes;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    Stroke s{g.edge(e).u, g.edge(e).v, {}};
    for (const Point2& q : g.geometry().polyline(g, e)) s.points.push_back(f(q));
    strokes.push_back(std::move(s));
  }
  return strokes;
}

std::size_t draw_chains(SvgCanvas& c, const std::vector<Stroke>& strokes, std::size_t nodes, const Rgb& colour,
                        double width) {
  const std::vector<std::vector<Point2d>> lines = chains(strokes, nodes);
  for (const std::vector<Point2d>& line : lines) c.polyline(line, colour, width);
  return lines.size();
}

// One kept stretch coloured by the field: pieces between the field's breakpoints inside
// the stretch, each coloured by the field at its middle.
std::size_t draw_coloured(SvgCanvas& c, const PanelStyle& st, const MedialGraph& g, const GrassfireResult& r,
                          const PrunedEdge& e, const Pruned2SvgOptions& o) {
  const double a = e.from.mid(), b = e.to.mid();
  std::vector<double> cuts{a};
  for (double q : field_breakpoints(g, r, e.source_edge))
    if (q > a && q < b) cuts.push_back(q);
  cuts.push_back(b);
  const std::uint32_t u = g.edge(e.source_edge).u;
  const double span = st.range.hi - st.range.lo;
  std::size_t pieces = 0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const std::vector<double> s = subdivide(cuts[k], cuts[k + 1], o.max_piece / st.frame.scale(), 1);
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
      const double v = medial2_field_along(g, r, o.field, e.source_edge, u, 0.5 * (s[i] + s[i + 1]));
      const Rgb col = std::isinf(v) ? kInfiniteColour : heat_color(span > 0 ? (v - st.range.lo) / span : 0.5);
      c.polyline(edge_points(st.frame, g, e.source_edge, {s[i], s[i + 1]}), col, st.axis_width);
      ++pieces;
    }
  }
  return pieces;
}

void draw_nodes(SvgCanvas& c, const PanelStyle& st, const PrunedAxis& p, const Pruned2SvgOptions& o) {
  std::vector<bool> on_edge(p.nodes.size(), false);
  for (const PrunedEdge& e : p.edges) on_edge[e.u] = on_edge[e.v] = true;
  for (std::size_t i = 0; i < p.nodes.size(); ++i) {
    const PrunedNode& n = p.nodes[i];
    if (!on_edge[i])
      c.circle(st.frame(n.position), 2.2 * st.axis_width, o.colour, kWhite, 0.4 * st.axis_width);
    else if (o.mark_cuts && n.source_node == kCutPoint)
      c.circle(st.frame(n.position), 0.9 * st.axis_width, kWhite, kBoundary, 0.45 * st.axis_width);
  }
}

}  // namespace

double PruningSummary::kept_fraction() const {
  return axis_length.mid() > 0 ? kept_length.mid() / axis_length.mid() : 0.0;
}

PruningSummary pruning_summary(const MedialGraph& g, const PrunedAxis& p) {
  PruningSummary s;
  s.axis_edges = g.edge_count();
  s.axis_nodes = g.node_count();
  s.axis_components = g.component_count();
  s.axis_cycles = g.cycle_rank();
  for (const MedialEdge& e : g.edges()) s.axis_length += e.length;
  s.kept_edges = p.edges.size();
  s.kept_nodes = p.nodes.size();
  s.cut_points = p.cut_points;
  s.kept_components = component_count(p.nodes.size(), p.edges);
  s.kept_cycles = s.kept_edges + s.kept_components - s.kept_nodes;
  for (const PrunedEdge& e : p.edges) s.kept_length += e.length;
  return s;
}

double pruned2_panel_height(const Shape2& shape, const Pruned2SvgOptions& o, double width) {
  double minx = INFINITY, maxx = -INFINITY, miny = INFINITY, maxy = -INFINITY;
  for (const Ring& ring : shape.rings)
    for (const Point2& p : ring.points)
      minx = std::min(minx, p.x), maxx = std::max(maxx, p.x), miny = std::min(miny, p.y), maxy = std::max(maxy, p.y);
  if (!(maxx > minx && maxy > miny)) throw std::invalid_argument("svg: the shape " + shape.name + " is empty");
  const double plot = std::min((width - 2 * kMargin) * (maxy - miny) / (maxx - minx), 1.2 * width);
  return plot + 2 * kMargin + (o.title.empty() ? 0 : kTitleStrip) + (o.note.empty() ? 0 : kNoteStrip);
}

std::size_t draw_pruned2(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape,
                         const MedialGraph& g, const GrassfireResult& r, const NodeMeasures& m, const PrunedAxis& p,
                         const Pruned2SvgOptions& o) {
  if (!(o.max_piece > 0)) throw std::invalid_argument("svg: the piece length must be positive");
  const double top = o.title.empty() ? 0 : kTitleStrip, bottom = o.note.empty() ? 0 : kNoteStrip;
  const Medial2Frame f(shape, x + kMargin, y + top + kMargin, w - 2 * kMargin, h - top - bottom - 2 * kMargin);
  PanelStyle st{f, o.axis_width > 0 ? o.axis_width : w / 200, medial2_field_range(g, r, m, o.field)};
  if (o.range_lo < o.range_hi) st.range.lo = o.range_lo, st.range.hi = o.range_hi;

  c.polygon_outline(shape_polygon(f, shape), kFill, kFill, 0);
  draw_boundary(c, f, shape, kBoundary, 0.4 * st.axis_width);
  if (o.show_axis) draw_chains(c, axis_strokes(f, g), g.node_count(), kFaintAxis, 0.4 * st.axis_width);
  std::size_t lines = 0;
  if (o.colour_by_field)
    for (const PrunedEdge& e : p.edges) lines += draw_coloured(c, st, g, r, e, o);
  else
    lines += draw_chains(c, kept_strokes(st, g, p, o), p.nodes.size(), o.colour, st.axis_width);
  if (o.overlay)  // a little wider, so that no antialiased rim of the axis under it shows
    lines += draw_chains(c, kept_strokes(st, g, *o.overlay, o), o.overlay->nodes.size(), o.overlay_colour,
                         1.25 * st.axis_width);
  draw_nodes(c, st, p, o);
  const double fs = font_size(w);
  if (!o.title.empty()) c.text({x + w / 2, y + 21}, o.title, 1.1 * fs, "middle");
  if (!o.note.empty()) c.text({x + w / 2, y + h - 8}, o.note, fs, "middle");
  return lines;
}

}  // namespace grassfire
