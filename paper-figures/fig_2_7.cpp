// fig_2_7.cpp -- Figure 2.7 (2.2.2, after Shaked and Bruckstein 1998): the erosion
// thickness (a), the potential, circularity and chord residues (b) and the erosion area (c)
// at a medial point q of a polygon with one finger, on its exact medial axis, with the
// values computed by the kernel (burn2/measures.h, burn2/potential_residue.h,
// burn2/feature_size.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

#include "burn2/closest_points.h"
#include "burn2/feature_size.h"
#include "burn2/potential_residue.h"
#include "figure_registry.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "shapes/validate_shape.h"

namespace grassfire::figures {
namespace {

const Rgb kFill{0.92, 0.92, 0.92}, kBoundary{0.15, 0.15, 0.15}, kAxis{0.35, 0.45, 0.85}, kBranch{0.9, 0.45, 0.0},
    kCircle{0.45, 0.1, 0.6}, kCurveB{0.85, 0.1, 0.1}, kArcA{0.1, 0.6, 0.2}, kChordC{0.1, 0.3, 0.9},
    kErosion{0.55, 0.55, 0.55}, kInk{0, 0, 0};
constexpr double kPi = 3.14159265358979323846;

// An 8 x 3 rectangle with a tapered finger on top, apex (4, 8). The vertex (2.96, 4.75) on
// the finger's left side lies on the segment from (2.4, 3) to the apex, so the exact axis
// keeps a degree-2 node where that vertex's normal meets the finger's centre line x = 4,
// at q = (4, 4.4172): a node, where the kernel's per-node measures are defined.
Shape2 finger_shape() {
  Shape2 s{"finger", {Ring{{{0, 0}, {8, 0}, {8, 3}, {5.6, 3}, {4, 8}, {2.96, 4.75}, {2.4, 3}, {0, 3}}}}};
  validate_shape(s, "Fig. 2.7 finger");
  return s;
}
const Point2 kQ{4, 4.4172}, kApex{4, 8};

// The node at a point known from the construction above (found by the nodes' double
// positions: a lookup for drawing, no geometric decision).
std::uint32_t node_at(const MedialGraph& g, const Point2& where) {
  std::uint32_t best = 0;
  double d = std::numeric_limits<double>::infinity();
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const double dv = std::hypot(g.node(v).position.x - where.x, g.node(v).position.y - where.y);
    if (dv < d) d = dv, best = v;
  }
  if (!(d < 1e-3)) throw std::runtime_error("fig2_7: the exact axis has no node at the expected point");
  return best;
}

// The edges of the unique path from `from` to `to` in the tree part of the axis.
std::vector<std::uint32_t> path_edges(const MedialGraph& g, std::uint32_t from, std::uint32_t to) {
  std::vector<std::uint32_t> via(g.node_count(), kNoSample);
  std::vector<bool> seen(g.node_count(), false);
  std::queue<std::uint32_t> open;
  open.push(from);
  seen[from] = true;
  while (!open.empty()) {
    const std::uint32_t v = open.front();
    open.pop();
    g.for_each_incident(v, [&](std::uint32_t e) {
      const std::uint32_t w = g.other_end(e, v);
      if (!seen[w]) seen[w] = true, via[w] = e, open.push(w);
    });
  }
  std::vector<std::uint32_t> path;
  for (std::uint32_t v = to; v != from; v = g.other_end(via[v], v)) path.push_back(via[v]);
  return path;
}

// What the three panels show, from the kernel's results (midpoints of the enclosures).
struct MeasuresAtQ {
  std::uint32_t p = 0, q = 0;
  std::vector<std::uint32_t> branch;  // edges from q to p
  double d_pq = 0, rho_p = 0, rho_q = 0, edf_q = 0, et_q = 0;
  double pr_q = 0, theta = 0, chord = 0, arc = 0, erosion_area = 0, raster_area = 0;
  Point2 foot[2];                 // the two closest boundary points of q
  const Point2& right_foot() const { return foot[0].x > foot[1].x ? foot[0] : foot[1]; }
  std::vector<Point2> curve_b;    // the boundary from foot[0] to foot[1] around the finger
  std::vector<Point2> arc_a;      // the medial circle's arc from foot[1] back to foot[0]
  std::vector<Point2> eroded;     // B then A: the region the pruned axis no longer covers
};

// The two closest points of q farthest apart (a vertex on a segment's end is listed once
// per site), as boundary points.
std::array<BoundaryPoint, 2> two_feet(const std::vector<BoundaryPoint>& pts) {
  std::array<BoundaryPoint, 2> best{pts.at(0), pts.at(0)};
  double far = -1;
  for (const BoundaryPoint& a : pts)
    for (const BoundaryPoint& b : pts) {
      const double d = std::hypot(a.position.x.mid() - b.position.x.mid(), a.position.y.mid() - b.position.y.mid());
      if (d > far) far = d, best = {a, b};
    }
  return best;
}

// The ring from a to b forwards when that is the shorter way (else from b to a), so that
// the curve is the one whose length is the potential residue.
std::vector<Point2> shorter_boundary(const Ring& ring, double length, BoundaryPoint a, BoundaryPoint b) {
  if (std::fmod(b.arc.mid() - a.arc.mid() + 2 * length, length) > length / 2) std::swap(a, b);
  const std::size_t n = ring.points.size();
  std::vector<Point2> out{{a.position.x.mid(), a.position.y.mid()}};
  for (std::size_t v = (a.vertex + 1) % n; v != (b.vertex + 1) % n; v = (v + 1) % n) out.push_back(ring.points[v]);
  out.push_back({b.position.x.mid(), b.position.y.mid()});
  return out;
}

double shoelace(const std::vector<Point2>& poly) {
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point2 &u = poly[i], &w = poly[(i + 1) % poly.size()];
    a += u.x * w.y - w.x * u.y;
  }
  return std::abs(a) / 2;
}

