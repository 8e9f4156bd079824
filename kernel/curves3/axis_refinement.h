// axis_refinement.h -- a triangulation K refining a medial complex M at a burning field's
// resolution, with the field sampled on it (the stage on which medial curves are built,
// medial_curves.h; 5.1.2).
//
// Computes K:
//  - vertices: M's vertices; on every edge e of M the field's points (BurningField::
//    edge_points(e), at parameters i / (n_e + 1)); inside every triangle t of M the
//    barycentric lattice points (j / L, k / L) with L = the largest n_e + 1 of t's edges
//    (spacing about the field's resolution along t's longest edge);
//  - triangles: per triangle t of M the Delaunay triangulation of its points in the affine
//    frame that maps t to the unit right triangle, with coordinates scaled to integers
//    (common denominator of the edge and lattice parameters), so that the points of one
//    edge of M are exactly collinear and consecutive ones are joined by an edge of K in
//    every triangle of that edge: K is conforming, and each triangle of K lies in one
//    triangle of M (its parent). Dangling segments of M are cut at their points.
//  - per vertex of K: position (doubles), R (exact at vertices of M, linear along edges
//    and inside triangles: an approximation of the medial radius), BT of the point (the
//    field's vertex or edge-point time; inside a triangle its sample);
//  - per triangle of K: the parent's side times BT_t at its three corners, and the fire's
//    direction sampled at its centroid (BurningField::sample_in_triangle);
//  - per edge of K: its incident triangles, and its parent cell (the edge of M it lies on,
//    or the triangle of M whose interior it crosses).
// Exactness: the combinatorics of K is exact (CGAL's filtered exact Delaunay predicates on
// integer coordinates); positions and field values are doubles, as the field gives them.
// Contract: a validated MedialComplex behind the field; the integer frame needs the common
// denominator of t's parameters below 2^52 (std::invalid_argument otherwise: the field's
// resolution is then far finer than any figure or study here needs).
// Complexity: O(sum over t of m_t log m_t) for m_t = the points of t (about (|t| / h)^2),
// plus one field sample per (point, incident triangle of M) and per triangle of K.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "burn3/burning_field.h"

namespace grassfire {

struct RefinedVertex {
  enum class On : std::uint8_t { Vertex, Edge, Triangle };
  Vec3d position{};
  On on = On::Vertex;
  std::uint32_t cell = 0;   // vertex, edge or triangle of M
  std::uint32_t index = 0;  // On::Edge: the point's index i on the edge
  // The point as a convex combination of its cell's vertices (exact rationals i / (n + 1)
  // and j / L in principle; their nearest doubles): On::Triangle, of the triangle's
  // corners v[0], v[1], v[2]; On::Edge, of the edge's ends v[0], v[1] (weight[2] = 0);
  // On::Vertex, {1, 0, 0}.
  std::array<double, 3> weight{1, 0, 0};
  double radius = 0;
  double bt = 0;
};

struct RefinedEdge {
  std::array<std::uint32_t, 2> v{};
  std::uint32_t on_edge = kNoIndex;      // the edge of M it lies on, or
  std::uint32_t in_triangle = kNoIndex;  // the triangle of M whose interior it crosses
  bool segment = false;                  // on a dangling segment of M
};

struct RefinedTriangle {
  std::array<std::uint32_t, 3> v{};
  std::array<std::uint32_t, 3> e{};  // e[i] opposite v[i]
  std::uint32_t parent = 0;
  std::array<double, 3> side_bt{};   // BT_parent at the corners
  Vec3d fire{};                      // direction of travel of the fire at the centroid
};

struct AxisRefinement {
  std::vector<RefinedVertex> vertices;
  std::vector<RefinedEdge> edges;
  std::vector<RefinedTriangle> triangles;
  std::vector<std::vector<std::uint32_t>> edge_triangles;  // per edge of K

  static AxisRefinement build(const BurningField& field);
  // Max over its corners of BT_parent: when the fire has swept the whole triangle.
  double burn_key(std::uint32_t t) const;
  double length(std::uint32_t e) const;
  double area(std::uint32_t t) const;
  Vec3d centroid(std::uint32_t t) const;
};

}  // namespace grassfire
