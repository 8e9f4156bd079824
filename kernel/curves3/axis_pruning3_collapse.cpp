// axis_pruning3_collapse.cpp -- the homotopy-preserving removal of failing simplices of K
// (axis_pruning3.h): elementary collapses from the free border inward, in the fire's order.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <tuple>

#include "curves3/axis_pruning3_detail.h"

namespace grassfire::pruning3 {
namespace {

// A pending elementary collapse: the larger simplex (a triangle, or an edge with no triangle
// left) with its free face (an edge, or a vertex). Ordered by the fire's key, then kind and
// ids (deterministic).
struct Collapse {
  double key;
  int kind;  // 0: (triangle, edge), 1: (edge, vertex)
  std::uint32_t larger, face;
  bool operator>(const Collapse& o) const {
    return std::tie(key, kind, larger, face) > std::tie(o.key, o.kind, o.larger, o.face);
  }
};

class Collapser {
 public:
  explicit Collapser(Refined& k) : k_(k) {
    edge_triangles_.resize(k.edges.size());
    vertex_edges_.resize(k.vertices.size());
    for (std::uint32_t t = 0; t < k.triangles.size(); ++t)
      for (std::uint32_t e : k.triangles[t].e) edge_triangles_[e].push_back(t);
    for (std::uint32_t e = 0; e < k.edges.size(); ++e)
      for (std::uint32_t v : k.edges[e].v) vertex_edges_[v].push_back(e);
    triangles_left_.resize(k.edges.size());
    edges_left_.resize(k.vertices.size());
    for (std::uint32_t e = 0; e < k.edges.size(); ++e) triangles_left_[e] = edge_triangles_[e].size();
    for (std::uint32_t v = 0; v < k.vertices.size(); ++v) edges_left_[v] = vertex_edges_[v].size();
    triangle_alive_.assign(k.triangles.size(), true);
    edge_alive_.assign(k.edges.size(), true);
    vertex_alive_.assign(k.vertices.size(), true);
  }

  void run(Pruning3Stats& stats) {
    for (std::uint32_t e = 0; e < k_.edges.size(); ++e) consider_edge(e);
    for (std::uint32_t v = 0; v < k_.vertices.size(); ++v) consider_vertex(v);
    // Each pop removes a pair or is stale; pushes are bounded by the incidences.
    while (!queue_.empty()) {
      const Collapse c = queue_.top();
      queue_.pop();
      if (c.kind == 0 && valid_triangle_collapse(c.larger, c.face)) {
        remove_triangle(c.larger, c.face);
        ++stats.removed_triangles, ++stats.removed_edges;
      } else if (c.kind == 1 && valid_edge_collapse(c.larger, c.face)) {
        remove_edge(c.larger, c.face);
        ++stats.removed_edges, ++stats.removed_vertices;
      }
    }
  }

  bool triangle_alive(std::uint32_t t) const { return triangle_alive_[t]; }
  bool edge_alive(std::uint32_t e) const { return edge_alive_[e]; }
  bool vertex_alive(std::uint32_t v) const { return vertex_alive_[v]; }
  std::size_t triangles_left(std::uint32_t e) const { return triangles_left_[e]; }

 private:
  double bt_key(std::initializer_list<std::uint32_t> vs) const {
    double key = -std::numeric_limits<double>::infinity();
    for (std::uint32_t v : vs) key = std::max(key, k_.vertices[v].info.bt);
    return key;
  }
  bool valid_triangle_collapse(std::uint32_t t, std::uint32_t e) const {
    return triangle_alive_[t] && edge_alive_[e] && k_.triangles[t].fails && k_.edges[e].fails && triangles_left_[e] == 1;
  }
  bool valid_edge_collapse(std::uint32_t e, std::uint32_t v) const {
    return edge_alive_[e] && vertex_alive_[v] && k_.edges[e].fails && k_.vertices[v].info.fails &&
           triangles_left_[e] == 0 && edges_left_[v] == 1;
  }
  // Edge e became free (one triangle left) or bare (none left): queue what it allows.
  void consider_edge(std::uint32_t e) {
    if (!edge_alive_[e]) return;
    if (triangles_left_[e] == 1) {
      for (std::uint32_t t : edge_triangles_[e])
        if (valid_triangle_collapse(t, e)) {
          const RefinedTriangle3& tr = k_.triangles[t];
          queue_.push({bt_key({tr.v[0], tr.v[1], tr.v[2]}), 0, t, e});
        }
    } else if (triangles_left_[e] == 0) {
      for (std::uint32_t v : k_.edges[e].v) consider_vertex(v);
    }
  }
  void consider_vertex(std::uint32_t v) {
    if (!vertex_alive_[v] || edges_left_[v] != 1) return;
    for (std::uint32_t e : vertex_edges_[v])
      if (valid_edge_collapse(e, v)) queue_.push({bt_key({k_.edges[e].v[0], k_.edges[e].v[1]}), 1, e, v});
  }
  void remove_triangle(std::uint32_t t, std::uint32_t free_edge) {
    triangle_alive_[t] = false;
    for (std::uint32_t e : k_.triangles[t].e) --triangles_left_[e];
    drop_edge(free_edge);
    for (std::uint32_t e : k_.triangles[t].e)
      if (e != free_edge) consider_edge(e);
  }
  void remove_edge(std::uint32_t e, std::uint32_t free_vertex) {
    vertex_alive_[free_vertex] = false;
    drop_edge(e);
  }
  void drop_edge(std::uint32_t e) {
    edge_alive_[e] = false;
    for (std::uint32_t v : k_.edges[e].v) {
      --edges_left_[v];
      consider_vertex(v);
    }
  }