// The arc of the circle (centre, r) from `from` to `to` the short way, `n` pieces.
std::vector<Point2> short_arc(const Point2& centre, double r, const Point2& from, const Point2& to, int n) {
  const double a0 = std::atan2(from.y - centre.y, from.x - centre.x);
  const double delta = std::remainder(std::atan2(to.y - centre.y, to.x - centre.x) - a0, 2 * kPi);
  std::vector<Point2> out;
  for (int k = 0; k <= n; ++k) {
    const double t = a0 + delta * k / n;
    out.push_back({centre.x + r * std::cos(t), centre.y + r * std::sin(t)});
  }
  return out;
}

// Medial disks every cell / 2 along the axis without the `removed` edges, R by
// boundary_distance (display).
std::vector<std::array<double, 3>> pruned_disks(const Shape2& shape, const MedialGraph& g,
                                                const std::vector<std::uint32_t>& removed, double cell) {
  std::vector<std::array<double, 3>> disks;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    if (std::find(removed.begin(), removed.end(), e) != removed.end()) continue;
    const double w = g.edge(e).length.mid();
    const int n = std::max(2, static_cast<int>(std::ceil(2 * w / cell)));
    for (int k = 0; k <= n; ++k) {
      const Point2 p = g.geometry().point_along(g, e, g.edge(e).u, w * k / n);
      disks.push_back({p.x, p.y, boundary_distance(shape, p)});
    }
  }
  return disks;
}

bool inside_ring(const std::vector<Point2>& ring, double x, double y) {  // crossing number (display)
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i].y > y) != (ring[j].y > y) &&
        x < (ring[j].x - ring[i].x) * (y - ring[i].y) / (ring[j].y - ring[i].y) + ring[i].x)
      in = !in;
  return in;
}

// The erosion area by its definition: the area of the shape outside every medial disk of
// the axis without the `removed` edges, on a raster of `cell`-sized cells (display only).
double uncovered_area(const Shape2& shape, const MedialGraph& g, const std::vector<std::uint32_t>& removed, double cell) {
  const std::vector<std::array<double, 3>> disks = pruned_disks(shape, g, removed, cell);
  const std::vector<Point2>& ring = shape.rings[0].points;
  double lo_x = ring[0].x, hi_x = lo_x, lo_y = ring[0].y, hi_y = lo_y;
  for (const Point2& p : ring)
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x), lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  std::size_t open = 0;
  // Cell centres off the polygon's lines (its coordinates are short decimals).
  for (double x = lo_x + 0.37 * cell; x < hi_x; x += cell)
    for (double y = lo_y + 0.29 * cell; y < hi_y; y += cell)
      open += inside_ring(ring, x, y) && std::none_of(disks.begin(), disks.end(), [&](const std::array<double, 3>& d) {
                return (x - d[0]) * (x - d[0]) + (y - d[1]) * (y - d[1]) <= d[2] * d[2];
              });
  return static_cast<double>(open) * cell * cell;
}

