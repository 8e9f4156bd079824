// disk_union_validate.cpp -- see disk_union_validate.h.
#include "medial2/disks/disk_union_validate.h"

#include <algorithm>
#include <functional>

#include "medial2/disks/disk_union_geometry.h"
#include "medial2/disks/disk_union_triangulations.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

// A point of the axis under test, with the corners that must be its closest points.
struct Probe {
  std::string name;
  std::array<ExactSum, 2> x;
  IntervalPoint2 approx;
  std::function<ExactSum()> r2;  // R^2, built only when a filter fails
  Interval r2_approx;
  std::vector<std::uint32_t> closest;
  std::uint32_t own_disk = kNoId;  // a centre: the disk whose arcs are all closest
  bool equidistance_proved = false;  // the closest corners' distances need no test
};

class Checker {
 public:
  Checker(const DiskUnionGeometry& geo, DiskAxisValidation& out) : geo_(geo), out_(out) {}

  void check(const Probe& p) {
    for (std::uint32_t q = 0; q < geo_.corners().size(); ++q) check_corner(p, q);
    for (const UnionArc& arc : geo_.arcs())
      if (arc.disk != p.own_disk) check_arc(p, arc);
  }

 private:
  // Certified sign: the interval when it decides, else the exact value.
  int decide(const Interval& quick, const std::function<ExactSum()>& exact) {
    ++out_.feature_tests;
    const int s = certified_sign(quick);
    if (s != kUndecided && s != 0) return s;
    ++out_.exact_decisions;
    return exact_sign(exact(), &stats_);
  }

  void check_corner(const Probe& p, std::uint32_t q) {
    const UnionCorner& c = geo_.corners()[q];
    const bool closest = std::binary_search(p.closest.begin(), p.closest.end(), q);
    if (closest && p.equidistance_proved) return;
    const Interval quick = square(p.approx.x - c.approx.x) + square(p.approx.y - c.approx.y) - p.r2_approx;
    const int s = decide(closest ? Interval(-1.0, 1.0) : quick, [&] {
      const ExactSum dx = p.x[0] - corner_x(c), dy = p.x[1] - corner_y(c);
      return multiply(dx, dx) + multiply(dy, dy) - p.r2();
    });
    if (closest && s != 0) fail(p.name + ": closest corner " + std::to_string(q) + " is not at distance R");
    if (!closest && s <= 0) fail(p.name + ": corner " + std::to_string(q) + " is at distance <= R");
  }

  // Is the direction u strictly inside the counter-clockwise arc from s to e (both relative
  // to the centre)?
  bool inside_arc(const std::array<ExactSum, 2>& u, const IntervalPoint2& ua, const UnionCorner& s,
                  const UnionCorner& e, const Disk& d) {
    auto rel = [&](const UnionCorner& c) {
      return std::array<ExactSum, 2>{corner_x(c) - ExactSum::rational(d.x), corner_y(c) - ExactSum::rational(d.y)};
    };
    auto rel_approx = [&](const UnionCorner& c) {
      return IntervalPoint2{c.approx.x - enclose(d.x), c.approx.y - enclose(d.y)};
    };
    auto cross = [&](const std::array<ExactSum, 2>& a, const IntervalPoint2& aa, const std::array<ExactSum, 2>& b,
                     const IntervalPoint2& ba) {
      return decide(aa.x * ba.y - aa.y * ba.x, [&] { return multiply(a[0], b[1]) - multiply(a[1], b[0]); });
    };
    const auto sr = rel(s), er = rel(e);
    const IntervalPoint2 sa = rel_approx(s), ea = rel_approx(e);
    const int after_start = cross(sr, sa, u, ua), before_end = cross(u, ua, er, ea);
    if (cross(sr, sa, er, ea) >= 0) return after_start > 0 && before_end > 0;  // arc of at most pi
    return after_start > 0 || before_end > 0;
  }

  void check_arc(const Probe& p, const UnionArc& arc) {
    const Disk& d = geo_.disks().disks[arc.disk];
    const std::array<ExactSum, 2> u{p.x[0] - ExactSum::rational(d.x), p.x[1] - ExactSum::rational(d.y)};
    const IntervalPoint2 ua{p.approx.x - enclose(d.x), p.approx.y - enclose(d.y)};
    auto d2 = [&] { return multiply(u[0], u[0]) + multiply(u[1], u[1]); };
    const Interval d2a = square(ua.x) + square(ua.y), r2a = enclose(d.r * d.r);
    const ExactSum r2 = ExactSum::rational(d.r * d.r);
    if (certified_sign(d2a) != 1 && exact_sign(d2(), &stats_) == 0) {
      // x at the centre: every point of the arc is at distance r.
      if (decide(r2a - p.r2_approx, [&] { return r2 - p.r2(); }) <= 0)
        fail(p.name + ": an arc of another disk is at distance <= R");
      return;
    }
    if (!inside_arc(u, ua, geo_.corners()[arc.start], geo_.corners()[arc.end], d)) return;
    // (|u| - r)^2 > R^2  <=>  A = |u|^2 + r^2 - R^2 > 2 r |u|  <=>  A > 0 and A^2 > 4 r^2 |u|^2.
    const Interval aa = d2a + r2a - p.r2_approx;
    auto a = [&] { return d2() + r2 - p.r2(); };
    const int sa = decide(aa, a);
    const int sq = sa > 0 ? decide(square(aa) - Interval(4.0) * r2a * d2a,
                                   [&] {
                                     const ExactSum av = a();
                                     return multiply(av, av) - multiply(ExactSum::rational(4 * d.r * d.r), d2());
                                   })
                          : -1;
    if (sq <= 0) fail(p.name + ": the arc of disk " + std::to_string(arc.disk) + " comes within R");
  }

