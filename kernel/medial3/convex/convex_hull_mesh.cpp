// convex_hull_mesh.cpp -- random_convex_hull_mesh (see synthetic_meshes.h): CGAL's
// convex_hull_3 on integer points, kept apart from synthetic_meshes.cpp so that only this
// file pulls in the hull's headers.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <random>

#include "geometry3/synthetic_meshes.h"

namespace grassfire {

TriangleMesh3 random_convex_hull_mesh(std::uint32_t seed, int points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<K::Point_3> p;
  for (int i = 0; i < points; ++i) {
    double x = normal(rng), y = normal(rng), z = normal(rng);
    const double r = std::sqrt(x * x + y * y + z * z);
    if (r == 0) continue;
    // On the sphere of radius 8, rounded to integers: exact and in general enough position.
    p.emplace_back(std::round(8 * x / r), std::round(8 * y / r), std::round(8 * z / r));
  }
  CGAL::Surface_mesh<K::Point_3> hull;
  CGAL::convex_hull_3(p.begin(), p.end(), hull);
  TriangleMesh3 m;
  m.source = "random convex hull (seed " + std::to_string(seed) + ", " + std::to_string(points) + " points)";
  std::vector<std::uint32_t> id(hull.number_of_vertices() + hull.number_of_removed_vertices(), UINT32_MAX);
  for (auto v : hull.vertices()) {
    id[v.idx()] = static_cast<std::uint32_t>(m.vertices.size());
    const K::Point_3& q = hull.point(v);
    m.vertices.push_back({q.x(), q.y(), q.z()});
  }
  for (auto f : hull.faces()) {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) t[k++] = id[v.idx()];
    m.triangles.push_back(t);
  }
  return m;
}

}  // namespace grassfire
