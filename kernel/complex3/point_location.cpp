// point_location.cpp -- see point_location.h.
#include "complex3/point_location.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry3/closest_point3.h"
#include "geometry3/filtered_predicates3.h"

namespace grassfire {
namespace {

// A certified enclosure of q: the point itself when q is a double, else its neighbourhood;
// the whole line beyond the filter's range (such cells are never pruned).
Interval enclosure(const mpq_class& q) {
  const CoordinateEnclosure e = enclose_coordinate(q);
  if (!e.usable) return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  return e.value;
}

std::array<Interval, 3> enclosure(const ExactPoint3& p) { return {enclosure(p.x), enclosure(p.y), enclosure(p.z)}; }

std::array<Interval, 3> box_of(const std::vector<IntervalPoint3>& points, std::initializer_list<std::uint32_t> ids) {
  std::array<Interval, 3> box = points[*ids.begin()];
  for (std::uint32_t v : ids)
    for (int i = 0; i < 3; ++i) box[i] = hull(box[i], points[v][i]);
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

double point_upper_bound(const std::array<Interval, 3>& qi, const IntervalPoint3& pi) {
  return (square(pi[0] - qi[0]) + square(pi[1] - qi[1]) + square(pi[2] - qi[2])).hi;
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
  vertex_box_.reserve(mc.vertex_count());
  for (const ComplexVertex& v : mc.vertices()) vertex_box_.push_back(enclosure(v.exact));
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    const ComplexTriangle& tr = mc.triangle(t);
    cells_.push_back({2, t, box_of(vertex_box_, {tr.v[0], tr.v[1], tr.v[2]})});
  }
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    if (mc.edge(e).stratum == EdgeStratum::Dangling) {
      const ComplexEdge& edge = mc.edge(e);
      cells_.push_back({1, e, box_of(vertex_box_, {edge.v[0], edge.v[1]})});
    }
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (mc.vertex_edges(v).empty()) cells_.push_back({0, v, box_of(vertex_box_, {v})});
  std::vector<BoxTree3::Box> boxes;
  boxes.reserve(cells_.size());
  for (const Cell& c : cells_) boxes.push_back(c.box);
  tree_ = std::make_unique<BoxTree3>(boxes);
}

ComplexLocator::~ComplexLocator() = default;

std::uint32_t ComplexLocator::corner(const Cell& c) const {
  return c.dimension == 2 ? mc_.triangle(c.id).v[0] : c.dimension == 1 ? mc_.edge(c.id).v[0] : c.id;
}

Interval ComplexLocator::enclosed_distance(const Cell& c, const IntervalPoint3& qi, double box_lower) const {
  std::optional<Interval> d;
  if (c.dimension == 2) {
    const auto& v = mc_.triangle(c.id).v;
    d = closest_squared_distance(vertex_box_[v[0]], vertex_box_[v[1]], vertex_box_[v[2]], qi);
  } else if (c.dimension == 1) {
    const auto& v = mc_.edge(c.id).v;
    d = closest_squared_distance(vertex_box_[v[0]], vertex_box_[v[1]], qi);
  }
  Interval out(box_lower, point_upper_bound(qi, vertex_box_[corner(c)]));
  if (d) out = {std::max(out.lo, d->lo), std::min(out.hi, d->hi)};
  return out;
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

// The nearest cell under exact comparison, ties to the lower cell index, among the
// candidates whose certified lower bound does not exceed every exact distance found.
ComplexPoint ComplexLocator::nearest_of(std::vector<std::pair<double, std::size_t>>& order, const ExactPoint3& q) const {
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

ComplexPoint ComplexLocator::locate(const ExactPoint3& q) const {
  const IntervalPoint3 qi = enclosure(q);
  double best_upper = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, std::size_t>> order;  // (certified lower bound, cell)
  tree_->best_first([&](const BoxTree3::Box& box) { return box_lower_bound(qi, box); },
                    [&](std::uint32_t i) {
                      const double box_lower = box_lower_bound(qi, cells_[i].box);
                      if (box_lower > best_upper) return;
                      const Interval d = enclosed_distance(cells_[i], qi, box_lower);
                      best_upper = std::min(best_upper, d.hi);
                      if (d.lo <= best_upper) order.emplace_back(d.lo, i);
                    },
                    [&] { return best_upper; });
  // Certified exclusion: a cell whose lower bound exceeds some cell's upper bound is farther.
  order.erase(std::remove_if(order.begin(), order.end(), [&](const auto& o) { return o.first > best_upper; }),
              order.end());
  return nearest_of(order, q);
}

ComplexPoint ComplexLocator::locate_by_scan(const ExactPoint3& q) const {
  const IntervalPoint3 qi = enclosure(q);
  double best_upper = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, std::size_t>> order;  // (lower bound, cell), cells in their order
  order.reserve(cells_.size());
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    best_upper = std::min(best_upper, point_upper_bound(qi, vertex_box_[corner(cells_[i])]));
    order.emplace_back(box_lower_bound(qi, cells_[i].box), i);
  }
  order.erase(std::remove_if(order.begin(), order.end(), [&](const auto& o) { return o.first > best_upper; }),
              order.end());
  return nearest_of(order, q);
}

}  // namespace grassfire
