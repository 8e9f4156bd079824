// discrete_burning_field.cpp -- BT_t, directions and burning paths from the baseline.
#include "burn3/discrete/discrete_burning_field.h"

#include <cstdio>
#include <limits>

#include "geometry3/vec3.h"

namespace grassfire {

Vec3d edge_point(const MedialComplex& mc, std::uint32_t e, double s) {
  return v3::lerp(mc.vertex(mc.edge(e).v[0]).approx, mc.vertex(mc.edge(e).v[1]).approx, s);
}

double polyline_length(const std::vector<Vec3d>& path) {
  double sum = 0;
  for (std::size_t i = 1; i < path.size(); ++i) sum += v3::dist(path[i - 1], path[i]);
  return sum;
}

DiscreteBurningField::DiscreteBurningField(const MedialComplex& mc, const DiscreteBurning& burning, double chord_length)
    : mc_(mc),
      d_(burning),
      g_(mc, burning.spacing, std::numeric_limits<std::uint64_t>::max()),
      chord_(chord_length > 0 ? chord_length : 6 * burning.spacing) {}

std::string DiscreteBurningField::method() const {
  char buf[64];
  std::snprintf(buf, sizeof buf, "discrete h = %.6g", d_.spacing);
  return buf;
}

Vec3d DiscreteBurningField::position(std::uint32_t node) const {
  return is_source(node) ? d_.source_points[node - DiscreteBurning::kFromSource] : g_.position(node);
}

double DiscreteBurningField::node_bt(std::uint32_t node) const {
  return g_.is_vertex(node) ? d_.vertex_bt[node] : d_.steiner_bt[node - g_.vertex_count()];
}

DiscreteBurningField::Side DiscreteBurningField::own(std::uint32_t node) const {
  const std::uint32_t s = d_.burn_slot[node];
  if (s == kNoIndex) return {};
  if (s == DiscreteBurning::kIgnited) return {node_bt(node), kNoIndex};
  return {node_bt(node), d_.arrival_from[g_.slot(node, s)]};
}

// The arrival through link element `local` when it came before the point burned (the
// recorded arrivals are exactly those), else the point's own time and path.
DiscreteBurningField::Side DiscreteBurningField::through_slot(std::uint32_t node, std::uint32_t local) const {
  const std::uint64_t s = g_.slot(node, local);
  const double arrival = d_.arrival_time[s];
  const Side self = own(node);
  if (arrival < self.bt) return {arrival, d_.arrival_from[s]};
  return self;
}

DiscreteBurningField::Side DiscreteBurningField::through_triangle(std::uint32_t node, std::uint32_t t) const {
  if (g_.is_vertex(node)) return through_slot(node, mc_.corner_element(t, corner_of(mc_.triangle(t), node)));
  const auto& tris = mc_.edge_triangles(g_.edge_of(node));
  for (std::uint32_t j = 0; j < tris.size(); ++j)
    if (tris[j] == t) return through_slot(node, 2 + j);
  return own(node);
}

std::vector<std::uint32_t> DiscreteBurningField::boundary_nodes(std::uint32_t t) const {
  const ComplexTriangle& tr = mc_.triangle(t);
  std::vector<std::uint32_t> nodes(tr.v.begin(), tr.v.end());
  for (std::uint32_t e : tr.e)
    for (std::uint32_t i = 1; i <= g_.steiner_count(e); ++i) nodes.push_back(g_.steiner_node(e, i));
  return nodes;
}

std::vector<std::uint32_t> DiscreteBurningField::segment_nodes(std::uint32_t e) const {
  std::vector<std::uint32_t> nodes = {mc_.edge(e).v[0], mc_.edge(e).v[1]};
  for (std::uint32_t i = 1; i <= g_.steiner_count(e); ++i) nodes.push_back(g_.steiner_node(e, i));
  return nodes;
}

FieldSample DiscreteBurningField::best_of(const Vec3d& p, const std::vector<std::uint32_t>& nodes, std::uint32_t t,
                                          std::uint32_t* best_node, Side* best_side) const {
  FieldSample out;
  *best_node = kNoIndex;
  for (std::uint32_t y : nodes) {
    const Side side = t == kNoIndex ? own(y) : through_triangle(y, t);
    const double value = side.bt + v3::dist(p, g_.position(y));
    if (value < out.bt) out.bt = value, *best_node = y, *best_side = side;
  }
  if (t != kNoIndex) {
    const BorderFoot foot = nearest_ignition(t, p);
    if (foot.time < out.bt) {  // the fire came straight from t's border
      out.bt = foot.time;
      out.from = foot.point;
      out.direction = v3::unit(v3::sub(p, foot.point));
      out.started = out.direction == Vec3d{0, 0, 0};
      *best_node = kNoIndex;
      return out;
    }
  }
  if (*best_node == kNoIndex) return out;
  out.from = g_.position(*best_node);
  Vec3d at = p;
  double left = chord_;
  if (v3::dist(p, out.from) > 0) at = chord_step(at, out.from, left);
  const Vec3d start = left > 0 ? chord_start(at, best_side->next, left) : at;
  out.direction = v3::unit(v3::sub(p, start));
  out.started = out.direction == Vec3d{0, 0, 0};
  return out;
}

// Walks from `at` towards q by at most `left`; returns where it stops.
Vec3d DiscreteBurningField::chord_step(const Vec3d& at, const Vec3d& q, double& left) {
  const double step = v3::dist(at, q);
  if (step >= left) {
    const Vec3d stop = v3::lerp(at, q, left / step);
    left = 0;
    return stop;
  }
  left -= step;
  return q;
}

// The point `left` further back from `at` along the path through `node` and node's own
// burning path (or the path's end when it is shorter).
Vec3d DiscreteBurningField::chord_start(Vec3d at, std::uint32_t node, double left) const {
  for (std::uint64_t guard = 0; node != kNoIndex && left > 0 && guard <= g_.node_count(); ++guard) {
    at = chord_step(at, position(node), left);
    node = is_source(node) ? kNoIndex : own(node).next;
  }
  return at;
}

// min over the border edges b of t of min over y in b of f(y) + |p - y|: f is linear or a
// distance to a point along b, so the sum is convex in y's parameter and a golden-section
// search finds it (to 1e-12 of |b|). The graph points of b carry f only at themselves.
DiscreteBurningField::BorderFoot DiscreteBurningField::nearest_ignition(std::uint32_t t, const Vec3d& p) const {
  BorderFoot best;
  for (std::uint32_t e : mc_.triangle(t).e) {
    if (mc_.edge(e).stratum != EdgeStratum::Border || mc_.edge(e).rule == IgnitionRule::Never) continue;
    auto cost = [&](double s) { return mc_.ignition_on_edge(e, s) + v3::dist(p, edge_point(mc_, e, s)); };
    const double phi = (std::sqrt(5.0) - 1) / 2;
    double lo = 0, hi = 1, a = hi - phi * (hi - lo), b = lo + phi * (hi - lo), fa = cost(a), fb = cost(b);
    for (int i = 0; i < 60; ++i) {
      if (fa <= fb)
        hi = b, b = a, fb = fa, a = hi - phi * (hi - lo), fa = cost(a);
      else
        lo = a, a = b, fa = fb, b = lo + phi * (hi - lo), fb = cost(b);
    }
    for (double s : {0.0, (lo + hi) / 2, 1.0})
      if (cost(s) < best.time) best = {cost(s), edge_point(mc_, e, s)};
  }
  return best;
}

FieldSample DiscreteBurningField::sample_in_triangle(std::uint32_t t, const Vec3d& p) const {
  std::uint32_t node;
  Side side;
  return best_of(p, boundary_nodes(t), t, &node, &side);
}

FieldSample DiscreteBurningField::sample_on_segment(std::uint32_t e, double s) const {
  std::uint32_t node;
  Side side;
  return best_of(edge_point(mc_, e, s), segment_nodes(e), kNoIndex, &node, &side);
}

// Follows the burning slots back to an ignited graph point; at most one step per graph
// point (BT strictly decreases along a path up to ties, and a graph point is burned once).
void DiscreteBurningField::append_path(std::uint32_t node, std::vector<Vec3d>& path) const {
  for (std::uint64_t guard = 0; node != kNoIndex && guard <= g_.node_count(); ++guard) {
    path.push_back(position(node));
    node = is_source(node) ? kNoIndex : own(node).next;
  }
}

std::vector<Vec3d> DiscreteBurningField::path_in_triangle(std::uint32_t t, const Vec3d& p) const {
  std::uint32_t node;
  Side side;
  const FieldSample s = best_of(p, boundary_nodes(t), t, &node, &side);
  std::vector<Vec3d> path = {p};
  if (!std::isfinite(s.bt)) return path;
  if (node == kNoIndex) {  // straight from t's border
    if (v3::dist(p, s.from) > 0) path.push_back(s.from);
    return path;
  }
  if (v3::dist(p, g_.position(node)) > 0) path.push_back(g_.position(node));
  append_path(side.next, path);
  return path;
}

std::vector<Vec3d> DiscreteBurningField::path_on_segment(std::uint32_t e, double s) const {
  const Vec3d p = edge_point(mc_, e, s);
  std::uint32_t node;
  Side side;
  const FieldSample sample = best_of(p, segment_nodes(e), kNoIndex, &node, &side);
  std::vector<Vec3d> path = {p};
  if (node == kNoIndex || !std::isfinite(sample.bt)) return path;
  if (v3::dist(p, g_.position(node)) > 0) path.push_back(g_.position(node));
  append_path(side.next, path);
  return path;
}

std::vector<Vec3d> DiscreteBurningField::path_from_vertex(std::uint32_t v) const {
  std::vector<Vec3d> path;
  append_path(v, path);
  return path;
}

std::vector<Vec3d> DiscreteBurningField::path_from_edge_point(std::uint32_t e, std::uint32_t i) const {
  std::vector<Vec3d> path;
  const std::uint32_t n = g_.steiner_count(e);
  append_path(i == 0 ? mc_.edge(e).v[0] : i == n + 1 ? mc_.edge(e).v[1] : g_.steiner_node(e, i), path);
  return path;
}

}  // namespace grassfire