MeasuresAtQ measures_at_q(const Shape2& shape, const Edf2dResult& r) {
  const MedialGraph& g = *r.graph;
  MeasuresAtQ m;
  m.q = node_at(g, kQ);
  m.p = node_at(g, kApex);
  m.branch = path_edges(g, m.q, m.p);
  for (std::uint32_t e : m.branch) m.d_pq += g.edge(e).length.mid();
  m.rho_p = g.node(m.p).radius.mid();
  m.rho_q = g.node(m.q).radius.mid();
  m.edf_q = r.burning->edf(m.q).mid();
  m.et_q = r.measures.erosion_thickness[m.q].mid();
  const ClosestPoints cp = closest_points(g);
  m.pr_q = potential_residue(g, cp).node[m.q].value.mid();
  const LocalFeatureMeasures lf = local_feature_measures(g, cp);
  m.theta = lf.separation_angle[m.q].mid();
  m.arc = m.rho_q * m.theta;                 // L(A): the short arc of the medial circle between the feet
  m.chord = 2 * lf.feature_size[m.q].mid();  // L(C): the feet fit in a half-plane, so r(q) = |C| / 2
  const std::array<BoundaryPoint, 2> feet = two_feet(cp.node[m.q]);
  m.curve_b = shorter_boundary(shape.rings[feet[0].ring], cp.ring_length[feet[0].ring].mid(), feet[0], feet[1]);
  m.foot[0] = m.curve_b.front();
  m.foot[1] = m.curve_b.back();
  m.arc_a = short_arc(g.node(m.q).position, m.rho_q, m.foot[1], m.foot[0], 96);
  m.eroded = m.curve_b;
  m.eroded.insert(m.eroded.end(), m.arc_a.begin() + 1, m.arc_a.end() - 1);
  m.erosion_area = shoelace(m.eroded);
  m.raster_area = uncovered_area(shape, g, m.branch, 0.01);
  return m;
}

std::vector<Point2d> to_canvas(const Medial2Frame& f, const std::vector<Point2>& pts) {
  std::vector<Point2d> out;
  for (const Point2& p : pts) out.push_back(f(p));
  return out;
}

void draw_circle(SvgCanvas& c, const Medial2Frame& f, const Point2& centre, double r, const Rgb& colour, double width,
                 const std::string& dash = "") {
  std::vector<Point2d> pts;
  for (int k = 0; k <= 128; ++k)
    pts.push_back(f({centre.x + r * std::cos(2 * kPi * k / 128), centre.y + r * std::sin(2 * kPi * k / 128)}));
  c.polyline(pts, colour, width, dash);
}

// The shape, its axis (the edges in `skip` left out) and the points p and q.
void draw_base(SvgCanvas& c, const Medial2Frame& f, const Shape2& shape, const MedialGraph& g, const MeasuresAtQ& m,
               const std::vector<std::uint32_t>& skip) {
  c.polygon(shape_polygon(f, shape), kFill);
  draw_boundary(c, f, shape, kBoundary, 1.6);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    if (std::find(skip.begin(), skip.end(), e) == skip.end())
      c.polyline(to_canvas(f, g.geometry().polyline(g, e)), kAxis, 1.6);
  for (std::uint32_t v : {m.p, m.q}) c.circle(f(g.node(v).position), 3.5, kInk, kInk, 1);
  c.text({f(g.node(m.q).position)[0] - 10, f(g.node(m.q).position)[1] + 20}, "q", 18, "end");
  c.text({f(g.node(m.p).position)[0] + 12, f(g.node(m.p).position)[1] + 6}, "p", 18);
}

std::string fmt(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, a, b, c, d);
  return buf;
}

struct Panel {
  double x, w;
  Medial2Frame frame;
};
constexpr double kPanelW = 560, kTop = 44, kShapeH = 560, kHeight = kTop + kShapeH + 120;

struct Line {
  std::string text;
  Rgb colour;
};
void lines_under(SvgCanvas& c, const Panel& p, const std::vector<Line>& lines) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    c.text({p.x + 20, kTop + kShapeH + 34 + 26 * static_cast<double>(i)}, lines[i].text, 16, "start", lines[i].colour);
}

