// point_location.cpp -- see point_location.h.
#include "complex3/point_location.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace grassfire {
namespace {

Interval enclosure(const mpq_class& q) {
  const double d = q.get_d();  // within one ulp of q (mpq get_d truncates)
  if (!std::isfinite(d)) return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  return {round_down(d), round_up(d)};
}

std::array<Interval, 3> enclosure(const ExactPoint3& p) { return {enclosure(p.x), enclosure(p.y), enclosure(p.z)}; }

std::array<Interval, 3> box_of(const std::vector<const ExactPoint3*>& points) {
  std::array<Interval, 3> box = enclosure(*points[0]);
  for (const ExactPoint3* p : points) {
    const std::array<Interval, 3> e = enclosure(*p);
    for (int i = 0; i < 3; ++i) box[i] = hull(box[i], e[i]);
  }
  return box;
}

// Lower bound on the squared distance from q (enclosed by qi) to the box.
double box_lower_bound(const std::array<Interval, 3>& qi, const std::array<Interval, 3>& box) {
  Interval sum(0.0);
  for (int i = 0; i < 3; ++i) {
    if (qi[i].hi < box[i].lo) sum += square(Interval(box[i].lo) - Interval(qi[i].hi));
    else if (qi[i].lo > box[i].hi) sum += square(Interval(qi[i].lo) - Interval(box[i].hi));
  }
  return sum.lo;
}

double point_upper_bound(const std::array<Interval, 3>& qi, const ExactPoint3& p) {
  const std::array<Interval, 3> pi = enclosure(p);
  return (square(pi[0] - qi[0]) + square(pi[1] - qi[1]) + square(pi[2] - qi[2])).hi;
}

// Closest point of triangle abc to p as barycentric weights (Ericson 5.1.5, exact).
std::array<mpq_class, 3> closest_weights(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c,
                                         const ExactPoint3& p) {
  const ExactPoint3 ab = b - a, ac = c - a, ap = p - a;
  const mpq_class d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (sgn(d1) <= 0 && sgn(d2) <= 0) return {1, 0, 0};
  const ExactPoint3 bp = p - b;
  const mpq_class d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (sgn(d3) >= 0 && d4 <= d3) return {0, 1, 0};
  const mpq_class vc = d1 * d4 - d3 * d2;
  if (sgn(vc) <= 0 && sgn(d1) >= 0 && sgn(d3) <= 0) {
    const mpq_class v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const ExactPoint3 cp = p - c;
  const mpq_class d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (sgn(d6) >= 0 && d5 <= d6) return {0, 0, 1};
  const mpq_class vb = d5 * d2 - d1 * d6;
  if (sgn(vb) <= 0 && sgn(d2) >= 0 && sgn(d6) <= 0) {
    const mpq_class w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const mpq_class va = d3 * d6 - d5 * d4;
  if (sgn(va) <= 0 && sgn(d4 - d3) >= 0 && sgn(d5 - d6) >= 0) {
    const mpq_class w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const mpq_class denom = va + vb + vc;
  const mpq_class v = vb / denom, w = vc / denom;
  return {1 - v - w, v, w};
}

}  // namespace

double ComplexPoint::snap() const {
  const double d = std::sqrt(snap_squared.get_d());
  return sgn(snap_squared) == 0 ? 0.0 : d;
}

ComplexPoint point_on_edge(const MedialComplex& mc, std::uint32_t e, const mpq_class& s) {
  const ComplexEdge& edge = mc.edge(e);
  ComplexPoint x;
  if (sgn(s) == 0 || s == 1) {
    x.kind = ComplexPoint::Kind::Vertex;
    x.id = edge.v[sgn(s) == 0 ? 0 : 1];
    x.point = mc.vertex(x.id).exact;
    return x;
  }
  x.kind = ComplexPoint::Kind::Edge;
  x.id = e;
  x.parameter = s;
  const ExactPoint3& a = mc.vertex(edge.v[0]).exact;
  x.point = a + s * (mc.vertex(edge.v[1]).exact - a);
  return x;
}

ComplexPoint point_in_triangle(const MedialComplex& mc, std::uint32_t t, const std::array<mpq_class, 3>& w) {
  const ComplexTriangle& tr = mc.triangle(t);
  int zeros = 0, zero_at = -1, nonzero_at = -1;
  for (int i = 0; i < 3; ++i) (sgn(w[i]) == 0 ? (++zeros, zero_at) : nonzero_at) = i;
  ComplexPoint x;
  if (zeros == 2) {
    x.kind = ComplexPoint::Kind::Vertex;
    x.id = tr.v[nonzero_at];
    x.point = mc.vertex(x.id).exact;
    return x;
  }
  if (zeros == 1) {
    // On the edge opposite the zero weight; its parameter is the weight of its end v[1].
    const std::uint32_t e = tr.e[zero_at];
    return point_on_edge(mc, e, w[corner_of(tr, mc.edge(e).v[1])]);
  }
  x.kind = ComplexPoint::Kind::Triangle;
  x.id = t;
  x.barycentric = w;
  x.point = w[0] * mc.vertex(tr.v[0]).exact + w[1] * mc.vertex(tr.v[1]).exact + w[2] * mc.vertex(tr.v[2]).exact;
  return x;
}

std::vector<std::uint32_t> triangles_containing(const MedialComplex& mc, const ComplexPoint& x) {
  switch (x.kind) {
    case ComplexPoint::Kind::Vertex: return mc.vertex_triangles(x.id);
    case ComplexPoint::Kind::Edge: return mc.edge_triangles(x.id);
    case ComplexPoint::Kind::Triangle: return {x.id};
  }
  return {};
}

ComplexLocator::ComplexLocator(const MedialComplex& mc) : mc_(mc) {
  if (mc.vertex_count() == 0) throw std::invalid_argument(mc.source() + ": cannot locate points on an empty complex");
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    const ComplexTriangle& tr = mc.triangle(t);
    cells_.push_back({2, t, box_of({&mc.vertex(tr.v[0]).exact, &mc.vertex(tr.v[1]).exact, &mc.vertex(tr.v[2]).exact})});
  }
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    if (mc.edge(e).stratum == EdgeStratum::Dangling) {
      const ComplexEdge& edge = mc.edge(e);
      cells_.push_back({1, e, box_of({&mc.vertex(edge.v[0]).exact, &mc.vertex(edge.v[1]).exact})});
    }
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (mc.vertex_edges(v).empty()) cells_.push_back({0, v, box_of({&mc.vertex(v).exact})});
}

ComplexPoint ComplexLocator::closest_in(const Cell& c, const ExactPoint3& q) const {
  ComplexPoint x;
  if (c.dimension == 2) {
    const ComplexTriangle& tr = mc_.triangle(c.id);
    x = point_in_triangle(mc_, c.id, closest_weights(mc_.vertex(tr.v[0]).exact, mc_.vertex(tr.v[1]).exact,
                                                    mc_.vertex(tr.v[2]).exact, q));
  } else if (c.dimension == 1) {
    const ComplexEdge& edge = mc_.edge(c.id);
    const ExactPoint3& a = mc_.vertex(edge.v[0]).exact;
    const ExactPoint3 d = mc_.vertex(edge.v[1]).exact - a;
    const mpq_class s = dot(q - a, d) / dot(d, d);
    x = point_on_edge(mc_, c.id, sgn(s) < 0 ? mpq_class(0) : s > 1 ? mpq_class(1) : s);
  } else {
    x.kind = ComplexPoint::Kind::Vertex;
    x.id = c.id;
    x.point = mc_.vertex(c.id).exact;
  }
  x.snap_squared = squared_distance(x.point, q);
  return x;
}

ComplexPoint ComplexLocator::locate(const ExactPoint3& q) const {
  const std::array<Interval, 3> qi = enclosure(q);
  double best_upper = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, std::size_t>> order;  // (lower bound, cell), cells in their order
  order.reserve(cells_.size());
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const Cell& c = cells_[i];
    const std::uint32_t corner = c.dimension == 2 ? mc_.triangle(c.id).v[0] : c.dimension == 1 ? mc_.edge(c.id).v[0] : c.id;
    best_upper = std::min(best_upper, point_upper_bound(qi, mc_.vertex(corner).exact));
    order.emplace_back(box_lower_bound(qi, c.box), i);
  }
  // Certified exclusion: a cell whose lower bound exceeds some cell's upper bound is farther.
  order.erase(std::remove_if(order.begin(), order.end(), [&](const auto& o) { return o.first > best_upper; }),
              order.end());
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  ComplexPoint best;
  std::size_t best_cell = cells_.size();
  for (const auto& [lower, i] : order) {
    if (best_cell < cells_.size() && mpq_class(lower) > best.snap_squared) break;
    ComplexPoint x = closest_in(cells_[i], q);
    const int c = best_cell == cells_.size() ? -1 : cmp(x.snap_squared, best.snap_squared);
    if (c < 0 || (c == 0 && i < best_cell)) best = std::move(x), best_cell = i;
  }
  return best;
}

}  // namespace grassfire
