// planar_sheet_reference.cpp -- see planar_sheet_reference.h.
#include "burn3/planar_sheet_reference.h"

#include <algorithm>
#include <stdexcept>

#include "geometry3/exact_predicates3.h"

namespace grassfire {
namespace {

using Uv = std::array<mpq_class, 2>;

Uv operator-(const Uv& a, const Uv& b) { return {a[0] - b[0], a[1] - b[1]}; }
mpq_class cross(const Uv& a, const Uv& b) { return a[0] * b[1] - a[1] * b[0]; }
mpq_class dot(const Uv& a, const Uv& b) { return a[0] * b[0] + a[1] * b[1]; }

// The parameters t for which p + t d lies in the closed triangle (a, b, c), ccw: an
// interval [lo, hi] (lo absent: unbounded below), or empty.
struct Span {
  bool empty = false;
  std::optional<mpq_class> lo, hi;
};

Span span_in(const std::array<const Uv*, 3>& corner, const Uv& p, const Uv& d) {
  Span s;
  for (int i = 0; i < 3; ++i) {
    const Uv edge = *corner[(i + 1) % 3] - *corner[i];
    const mpq_class alpha = cross(edge, p - *corner[i]), beta = cross(edge, d);
    if (sgn(beta) == 0) {
      if (sgn(alpha) < 0) s.empty = true;
      continue;
    }
    const mpq_class t = -alpha / beta;
    if (sgn(beta) > 0) {
      if (!s.lo || t > *s.lo) s.lo = t;
    } else if (!s.hi || t < *s.hi) {
      s.hi = t;
    }
  }
  if (s.lo && s.hi && *s.lo > *s.hi) s.empty = true;
  return s;
}

Ball distance(const ExactPoint3& a, const ExactPoint3& b) { return sqrt(ball_of(squared_distance(a, b))); }

std::optional<Ball> smaller(const std::optional<Ball>& a, const std::optional<Ball>& b) {
  if (!a) return b;
  if (!b) return a;
  return min(*a, *b);
}

}  // namespace

PlanarSheetReference::PlanarSheetReference(const MedialComplex& mc, long bits) : mc_(mc), bits_(bits) {
  const std::string who = "planar sheet reference: " + mc.source();
  if (mc.sheets().size() != 1 || !mc.sheets()[0].planar) throw std::invalid_argument(who + " is not one planar sheet");
  if (mc.count(EdgeStratum::Dangling) > 0 || mc.count(EdgeStratum::Singular) > 0)
    throw std::invalid_argument(who + " has segments or singular edges");
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (mc.vertex_triangles(v).empty()) throw std::invalid_argument(who + ": vertex " + std::to_string(v) + " is on no triangle");
  const PlanarFrame& frame = mc.triangle_frame(0);
  for (const ComplexVertex& v : mc.vertices()) uv_.push_back(frame.local(v.exact));
  for (const ComplexTriangle& t : mc.triangles()) {
    std::array<std::uint32_t, 3> c = t.v;
    if (sgn(cross(uv_[c[1]] - uv_[c[0]], uv_[c[2]] - uv_[c[0]])) < 0) std::swap(c[1], c[2]);
    ccw_.push_back(c);
  }
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    const ComplexEdge& edge = mc.edge(e);
    if (edge.stratum != EdgeStratum::Border) continue;
    border_.push_back(e);
    ignited_.push_back({mc.vertex(edge.v[0]).exact, mc.vertex(edge.v[1]).exact, edge.rule,
                        mc.vertex(edge.v[0]).radius_squared, mc.vertex(edge.v[1]).radius_squared, edge.rule_point});
  }
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (is_node(v)) nodes_.push_back(v);
  // Node values: direct ignition, then n rounds of relaxation over the visibility graph.
  const BallPrecision precision(bits_);
  const std::size_t n = nodes_.size();
  std::vector<SheetPoint> points;
  for (std::uint32_t v : nodes_) points.push_back(vertex_point(v));
  std::vector<std::vector<char>> sees(n, std::vector<char>(n, 0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) sees[i][j] = sees[j][i] = visible(points[i], points[j]);
  for (std::size_t i = 0; i < n; ++i) node_value_.push_back(direct(points[i], sees[i]));
  for (std::size_t round = 0; round + 1 < n; ++round) {
    std::vector<std::optional<Ball>> next = node_value_;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (sees[i][j] && node_value_[j]) next[i] = smaller(next[i], *node_value_[j] + distance(points[i].p, points[j].p));
    node_value_ = std::move(next);
  }
}

bool PlanarSheetReference::is_node(std::uint32_t v) const {
  std::vector<std::uint32_t> border_ends;
  for (std::uint32_t e : mc_.vertex_edges(v))
    if (mc_.edge(e).stratum == EdgeStratum::Border) border_ends.push_back(mc_.edge(e).v[0] == v ? mc_.edge(e).v[1] : mc_.edge(e).v[0]);
  if (border_ends.empty()) return false;
  if (border_ends.size() != 2) return true;  // a pinch: several fans meet at v
  // Reflex: the direction opposite one border edge lies in the fan, and is not the other
  // border edge's direction (an angle of exactly pi).
  const Uv back = uv_[v] - uv_[border_ends[0]], other = uv_[border_ends[1]] - uv_[v];
  if (sgn(cross(back, other)) == 0 && sgn(dot(back, other)) > 0) return false;
  for (std::uint32_t t : mc_.vertex_triangles(v)) {
    const std::array<std::uint32_t, 3>& c = ccw_[t];
    const int i = c[0] == v ? 0 : c[1] == v ? 1 : 2;
    const Uv p = uv_[c[(i + 1) % 3]] - uv_[v], q = uv_[c[(i + 2) % 3]] - uv_[v];
    if (sgn(cross(p, back)) >= 0 && sgn(cross(back, q)) >= 0) return true;
  }
  return false;
}

PlanarSheetReference::SheetPoint PlanarSheetReference::sheet_point(const ComplexPoint& x) const {
  return {mc_.triangle_frame(0).local(x.point), x.point, triangles_containing(mc_, x)};
}

PlanarSheetReference::SheetPoint PlanarSheetReference::vertex_point(std::uint32_t v) const {
  return {uv_[v], mc_.vertex(v).exact, mc_.vertex_triangles(v)};
}

bool PlanarSheetReference::visible(const ComplexPoint& a, const ComplexPoint& b) const {
  return visible(sheet_point(a), sheet_point(b));
}

// Walks along from -> to through the triangles: from the triangle holding the current
// point in which the segment goes on, to its exit point; through an edge into the
// triangle across, through a vertex into one of the vertex's triangles that the segment
// enters. Blocked when no triangle continues it (a border edge or a border vertex).
bool PlanarSheetReference::visible(const SheetPoint& from, const SheetPoint& to) const {
  const Uv d = to.uv - from.uv;
  if (sgn(d[0]) == 0 && sgn(d[1]) == 0) return true;
  mpq_class t_now = 0;
  std::vector<std::uint32_t> candidates = from.triangles;
  for (std::size_t step = 0; step <= mc_.triangle_count() + 1; ++step) {
    std::optional<std::uint32_t> next;
    Span span;
    for (std::uint32_t t : candidates) {
      const std::array<std::uint32_t, 3>& c = ccw_[t];
      span = span_in({&uv_[c[0]], &uv_[c[1]], &uv_[c[2]]}, from.uv, d);
      if (!span.empty && (!span.lo || *span.lo <= t_now) && *span.hi > t_now) {
        next = t;
        break;
      }
    }
    if (!next) return false;
    if (*span.hi >= 1) return true;
    t_now = *span.hi;
    // The exit point lies on one edge of the triangle (inside it) or at a vertex: the
    // edge lines through it.
    const std::array<std::uint32_t, 3>& c = ccw_[*next];
    const Uv x = {from.uv[0] + t_now * d[0], from.uv[1] + t_now * d[1]};
    std::vector<int> on;
    for (int i = 0; i < 3; ++i)
      if (sgn(cross(uv_[c[(i + 1) % 3]] - uv_[c[i]], x - uv_[c[i]])) == 0) on.push_back(i);
    if (on.size() == 1) {
      const std::uint32_t e = mc_.find_edge(c[on[0]], c[(on[0] + 1) % 3]);
      candidates.clear();
      for (std::uint32_t t : mc_.edge_triangles(e))
        if (t != *next) candidates.push_back(t);
    } else {
      // Edge lines i and j meet at c[j] when j = i + 1, and at c[0] for lines 0 and 2.
      candidates = mc_.vertex_triangles(on[1] == on[0] + 1 ? c[on[1]] : c[on[0]]);
    }
  }
  throw std::logic_error("planar sheet reference: a visibility walk did not end");
}

std::optional<Ball> PlanarSheetReference::direct(const SheetPoint& x, const std::vector<char>& node_visible) const {
  std::optional<Ball> best;
  for (std::size_t k = 0; k < border_.size(); ++k) {
    if (ignited_[k].rule == IgnitionRule::Never) continue;
    const ComplexEdge& edge = mc_.edge(border_[k]);
    const Uv& a = uv_[edge.v[0]];
    const Uv& b = uv_[edge.v[1]];
    std::vector<mpq_class> cut = {0, 1};
    for (std::size_t j = 0; j < nodes_.size(); ++j) {
      if (!node_visible[j]) continue;
      const Uv w = uv_[nodes_[j]] - x.uv;
      const mpq_class oa = cross(w, a - x.uv), ob = cross(w, b - x.uv);
      if (oa == ob) continue;
      const mpq_class s = oa / (oa - ob);
      if (sgn(s) > 0 && s < 1) cut.push_back(s);
    }
    std::sort(cut.begin(), cut.end());
    cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
    auto point_at = [&](const mpq_class& s) -> SheetPoint {
      const ExactPoint3 p = ignited_[k].a + s * (ignited_[k].b - ignited_[k].a);
      const Uv uv = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])};
      if (sgn(s) == 0) return {uv, p, mc_.vertex_triangles(edge.v[0])};
      if (s == 1) return {uv, p, mc_.vertex_triangles(edge.v[1])};
      return {uv, p, mc_.edge_triangles(border_[k])};
    };
    // Maximal visible runs [cut[i], cut[j]]: pieces visible at their midpoint join their ends.
    std::size_t i = 0;
    while (i < cut.size()) {
      if (!visible(x, point_at(cut[i]))) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < cut.size() && visible(x, point_at((cut[j] + cut[j + 1]) / 2))) ++j;
      best = smaller(best, min_distance_plus_ignition(ignited_[k], x.p, cut[i], cut[j]));
      i = j + 1;
    }
  }
  return best;
}

std::optional<Ball> PlanarSheetReference::evaluate(const SheetPoint& x) const {
  std::vector<char> sees(nodes_.size(), 0);
  for (std::size_t j = 0; j < nodes_.size(); ++j) sees[j] = visible(x, vertex_point(nodes_[j]));
  std::optional<Ball> best = direct(x, sees);
  for (std::size_t j = 0; j < nodes_.size(); ++j)
    if (sees[j] && node_value_[j]) best = smaller(best, *node_value_[j] + distance(x.p, mc_.vertex(nodes_[j]).exact));
  return best;
}

Interval PlanarSheetReference::burning_time(const ComplexPoint& x) const {
  const BallPrecision precision(bits_);
  const std::optional<Ball> bt = evaluate(sheet_point(x));
  return bt ? bt->to_interval() : Interval::infinity();
}

}  // namespace grassfire
