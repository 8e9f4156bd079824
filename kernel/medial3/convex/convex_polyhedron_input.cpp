// convex_polyhedron_input.cpp -- convex meshes and seeded random cut cubes as ConvexPolyhedron
// (see convex_polyhedron_axis.h; half-space files: io/halfspace_list.h).
#include <map>
#include <random>
#include <stdexcept>
#include <tuple>

#include "medial3/convex/convex_polyhedron_axis.h"
#include "medial3/mesh/mesh_checks.h"
#include "geometry3/exact_predicates3.h"

namespace grassfire {

ConvexPolyhedron random_cut_cube(std::uint32_t seed) {
  static const int dirs[6][3] = {{3, 4, 0}, {0, 3, 4}, {4, 0, 3}, {1, 2, 2}, {2, 3, 6}, {12, 5, 0}};
  static const int length[6] = {5, 5, 5, 3, 7, 13};
  ConvexPolyhedron p;
  p.source = "cube cut at seed " + std::to_string(seed);
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {1, -1}) {
      mpq_class n[3] = {0, 0, 0};
      n[axis] = sign;
      p.planes.push_back({n[0], n[1], n[2], 2});
    }
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> cuts(1, 4), pick(0, 5), sign(0, 1);
  for (int k = cuts(rng); k > 0; --k) {
    const int d = pick(rng);
    int v[3];
    for (int i = 0; i < 3; ++i) v[i] = dirs[d][i] * (sign(rng) ? 1 : -1);
    std::uniform_int_distribution<int> offset(length[d], 2 * (std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2])) - 1);
    p.planes.push_back({v[0], v[1], v[2], offset(rng)});
  }
  return p;
}

namespace {

// The plane of a triangle scaled by a positive factor so that its first nonzero normal
// coordinate is +-1: coplanar, equally oriented triangles get equal keys.
std::tuple<mpq_class, mpq_class, mpq_class, mpq_class> canonical_plane(const ExactPoint3& n, const mpq_class& d) {
  const mpq_class& lead = sgn(n.x) != 0 ? n.x : sgn(n.y) != 0 ? n.y : n.z;
  const mpq_class f = 1 / abs(lead);
  return {n.x * f, n.y * f, n.z * f, d * f};
}

}  // namespace

ConvexPolyhedron convex_polyhedron_from_mesh(const TriangleMesh3& mesh) {
  require_closed_manifold(mesh);
  const int orientation_sign = mesh_orientation(mesh);
  if (orientation_sign == 0) throw std::invalid_argument(mesh.source + ": the mesh encloses zero volume");
  ConvexPolyhedron p;
  p.source = mesh.source;
  std::map<std::tuple<mpq_class, mpq_class, mpq_class, mpq_class>, std::size_t> facet_of_plane;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    auto tri = mesh.triangles[t];
    if (orientation_sign < 0) std::swap(tri[1], tri[2]);  // inside-out mesh: use outward order
    const auto& a = mesh.vertices[tri[0]];
    const auto& b = mesh.vertices[tri[1]];
    const auto& c = mesh.vertices[tri[2]];
    const ExactPoint3 ea = exact_point(a);
    const ExactPoint3 n = cross(exact_point(b) - ea, exact_point(c) - ea);
    if (is_zero(n)) continue;  // a degenerate triangle adds no facet plane
    // Convexity: no vertex strictly on the outer side of any triangle's plane.
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      if (orient3d(a, b, c, mesh.vertices[v]) > 0)
        throw std::invalid_argument(mesh.source + ": not convex: vertex " + std::to_string(v) +
                                    " lies outside the plane of triangle " + std::to_string(t));
    auto key = canonical_plane(n, dot(n, ea));
    if (facet_of_plane.emplace(key, p.planes.size()).second)
      p.planes.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), std::get<3>(key)});
  }
  return p;
}

}  // namespace grassfire
