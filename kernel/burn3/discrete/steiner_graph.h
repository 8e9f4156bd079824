// steiner_graph.h -- the graph of the discrete burning baseline (docs/design.md 5).
//
// Computes: the graph points of a medial complex at Steiner spacing h (its vertices, and
// n_e = ceil(|e| / h) - 1 equally spaced points inside each edge e, at parameters
// i / (n_e + 1)), their positions, and the moves between them: along an edge between
// consecutive points, and across a triangle between a point of one of its edges and every
// point of another of its edges (vertices of the triangle are reached along its edges).
// Each move carries the link element through which it arrives at its end point (the
// "slot"): at a vertex, the index in MedialComplex::link_elements (the sector containing
// the triangle, or the direction of the edge); at a Steiner point of edge e, 0 / 1 for
// fire coming along e from the side of e.v[0] / e.v[1], and 2 + j for the j-th triangle of
// edge_triangles(e). Moves are symmetric: y is a neighbour of x iff x is one of y.
// Node ids: vertices first (0 .. V-1), then the Steiner points edge by edge.
// Contract: a validated MedialComplex; spacing > 0; at most max_points graph points
// (std::invalid_argument otherwise). Complexity: construction O(E); for_each_move from a
// point visits O(points on the boundary of its incident triangles).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "complex3/medial_complex.h"

namespace grassfire {

class SteinerGraph {
 public:
  SteinerGraph(const MedialComplex& mc, double spacing, std::uint64_t max_points);

  const MedialComplex& complex() const { return mc_; }
  double spacing() const { return spacing_; }
  std::uint32_t vertex_count() const { return nv_; }
  std::uint64_t node_count() const { return nv_ + first_steiner_.back(); }
  std::uint64_t steiner_total() const { return first_steiner_.back(); }
  const std::vector<std::uint64_t>& first_steiner() const { return first_steiner_; }
  std::uint32_t steiner_count(std::uint32_t e) const {
    return static_cast<std::uint32_t>(first_steiner_[e + 1] - first_steiner_[e]);
  }
  bool is_vertex(std::uint32_t node) const { return node < nv_; }
  std::uint32_t edge_of(std::uint32_t node) const { return steiner_edge_[node - nv_]; }
  // 1-based index of a Steiner point on its edge.
  std::uint32_t index_on_edge(std::uint32_t node) const {
    return static_cast<std::uint32_t>(node - nv_ - first_steiner_[edge_of(node)] + 1);
  }
  std::uint32_t steiner_node(std::uint32_t e, std::uint32_t i) const {
    return static_cast<std::uint32_t>(nv_ + first_steiner_[e] + i - 1);
  }
  double parameter(std::uint32_t e, std::uint32_t i) const { return static_cast<double>(i) / (steiner_count(e) + 1); }
  Vec3d position(std::uint32_t node) const;
  std::size_t slot_count(std::uint32_t node) const {
    return is_vertex(node) ? mc_.link_elements(node).size() : 2 + mc_.edge_triangles(edge_of(node)).size();
  }
  // Global index of slot `local` of `node` in one array over all slots: vertex v owns
  // [vertex_slot[v], vertex_slot[v + 1]); Steiner point i of edge e owns 2 + k slots from
  // edge_slot[e] + (i - 1)(2 + k), k = edge_triangles(e).size().
  std::uint64_t slot(std::uint32_t node, std::uint32_t local) const {
    if (is_vertex(node)) return vertex_slot_[node] + local;
    const std::uint32_t e = edge_of(node);
    return edge_slot_[e] + (index_on_edge(node) - 1) * (2 + mc_.edge_triangles(e).size()) + local;
  }
  std::uint64_t slot_total() const { return edge_slot_.back(); }
  const std::vector<std::uint64_t>& vertex_slots() const { return vertex_slot_; }
  const std::vector<std::uint64_t>& edge_slots() const { return edge_slot_; }

  // Calls f(neighbour, slot at the neighbour, length) for every move from `node`.
  template <class F>
  void for_each_move(std::uint32_t node, F&& f) const;
  // The same moves from a point p that is not a graph point (a point source): p inside
  // triangle t reaches every graph point on t's boundary through t; p inside edge e, at
  // parameter s strictly between the graph points lower and lower + 1 of e (0 and
  // steiner_count(e) + 1 are its ends), reaches those two along e, and through each
  // triangle of e the graph points on its two other edges and its third vertex.
  template <class F>
  void for_each_move_from_triangle_point(const Vec3d& p, std::uint32_t t, F&& f) const;
  template <class F>
  void for_each_move_from_edge_point(const Vec3d& p, std::uint32_t e, std::uint32_t lower, F&& f) const;
  // The graph point of edge e at index i (0 and steiner_count(e) + 1: its end vertices).
  std::uint32_t edge_point(std::uint32_t e, std::uint32_t i) const {
    if (i == 0) return mc_.edge(e).v[0];
    if (i == steiner_count(e) + 1) return mc_.edge(e).v[1];
    return steiner_node(e, i);
  }

