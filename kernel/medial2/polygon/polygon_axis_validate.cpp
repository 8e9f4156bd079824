// polygon_axis_validate.cpp -- see polygon_axis_validate.h.
#include "medial2/polygon/polygon_axis_validate.h"

#include <algorithm>
#include <stdexcept>

#include "medial2/polygon/polygon_axis_geometry.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

// Certified sign of expr(circle) for one node: double interval, Arb at 256 bits, the
// exact form when the circle has one, Arb at 1024 bits; kUndecided when none decides.
class NodeSigns {
 public:
  NodeSigns(const PolygonAxisGeometry& geo, std::uint32_t node, AxisValidation& out)
      : geo_(geo), node_(node), out_(out), interval_(solve_interval(geo.sites(), geo.node_data(node).circle)) {}

  template <class Expr>
  int sign(Expr&& expr) {
    const int quick = certified_sign(expr(interval_));
    if (quick != kUndecided) return quick;
    for (long bits : {256L, 1024L}) {
      BallPrecision guard(bits);
      const int s = expr(solve_ball(geo_.sites(), geo_.node_data(node_).circle)).sign();
      if (s != kUndecided) {
        ++out_.ball_decisions;
        return s;
      }
      if (const auto& e = geo_.exact_circle(node_)) {
        const CircleValue<RootSum> x{RootSum(e->x), RootSum(e->y), RootSum(e->r)};
        ++out_.exact_decisions;
        return exact_sign(expr(x).v);
      }
    }
    return kUndecided;
  }

 private:
  const PolygonAxisGeometry& geo_;
  std::uint32_t node_;
  AxisValidation& out_;
  CircleValue<Interval> interval_;
};

// Residual of the squared distance to a point, and the line quantities of a segment.
template <class T>
T point_residual(const CircleValue<T>& c, const Point2& a) {
  const T dx = c.x - T(a.x), dy = c.y - T(a.y);
  return dx * dx + dy * dy - c.r * c.r;
}
template <class T>
T projection(const CircleValue<T>& c, const Point2& a, const Point2& b) {  // (X - A).(B - A)
  return (c.x - T(a.x)) * (T(b.x) - T(a.x)) + (c.y - T(a.y)) * (T(b.y) - T(a.y));
}
template <class T>
T beyond_end(const CircleValue<T>& c, const Point2& a, const Point2& b) {  // (X - A).(B - A) - |B-A|^2
  const T ux = T(b.x) - T(a.x), uy = T(b.y) - T(a.y);
  return projection(c, a, b) - (ux * ux + uy * uy);
}
template <class T>
T line_residual(const CircleValue<T>& c, const Point2& a, const Point2& b) {  // cross^2 - R^2 |B-A|^2
  const T ux = T(b.x) - T(a.x), uy = T(b.y) - T(a.y);
  const T cr = ux * (c.y - T(a.y)) - uy * (c.x - T(a.x));
  return cr * cr - c.r * c.r * (ux * ux + uy * uy);
}

std::string node_label(const MedialGraph& g, std::uint32_t v) {
  return "node " + std::to_string(v) + " at (" + std::to_string(g.node(v).position.x) + ", " +
         std::to_string(g.node(v).position.y) + ")";
}

void check_node(const MedialGraph& g, const PolygonAxisGeometry& geo, std::uint32_t v, AxisValidation& out) {
  const PolygonSites& s = geo.sites();
  const AxisNodeData& d = geo.node_data(v);
  if (d.circle.kind == CircleKind::Apex) return;
  ++out.nodes_checked;
  NodeSigns signs(geo, v, out);
  auto has = [&](std::uint32_t site) { return std::binary_search(d.sites.begin(), d.sites.end(), site); };
  // 1. Equidistance to the defining sites.
  for (std::uint32_t site : d.sites) {
    const Point2 a = s.vertex[s.is_point(site) ? site : s.seg_start(site)];
    const Point2 b = s.is_point(site) ? a : s.vertex[s.seg_end(site)];
    const int z = s.is_point(site) ? signs.sign([&](const auto& c) { return point_residual(c, a); })
                                   : signs.sign([&](const auto& c) { return line_residual(c, a, b); });
    if (z == kUndecided) ++out.residual_ties;
    else if (z != 0) out.failures.push_back(node_label(g, v) + ": not equidistant to its site " + std::to_string(site));
  }
  // 2. No closed boundary segment closer than R.
  for (std::uint32_t i = 0; i < s.vertex_count(); ++i) {
    ++out.boundary_tests;
    const Point2 a = s.vertex[i], b = s.vertex[s.next[i]];
    bool closer = false;
    for (std::uint32_t end : {i, s.next[i]}) {
      if (has(end)) continue;
      const Point2 p = s.vertex[end];
      closer = closer || signs.sign([&](const auto& c) { return point_residual(c, p); }) < 0;
    }
    if (!has(s.vertex_count() + i) && signs.sign([&](const auto& c) { return projection(c, a, b); }) > 0) {
      const int beyond = signs.sign([&](const auto& c) { return beyond_end(c, a, b); });
      if (beyond < 0) closer = closer || signs.sign([&](const auto& c) { return line_residual(c, a, b); }) < 0;
    }
    if (closer)
      out.failures.push_back(node_label(g, v) + ": boundary segment " + std::to_string(i) + " is closer than R");
  }
}

