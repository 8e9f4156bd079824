// mesh_poles.h -- the inner polar balls of a sampled closed triangle mesh (2.1.2): a union
// of balls that approximates the solid, whose exact medial axis approximates the solid's.
//
// Computes: samples of the mesh (its vertices, plus with subdivision S > 1 the points of
// barycentric coordinates (i, j, k) / S on every triangle, shared points merged exactly),
// their Delaunay triangulation (CGAL, exact), and for each sample s the inner pole: the
// Voronoi vertex of s's cell farthest from s among those on the inner side of the outward
// normal at s (Amenta, Choi, Kolluri 2001, the power crust). Each inner pole p, kept when
// it lies strictly inside the mesh (exact ray-parity test, CGAL Side_of_triangle_mesh),
// gives the ball B(p, |p - s|), which is empty of samples. Poles shared by several samples
// are merged (their balls are equal).
// Guarantee: for an epsilon-sample of a smooth surface with epsilon small, the union of the
// inner polar balls converges to the solid in Hausdorff distance and its medial axis to
// the solid's (Amenta-Choi-Kolluri 2001; Tam-Heidrich 2003 take its exact axis as here);
// for meshes with sharp edges the theorem does not apply and the subdivision only helps.
// Measured here: `protrusion` certifies max over balls of (r - dist(centre, mesh)), how far
// the union leaves the solid (exact squared distances, CGAL AABB tree on the exact kernel);
// `uncovered` estimates (doubles, at triangle centroids) how far the mesh lies outside.
// Contract: a closed, consistently oriented 2-manifold (mesh_checks.h; errors name the file
// and the first offending edge); subdivision >= 1.
// Complexity: O(n log n) expected for the triangulation of n samples, O(log F) per pole
// for the inside test and the distance.
#pragma once

#include <cstddef>

#include "complex3/ball_set.h"
#include "complex3/triangle_mesh.h"

namespace grassfire {

struct MeshPolesOptions {
  int subdivision = 1;  // S: edges split into S parts (1 = the mesh vertices only)
};

struct MeshPoles {
  BallSet balls;                 // centres = inner poles, w = squared polar radius
  std::size_t samples = 0;
  std::size_t poles_outside = 0;  // inner-side poles rejected: not strictly inside the mesh
  std::size_t samples_without_pole = 0;
  double protrusion = 0;          // certified upper bound of max (r - dist(centre, mesh))
  double uncovered = 0;           // estimate: max over triangle centroids of dist(y, union)
};

MeshPoles inner_polar_balls(const TriangleMesh3& mesh, const MeshPolesOptions& options = {});

}  // namespace grassfire
