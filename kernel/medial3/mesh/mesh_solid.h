// mesh_solid.h -- the solid a closed triangle mesh bounds: exact point location and the
// solid's Betti numbers, computed from the mesh alone.
//
// Computes:
//  - SolidLocator: whether a point lies inside the solid, on its boundary or outside, by
//    the even-odd rule (the parity of the number of boundary crossings of a ray), exactly:
//    the ray leaves the point in direction +x from the symbolically perturbed start
//    (y + eps, z + eps^2) (simulation of simplicity), so it never passes through an edge
//    or a vertex of the projected mesh and the two triangles of an edge always agree on
//    which of them it crosses. The point is on the boundary when it lies in a closed
//    triangle (exact coplanarity and containment). Decisions: a double interval filter on
//    the point's enclosure, then exact rationals (the exact point is asked for only then).
//  - solid_topology: the shells (edge-connected components of the mesh), the genus of each
//    from its Euler characteristic V - E + F = 2 - 2g, the nesting depth of each (how
//    many other shells enclose it, by SolidLocator), and the Betti numbers of the solid
//    under the even-odd rule: b0 = shells at even depth (outer boundaries of the solid's
//    components), b2 = shells at odd depth (boundaries of cavities: a hollow ball has
//    b2 = 1), b1 = the sum of the genera (chi(solid) = chi(boundary) / 2 for a compact
//    3-manifold, and b1 = b0 + b2 - chi). Independent of any medial axis.
// Contract: a closed 2-manifold mesh (mesh_checks.h: require_closed_manifold), shells
// disjoint (a vertex of one shell on another is reported as std::invalid_argument naming
// the file). Orientation is not used: the even-odd rule needs none.
// Complexity: a uniform grid over the (y, z) projection of the triangles' bounding boxes;
// a query visits the triangles of one grid cell, O(1) expected for well-shaped meshes.
// solid_topology is O(F log F + s^2 q) for s shells and q the cost of a query.
// Section: 2.1 (the shape whose medial axis is built), docs/design.md 3 (certified decisions).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "complex3/simplicial_homology.h"
#include "complex3/raw_complex.h"
#include "geometry3/triangle_mesh.h"
#include "number/interval.h"

namespace grassfire {

class SolidLocator {
 public:
  // The solid bounded by `triangles` of the mesh (all of them when empty).
  explicit SolidLocator(const TriangleMesh3& mesh, std::vector<std::uint32_t> triangles = {});

  // +1 inside, 0 on the boundary, -1 outside; exact.
  int locate(const ExactPoint3& p) const;
  // The same for a point given by an enclosure; `exact` is called only when the filter
  // cannot decide.
  int locate(const std::array<Interval, 3>& box, const std::function<ExactPoint3()>& exact) const;

  struct Stats {
    std::uint64_t queries = 0, triangle_tests = 0, exact_tests = 0;
  };
  const Stats& stats() const { return stats_; }

 private:
  struct Tri {
    std::array<std::array<double, 3>, 3> v;
    std::array<double, 3> lo, hi;
  };
  int locate_in(const std::array<Interval, 3>& box, const std::function<ExactPoint3()>& exact) const;
  template <class F>
  void visit_cells(const Interval& y, const Interval& z, F f) const;

  std::vector<Tri> tris_;
  std::array<double, 3> lo_{}, hi_{};
  double y0_ = 0, z0_ = 0, hy_ = 1, hz_ = 1;
  long ny_ = 1, nz_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
  mutable Stats stats_;
};

struct MeshShell {
  std::vector<std::uint32_t> triangles;
  std::size_t vertices = 0, edges = 0;
  long genus = 0;
  int depth = 0;  // number of other shells enclosing this one
};

struct SolidTopology {
  std::vector<MeshShell> shells;
  BettiNumbers betti;  // of the solid, by the even-odd rule
};

SolidTopology solid_topology(const TriangleMesh3& mesh);

}  // namespace grassfire