void panel_erosion_thickness(SvgCanvas& c, const Panel& p, const Shape2& shape, const MedialGraph& g,
                             const MeasuresAtQ& m) {
  const Medial2Frame& f = p.frame;
  draw_base(c, f, shape, g, m, {});
  for (std::uint32_t e : m.branch) c.polyline(to_canvas(f, g.geometry().polyline(g, e)), kBranch, 4.5);
  const Point2 q = g.node(m.q).position, apex = g.node(m.p).position, foot = m.right_foot();
  draw_circle(c, f, q, m.rho_q, kCircle, 2);
  c.polyline({f(q), f(foot)}, kCircle, 1.8, "5,3");
  c.text({f(apex)[0] + 24, f(apex)[1] + 6}, fmt(", \u03c1(p) = %.3g (a convex vertex)", m.rho_p), 17);
  c.text({f(foot)[0] + 14, f(foot)[1] + 6}, fmt("\u03c1(q) = %.4f", m.rho_q), 17, "start", kCircle);
  c.text(f({q.x + 0.75, 0.45 * q.y + 0.55 * apex.y}), fmt("d(p, q) = %.4f", m.d_pq), 17, "start", kBranch);
  c.text({p.x + p.w / 2, 28}, "(a) erosion thickness at q", 19, "middle");
  lines_under(c, p,
              {{fmt("ET(q) = d(p, q) + \u03c1(p) \u2212 \u03c1(q) = %.4f + %.3g \u2212 %.4f = %.4f", m.d_pq, m.rho_p,
                    m.rho_q, m.d_pq + m.rho_p - m.rho_q),
                kInk},
               {fmt("kernel: EDF(q) = %.4f, ET(q) = EDF(q) \u2212 R(q) = %.4f", m.edf_q, m.et_q), kInk}});
}

void panel_residues(SvgCanvas& c, const Panel& p, const Shape2& shape, const MedialGraph& g, const MeasuresAtQ& m) {
  const Medial2Frame& f = p.frame;
  draw_base(c, f, shape, g, m, {});
  const Point2 q = g.node(m.q).position;
  draw_circle(c, f, q, m.rho_q, kCircle, 1.2, "4,3");
  c.polyline(to_canvas(f, m.curve_b), kCurveB, 4);
  c.polyline(to_canvas(f, m.arc_a), kArcA, 4);
  c.polyline({f(m.foot[0]), f(m.foot[1])}, kChordC, 3);
  const double side_y = 0.5 * (q.y + g.node(m.p).position.y);
  c.text(f({q.x + 0.45 * (kApex.y - side_y) + 0.25, side_y}), "B", 20, "start", kCurveB);
  const double label_angle = 0.35 * kPi;  // on the arc, clear of the centre line
  c.text(f({q.x + 1.12 * m.rho_q * std::cos(label_angle), q.y + 1.12 * m.rho_q * std::sin(label_angle)}), "A", 20,
         "start", kArcA);
  const Point2d left = f(m.foot[0].x < m.foot[1].x ? m.foot[0] : m.foot[1]);
  c.text({0.6 * left[0] + 0.4 * f(q)[0], left[1] + 22}, "C", 20, "middle", kChordC);
  c.text({p.x + p.w / 2, 28}, "(b) the three residues at q", 19, "middle");
  lines_under(c, p,
              {{fmt("potential residue L(B) = PR(q) = %.4f", m.pr_q), kCurveB},
               {fmt("circularity residue L(B) \u2212 L(A) = %.4f \u2212 %.4f = %.4f", m.pr_q, m.arc, m.pr_q - m.arc),
                kArcA},
               {fmt("chord residue L(B) \u2212 L(C) = %.4f \u2212 %.4f = %.4f", m.pr_q, m.chord, m.pr_q - m.chord),
                kChordC}});
}