 private:
  template <class F>
  void into_edge(const Vec3d& p, std::uint32_t e, std::uint32_t slot, F& f) const;
  template <class F>
  void across_triangle(const Vec3d& p, std::uint32_t t, int opposite_corner, F& f) const;
  static double distance(const Vec3d& a, const Vec3d& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  }

  const MedialComplex& mc_;
  double spacing_;
  std::uint32_t nv_;
  std::vector<std::uint64_t> first_steiner_;  // per edge, size E + 1
  std::vector<std::uint32_t> steiner_edge_;
  std::vector<std::uint32_t> tri_edge_pos_;   // position of triangle t in edge_triangles(t.e[c]), at 3 t + c
  std::vector<std::uint64_t> vertex_slot_, edge_slot_;
};

template <class F>
void SteinerGraph::into_edge(const Vec3d& p, std::uint32_t e, std::uint32_t slot, F& f) const {
  const std::uint32_t n = steiner_count(e);
  const Vec3d& a = mc_.vertex(mc_.edge(e).v[0]).approx;
  const Vec3d& b = mc_.vertex(mc_.edge(e).v[1]).approx;
  for (std::uint32_t i = 1; i <= n; ++i) {
    const double s = static_cast<double>(i) / (n + 1);
    const Vec3d q = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
    f(steiner_node(e, i), slot, distance(p, q));
  }
}

template <class F>
void SteinerGraph::for_each_move(std::uint32_t node, F&& f) const {
  if (is_vertex(node)) {
    const std::uint32_t v = node;
    const Vec3d& p = mc_.vertex(v).approx;
    for (std::uint32_t e : mc_.vertex_edges(v)) {
      const int j = mc_.edge(e).v[0] == v ? 0 : 1;
      const std::uint32_t n = steiner_count(e);
      const double step = mc_.edge(e).length / (n + 1);
      if (n > 0)
        f(steiner_node(e, j == 0 ? 1 : n), static_cast<std::uint32_t>(j), step);
      else
        f(mc_.edge(e).v[1 - j], mc_.edge_end_element(e, 1 - j), step);
    }
    for (std::uint32_t t : mc_.vertex_triangles(v)) {
      const int c = corner_of(mc_.triangle(t), v);
      into_edge(p, mc_.triangle(t).e[c], 2 + tri_edge_pos_[3 * t + c], f);
    }
    return;
  }
  const std::uint32_t e = edge_of(node), i = index_on_edge(node), n = steiner_count(e);
  const Vec3d p = position(node);
  const double step = mc_.edge(e).length / (n + 1);
  // Along the edge: the neighbour towards v[0] receives fire from its v[1] side (slot 1).
  if (i > 1)
    f(steiner_node(e, i - 1), 1u, step);
  else
    f(mc_.edge(e).v[0], mc_.edge_end_element(e, 0), step);
  if (i < n)
    f(steiner_node(e, i + 1), 0u, step);
  else
    f(mc_.edge(e).v[1], mc_.edge_end_element(e, 1), step);
  for (std::uint32_t t : mc_.edge_triangles(e)) {
    const ComplexTriangle& tr = mc_.triangle(t);
    across_triangle(p, t, tr.e[0] == e ? 0 : tr.e[1] == e ? 1 : 2, f);
  }
}

// From a point of edge t.e[c] (or inside t, then for every c): the vertex opposite and the
// Steiner points of the two other edges, through t.
template <class F>
void SteinerGraph::across_triangle(const Vec3d& p, std::uint32_t t, int c, F& f) const {
  const ComplexTriangle& tr = mc_.triangle(t);
  f(tr.v[c], mc_.corner_element(t, c), distance(p, mc_.vertex(tr.v[c]).approx));
  for (int d : {(c + 1) % 3, (c + 2) % 3}) into_edge(p, tr.e[d], 2 + tri_edge_pos_[3 * t + d], f);
}

template <class F>
void SteinerGraph::for_each_move_from_triangle_point(const Vec3d& p, std::uint32_t t, F&& f) const {
  const ComplexTriangle& tr = mc_.triangle(t);
  for (int c = 0; c < 3; ++c) {
    f(tr.v[c], mc_.corner_element(t, c), distance(p, mc_.vertex(tr.v[c]).approx));
    into_edge(p, tr.e[c], 2 + tri_edge_pos_[3 * t + c], f);
  }
}

template <class F>
void SteinerGraph::for_each_move_from_edge_point(const Vec3d& p, std::uint32_t e, std::uint32_t lower, F&& f) const {
  const std::uint32_t n = steiner_count(e);
  const std::uint32_t below = edge_point(e, lower), above = edge_point(e, lower + 1);
  // Fire along e reaches the point below from its v[1] side and the point above from its v[0] side.
  f(below, lower == 0 ? mc_.edge_end_element(e, 0) : 1u, distance(p, position(below)));
  f(above, lower + 1 == n + 1 ? mc_.edge_end_element(e, 1) : 0u, distance(p, position(above)));
  for (std::uint32_t t : mc_.edge_triangles(e)) {
    const ComplexTriangle& tr = mc_.triangle(t);
    across_triangle(p, t, tr.e[0] == e ? 0 : tr.e[1] == e ? 1 : 2, f);
  }
}

}  // namespace grassfire