  void fail(const std::string& what) {
    if (out_.failures.size() < 20) out_.failures.push_back(what);
  }

  const DiskUnionGeometry& geo_;
  DiskAxisValidation& out_;
  NumberStats stats_;
};

Probe node_probe(const MedialGraph& g, const DiskUnionGeometry& geo, std::uint32_t n) {
  const UnionNodeData& data = geo.node_data(n);
  Probe p;
  p.name = "node " + std::to_string(n);
  p.x = geo.exact_position(n);
  p.approx = geo.position_enclosure(n);
  p.r2 = [&geo, n] { return geo.exact_squared_radius(n); };
  p.r2_approx = square(g.node(n).radius);
  p.closest = data.corners;
  if (data.kind == UnionNodeKind::Center) p.own_disk = data.disk;
  return p;
}

Probe midpoint_probe(const MedialGraph& g, const DiskUnionGeometry& geo, std::uint32_t e) {
  const MedialEdge& edge = g.edge(e);
  const UnionEdgeData& data = geo.edge_data(e);
  Probe p;
  p.name = "midpoint of edge " + std::to_string(e);
  const auto &xu = geo.exact_position(edge.u), &xv = geo.exact_position(edge.v);
  for (int k = 0; k < 2; ++k) {
    p.x[k] = xu[k] + xv[k];
    p.x[k].scale(mpq_class(1, 2));
  }
  const IntervalPoint2 au = geo.position_enclosure(edge.u), av = geo.position_enclosure(edge.v);
  p.approx = {half(au.x + av.x), half(au.y + av.y)};
  const UnionCorner& a = geo.corners()[data.a];
  p.r2 = [x = p.x, &a] {
    const ExactSum dx = x[0] - corner_x(a), dy = x[1] - corner_y(a);
    return multiply(dx, dx) + multiply(dy, dy);
  };
  p.r2_approx = square(p.approx.x - a.approx.x) + square(p.approx.y - a.approx.y);
  p.closest = {std::min(data.a, data.b), std::max(data.a, data.b)};
  // Both ends are at distance R from a and b (checked at the nodes), so every point of the
  // segment is on the bisector of a and b: equidistant.
  p.equidistance_proved = true;
  return p;
}

}  // namespace

DiskAxisValidation validate_disk_union_axis(const MedialGraph& g, const DiskUnionAxisReport& report) {
  DiskAxisValidation out;
  const auto* geo = dynamic_cast<const DiskUnionGeometry*>(&g.geometry());
  if (!geo) {
    out.failures.push_back("the graph was not built by disk_union_axis");
    return out;
  }
  Checker checker(*geo, out);
  for (std::uint32_t n = 0; n < g.node_count(); ++n) {
    const UnionNodeData& data = geo->node_data(n);
    const std::size_t arcs = std::count_if(geo->arcs().begin(), geo->arcs().end(),
                                           [&](const UnionArc& a) { return a.disk == data.disk; });
    if (data.kind == UnionNodeKind::Center && g.degree(n) != arcs)
      out.failures.push_back("node " + std::to_string(n) + ": a centre with " + std::to_string(arcs) +
                             " arcs has degree " + std::to_string(g.degree(n)));
    if (data.kind == UnionNodeKind::Vertex && (g.degree(n) < 3 || data.corners.size() < 3))
      out.failures.push_back("node " + std::to_string(n) + ": a Voronoi vertex of degree " +
                             std::to_string(g.degree(n)));
    checker.check(node_probe(g, *geo, n));
    ++out.nodes_checked;
  }
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const UnionEdgeData& data = geo->edge_data(e);
    for (std::uint32_t end : {g.edge(e).u, g.edge(e).v}) {
      const std::vector<std::uint32_t>& c = geo->node_data(end).corners;
      if (!std::binary_search(c.begin(), c.end(), data.a) || !std::binary_search(c.begin(), c.end(), data.b))
        out.failures.push_back("edge " + std::to_string(e) + ": its corners are not closest to node " +
                               std::to_string(end));
    }
    checker.check(midpoint_probe(g, *geo, e));
    ++out.edges_checked;
  }
  if (g.component_count() != report.union_components || g.cycle_rank() != report.union_holes)
    out.failures.push_back("the axis has b0 = " + std::to_string(g.component_count()) + ", b1 = " +
                           std::to_string(g.cycle_rank()) + "; the union has b0 = " +
                           std::to_string(report.union_components) + ", b1 = " + std::to_string(report.union_holes));
  return out;
}

}  // namespace grassfire