void panel_erosion_area(SvgCanvas& c, const Panel& p, const Shape2& shape, const MedialGraph& g, const MeasuresAtQ& m) {
  const Medial2Frame& f = p.frame;
  draw_base(c, f, shape, g, m, m.branch);
  c.polygon(to_canvas(f, m.eroded), kErosion);
  c.polyline(to_canvas(f, m.curve_b), kCurveB, 1.5);
  c.polyline(to_canvas(f, m.arc_a), kArcA, 1.5);
  for (std::uint32_t e : m.branch) c.polyline(to_canvas(f, g.geometry().polyline(g, e)), kBranch, 2, "6,4");
  draw_circle(c, f, g.node(m.q).position, m.rho_q, kCircle, 1.2, "4,3");
  c.text({p.x + p.w / 2, 28}, "(c) erosion area of q (grey)", 19, "middle");
  lines_under(c, p, {{fmt("erosion area = the area between B and A = %.4f", m.erosion_area), kInk},
                     {fmt("check: shape outside the disks of the pruned axis %.3f", m.raster_area), kInk},
                     {"(computed for display here: not in the kernel)", kInk}});
}

std::string caption(const MedialGraph& g, const MeasuresAtQ& m) {
  return "Fig. 2.7 redone (after Shaked and Bruckstein) on an 8 x 3 rectangle with a tapered finger, its exact "
         "medial axis (segment Voronoi diagram, " +
         std::to_string(g.node_count()) + " nodes, " + std::to_string(g.edge_count()) +
         " edges, blue); q is the degree-2 node on the finger's centre line where the normal of the side's "
         "collinear vertex meets it. (a) Erosion thickness: the branch from q to its end p (orange), d(p, q) = " +
         fmt("%.4f", m.d_pq) + " along the axis, the medial circles at q (purple, rho(q) = " + fmt("%.4f", m.rho_q) +
         ") and at p (a convex vertex of the polygon: rho(p) = 0, where a smooth tip would have its radius of "
         "curvature); ET(q) = d(p, q) + rho(p) - rho(q) = " +
         fmt("%.4f", m.d_pq + m.rho_p - m.rho_q) + ", the same as the kernel's EDF(q) - R(q) = " + fmt("%.4f", m.et_q) +
         " (burn2/measures.h). (b) The boundary curve B between q's two closest points (red; its length is the "
         "kernel's potential residue PR(q) = " +
         fmt("%.4f", m.pr_q) + ", burn2/potential_residue.h), the arc A of the medial circle between them (green, L(A) = " +
         "R(q) times the separation angle " + fmt("%.4f", m.theta) + " rad = " + fmt("%.4f", m.arc) +
         ") and the chord C (blue, L(C) = twice the feature size r(q) = " + fmt("%.4f", m.chord) +
         ", burn2/feature_size.h): circularity residue " + fmt("%.4f", m.pr_q - m.arc) + ", chord residue " +
         fmt("%.4f", m.pr_q - m.chord) +
         ". (c) The erosion area (grey): what the reconstruction from the medial disks loses when the branch beyond "
         "q (dashed) is removed. It is not in the kernel; here it is the area between B and A, " +
         fmt("%.4f", m.erosion_area) + ", checked against a raster of 0.01 cells counting the shape outside every "
         "disk of the pruned axis: " + fmt("%.3f", m.raster_area) +
         " (display arithmetic). Look for the branch's length d(p, q) + rho(p) against its thickness rho(q) at q, "
         "B running round the finger, and the residues ordered PR > chord residue > circularity residue (the arc "
         "is longer than the chord).";
}

std::vector<FigureFile> fig_2_7(const FigureContext& ctx) {
  const Shape2 shape = finger_shape();
  Edf2dOptions exact;
  exact.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(shape, exact);
  const MedialGraph& g = *r.graph;
  const MeasuresAtQ m = measures_at_q(shape, r);
  SvgCanvas c(3 * kPanelW, kHeight);
  std::vector<Panel> panels;
  for (int i = 0; i < 3; ++i)
    panels.push_back({i * kPanelW, kPanelW, Medial2Frame(shape, i * kPanelW + 20, kTop, kPanelW - 40, kShapeH)});
  panel_erosion_thickness(c, panels[0], shape, g, m);
  panel_residues(c, panels[1], shape, g, m);
  panel_erosion_area(c, panels[2], shape, g, m);
  c.save(ctx.out_dir + "/fig2_7.svg");
  return {{"fig2_7.svg", caption(g, m)}};
}

GF_REGISTER_FIGURE("fig2_7", "Figure 2.7: erosion thickness, residues and erosion area", fig_2_7);

}  // namespace

}  // namespace grassfire::figures
