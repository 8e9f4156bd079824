// mesh_perturbation.cpp -- vertices moved along their normals (see header).
#include "geometry3/mesh_perturbation.h"

#include <random>
#include <stdexcept>

#include "geometry3/vec3.h"

namespace grassfire {

TriangleMesh3 perturb_mesh(const TriangleMesh3& mesh, double amplitude, std::uint64_t seed) {
  if (!(amplitude >= 0)) throw std::invalid_argument(mesh.source + ": perturbation amplitude must be >= 0");
  std::vector<Vec3d> normal(mesh.vertices.size(), Vec3d{0, 0, 0});
  for (const auto& t : mesh.triangles) {
    const Vec3d area = v3::cross(v3::sub(mesh.vertices[t[1]], mesh.vertices[t[0]]), v3::sub(mesh.vertices[t[2]], mesh.vertices[t[0]]));
    for (std::uint32_t v : t) normal[v] = v3::add(normal[v], area);
  }
  TriangleMesh3 out = mesh;
  out.source = mesh.source + " (perturbed)";
  out.exact_vertices.clear();  // the moved doubles are the coordinates now
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    out.vertices[v] = v3::add(mesh.vertices[v], v3::scale(v3::unit(normal[v]), amplitude * u(rng)));
  return out;
}

double mesh_bounding_diagonal(const TriangleMesh3& mesh) {
  if (mesh.vertices.empty()) return 0;
  Vec3d lo = mesh.vertices[0], hi = lo;
  for (const Vec3d& p : mesh.vertices)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  return v3::dist(lo, hi);
}

}  // namespace grassfire
