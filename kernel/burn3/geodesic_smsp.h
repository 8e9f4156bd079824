// geodesic_smsp.h -- multi-source geodesic distance with start times, by CGAL's
// Surface_mesh_shortest_path (Xin-Wang ICH), as an independent peer of the exact engine.
//
// Computes: on a triangle mesh (closed or open; manifold; double coordinates, Epick),
// for point sources s_i with start times t0_i, the function
//     T(x) = min over i of t0_i + d_geodesic(s_i, x)
// at arbitrary query points x: the burning time of the mesh burned as itself with point
// sources and no border ignition (point_sources.h; docs/design.md 5, reference case 3).
// CGAL's shortest-path tree has no per-source offsets, so the sources are grouped by
// t0 and each group gets its own sequence tree; T is the minimum over the groups of
// t0 + the group's distance. Points are (face, barycentric weights of the mesh
// triangle's three vertices in their order), or located on the mesh (the nearest point,
// by CGAL's AABB tree).
// Accuracy: double precision (CGAL with Epick: the kernel's constructions round); the
// exact engine is compared with it to that precision. +infinity where no source reaches
// (another component). CGAL 5.5.1 mishandles points on edges (issues #6681, #9646; the
// .cpp says how): a point at a vertex is passed as the vertex, and a point inside an edge,
// source or query, is moved 2^-40 of the way into its face, which changes T by at most
// 2^-40 times the distance to the face's opposite corner.
// Contract: a manifold triangle mesh (each edge on one or two faces, consistently
// oriented; std::invalid_argument otherwise); barycentric weights >= 0 summing to 1.
// Complexity: build O(n^2 log n) worst case, about O(n^1.5) in practice for n faces per
// group (CGAL's manual); a query O(1) after the build (O(log n) to locate a point).
// CGAL headers stay inside geodesic_smsp.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry3/exact_predicates3.h"
#include "geometry3/triangle_mesh.h"

namespace grassfire {

struct MeshPoint {
  std::uint32_t face = 0;
  std::array<double, 3> barycentric{};  // weights of mesh.triangles[face][0], [1], [2]
};

// The point of p.face at p's weights, exactly (every double is a rational; with dyadic
// weights such as k/8 this is the point CGAL is given), to locate on the mesh's complex
// (mesh_as_complex takes the same doubles exactly for meshes built in code, e.g. refined
// meshes; for a mesh read from text it takes the decimals written, io/decimal_text.h).
ExactPoint3 exact_mesh_point(const TriangleMesh3& mesh, const MeshPoint& p);

class SmspGeodesics {
 public:
  explicit SmspGeodesics(const TriangleMesh3& mesh);
  ~SmspGeodesics();
  SmspGeodesics(const SmspGeodesics&) = delete;
  SmspGeodesics& operator=(const SmspGeodesics&) = delete;

  // The nearest point of the mesh to p.
  MeshPoint locate(const std::array<double, 3>& p) const;
  void add_source(const MeshPoint& p, double t0);
  // Builds the sequence trees (once, before the first query; later sources need another build).
  void build();
  // min over sources of t0 + geodesic distance (build() must have run).
  double distance(const MeshPoint& q) const;
  std::size_t tree_count() const;
  double build_seconds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grassfire