  Refined& k_;
  std::vector<std::vector<std::uint32_t>> edge_triangles_, vertex_edges_;
  std::vector<std::size_t> triangles_left_, edges_left_;
  std::vector<bool> triangle_alive_, edge_alive_, vertex_alive_;
  std::priority_queue<Collapse, std::vector<Collapse>, std::greater<Collapse>> queue_;
};

void count_failing(const Refined& k, Pruning3Stats& s) {
  for (const RefinedVertex3& v : k.vertices) s.failing_vertices += v.info.fails ? 1 : 0;
  for (const RefinedEdge3& e : k.edges) s.failing_edges += e.fails ? 1 : 0;
  for (const RefinedTriangle3& t : k.triangles) s.failing_triangles += t.fails ? 1 : 0;
}

BettiNumbers refined_betti(const Refined& k) {
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (const RefinedEdge3& e : k.edges) edges.push_back(e.v);
  for (const RefinedTriangle3& t : k.triangles) triangles.push_back(t.v);
  return betti_numbers(k.vertices.size(), edges, triangles, {});
}

}  // namespace

PrunedAxis3 collapse(const MedialComplex& mc, Refined k) {
  PrunedAxis3 out;
  Pruning3Stats& s = out.stats;
  s.refined_vertices = k.vertices.size();
  s.refined_edges = k.edges.size();
  s.refined_triangles = k.triangles.size();
  s.cut_points = k.cut_points;
  count_failing(k, s);
  out.betti_refined = refined_betti(k);
  Collapser c(k);
  c.run(s);
  std::vector<std::uint32_t> id(k.vertices.size(), kNoIndex);
  RawComplex& raw = out.complex;
  raw.source = mc.source();
  for (std::uint32_t v = 0; v < k.vertices.size(); ++v) {
    if (!c.vertex_alive(v)) continue;
    id[v] = static_cast<std::uint32_t>(raw.vertices.size());
    raw.vertices.push_back(k.vertices[v].point);
    raw.radius_squared.push_back(k.vertices[v].radius_squared);
    out.vertices.push_back(k.vertices[v].info);
    s.kept_failing_vertices += k.vertices[v].info.fails ? 1 : 0;
  }
  for (std::uint32_t t = 0; t < k.triangles.size(); ++t) {
    if (!c.triangle_alive(t)) continue;
    const RefinedTriangle3& tr = k.triangles[t];
    raw.triangles.push_back({id[tr.v[0]], id[tr.v[1]], id[tr.v[2]]});
    s.kept_failing_triangles += tr.fails ? 1 : 0;
  }
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    if (!c.edge_alive(e)) continue;
    const RefinedEdge3& ed = k.edges[e];
    s.kept_failing_edges += ed.fails ? 1 : 0;
    const std::array<std::uint32_t, 2> v = {id[ed.v[0]], id[ed.v[1]]};
    if (c.triangles_left(e) == 0) raw.segments.push_back(v);
    // A border edge of the result keeps the ignition of the border edge of M it lies on.
    if (c.triangles_left(e) == 1 && ed.parent != kNoIndex) {
      const ComplexEdge& parent = mc.edge(ed.parent);
      if (parent.stratum == EdgeStratum::Border && parent.rule != IgnitionRule::Linear)
        raw.border_rules.push_back({v, parent.rule, parent.rule_point});
    }
  }
  out.betti_pruned = betti_numbers(raw);
  return out;
}

}  // namespace grassfire::pruning3