// Mid point of an edge (mid parameter of its bisector) and its distance to site_a, in Arb.
CircleValue<Ball> edge_mid(const PolygonAxisGeometry& geo, const AxisEdgeData& e) {
  const PolygonSites& s = geo.sites();
  const CircleValue<Ball> a = solve_ball(s, geo.node_data(e.u).circle), b = solve_ball(s, geo.node_data(e.v).circle);
  CircleValue<Ball> m;
  if (!e.parabolic) {
    m.x = Ball(0.5) * (a.x + b.x);
    m.y = Ball(0.5) * (a.y + b.y);
  } else {
    const std::uint32_t f = s.is_point(e.site_a) ? e.site_a : e.site_b, l = s.is_point(e.site_a) ? e.site_b : e.site_a;
    const Point2 fp = s.vertex[f], la = s.vertex[s.seg_start(l)], lb = s.vertex[s.seg_end(l)];
    const Ball dx = Ball(lb.x) - Ball(la.x), dy = Ball(lb.y) - Ball(la.y), len = sqrt(dx * dx + dy * dy);
    const Ball ex = dx / len, ey = dy / len, ux = -ey, uy = ex;
    const Ball p = ux * (Ball(fp.x) - Ball(la.x)) + uy * (Ball(fp.y) - Ball(la.y));
    const Ball xa = ex * (a.x - Ball(fp.x)) + ey * (a.y - Ball(fp.y)), xb = ex * (b.x - Ball(fp.x)) + ey * (b.y - Ball(fp.y));
    const Ball xi = Ball(0.5) * (xa + xb), eta = (xi * xi + p * p) / (Ball(2.0) * p) - p;
    m.x = Ball(fp.x) + xi * ex + eta * ux;
    m.y = Ball(fp.y) + xi * ey + eta * uy;
  }
  return m;
}

Ball distance_to_site(const PolygonSites& s, const CircleValue<Ball>& m, std::uint32_t site) {
  if (s.is_point(site)) {
    const Ball dx = m.x - Ball(s.vertex[site].x), dy = m.y - Ball(s.vertex[site].y);
    return sqrt(dx * dx + dy * dy);
  }
  const Point2 a = s.vertex[s.seg_start(site)], b = s.vertex[s.seg_end(site)];
  const Ball ux = Ball(b.x) - Ball(a.x), uy = Ball(b.y) - Ball(a.y);
  return (ux * (m.y - Ball(a.y)) - uy * (m.x - Ball(a.x))) / sqrt(ux * ux + uy * uy);
}

void check_edge(const MedialGraph& g, const PolygonAxisGeometry& geo, std::uint32_t e, AxisValidation& out) {
  ++out.edges_checked;
  const AxisEdgeData& d = geo.edge_data(e);
  const PolygonSites& s = geo.sites();
  for (std::uint32_t end : {d.u, d.v}) {
    const auto& sites = geo.node_data(end).sites;
    if (!std::binary_search(sites.begin(), sites.end(), d.site_a) || !std::binary_search(sites.begin(), sites.end(), d.site_b))
      out.failures.push_back("edge " + std::to_string(e) + ": its sites do not define its end " + node_label(g, end));
  }
  BallPrecision guard(256);
  CircleValue<Ball> m = edge_mid(geo, d);
  m.r = distance_to_site(s, m, d.site_a);
  const int equal = (m.r - distance_to_site(s, m, d.site_b)).sign();
  if (equal == 1 || equal == -1)
    out.failures.push_back("edge " + std::to_string(e) + ": mid point not equidistant to its two sites");
  auto defining = [&](std::uint32_t site) { return site == d.site_a || site == d.site_b; };
  // Signs at the mid point: first on the double interval enclosing the Arb ball (it
  // contains the ball, so a sign it certifies holds at the mid point), then in Arb.
  const CircleValue<Interval> box{m.x.to_interval(), m.y.to_interval(), m.r.to_interval()};
  auto sign_at_mid = [&](auto&& expr) {
    const int quick = certified_sign(expr(box));
    return quick != kUndecided ? quick : expr(m).sign();
  };
  for (std::uint32_t i = 0; i < s.vertex_count(); ++i) {
    ++out.boundary_tests;
    const Point2 a = s.vertex[i], b = s.vertex[s.next[i]];
    int worst = 1;
    for (std::uint32_t end : {i, s.next[i]})
      if (!defining(end)) worst = std::min(worst, sign_at_mid([&](const auto& c) { return point_residual(c, s.vertex[end]); }));
    if (!defining(s.vertex_count() + i) && sign_at_mid([&](const auto& c) { return projection(c, a, b); }) == 1 &&
        sign_at_mid([&](const auto& c) { return beyond_end(c, a, b); }) == -1)
      worst = std::min(worst, sign_at_mid([&](const auto& c) { return line_residual(c, a, b); }));
    if (worst == -1 || worst == 0)
      out.failures.push_back("edge " + std::to_string(e) + ": boundary segment " + std::to_string(i) +
                             " is as close as the sites at the mid point");
    else if (worst == kUndecided)
      ++out.residual_ties;
  }
}

}  // namespace

AxisValidation validate_polygon_axis(const MedialGraph& g) {
  const auto* geo = dynamic_cast<const PolygonAxisGeometry*>(&g.geometry());
  if (!geo) throw std::invalid_argument("validate_polygon_axis: the graph is not an exact polygon axis");
  AxisValidation out;
  const PolygonSites& s = geo->sites();
  std::uint32_t apexes = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const bool apex = geo->node_data(v).circle.kind == CircleKind::Apex;
    apexes += apex;
    if (apex != g.is_leaf(v)) out.failures.push_back(node_label(g, v) + (apex ? ": an apex that is no leaf" : ": a leaf that is no convex vertex"));
    check_node(g, *geo, v, out);
  }
  std::uint32_t convex = 0;
  for (std::uint32_t v = 0; v < s.vertex_count(); ++v) convex += is_convex_vertex(s, v);
  if (convex != apexes)
    out.failures.push_back(std::to_string(convex) + " convex vertices but " + std::to_string(apexes) + " apex nodes");
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) check_edge(g, *geo, e, out);
  return out;
}

}  // namespace grassfire
