// refined_mesh.cpp -- see refined_mesh.h. The only file with CGAL's subdivision headers.
#include "geometry3/refined_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "geometry3/exact_predicates3.h"

namespace grassfire {
namespace {

using Mesh = CGAL::Surface_mesh<CGAL::Epick::Point_3>;

ExactPoint3 exact(const std::array<double, 3>& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }

// Each vertex half way to the mean of its neighbours (along the mesh's edges).
void laplacian_step(TriangleMesh3& m) {
  std::vector<std::array<double, 3>> sum(m.vertices.size(), {0, 0, 0});
  std::vector<int> count(m.vertices.size(), 0);
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)  // each edge is seen from both faces: both ends count each neighbour twice
      for (int j : {(i + 1) % 3, (i + 2) % 3}) {
        for (int k = 0; k < 3; ++k) sum[t[i]][k] += m.vertices[t[j]][k];
        ++count[t[i]];
      }
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    if (count[v] > 0)
      for (int k = 0; k < 3; ++k) m.vertices[v][k] = 0.5 * m.vertices[v][k] + 0.5 * sum[v][k] / count[v];
}

}  // namespace

TriangleMesh3 loop_subdivided(const TriangleMesh3& given, int levels, int smoothing) {
  if (levels < 0 || smoothing < 0) throw std::invalid_argument("loop_subdivided: levels and smoothing must be >= 0");
  TriangleMesh3 input = given;
  for (int i = 0; i < smoothing; ++i) laplacian_step(input);
  Mesh mesh;
  for (const auto& v : input.vertices) mesh.add_vertex(CGAL::Epick::Point_3(v[0], v[1], v[2]));
  for (std::size_t f = 0; f < input.triangles.size(); ++f) {
    const auto& t = input.triangles[f];
    if (mesh.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2])) == Mesh::null_face())
      throw std::invalid_argument(input.source + ": face " + std::to_string(f) + " makes the mesh non-manifold");
  }
  if (levels > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
  TriangleMesh3 out;
  out.source = input.source + " (smoothed x" + std::to_string(smoothing) + ", Loop x" + std::to_string(levels) + ")";
  std::map<Mesh::Vertex_index, std::uint32_t> id;
  for (Mesh::Vertex_index v : mesh.vertices()) {
    id[v] = static_cast<std::uint32_t>(out.vertices.size());
    const auto& p = mesh.point(v);
    out.vertices.push_back({p.x(), p.y(), p.z()});
  }
  for (Mesh::Face_index f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[k++] = id[v];
    out.triangles.push_back(t);
  }
  return out;
}

int loop_levels_for(std::size_t faces, std::size_t target) {
  if (faces == 0 || target == 0) throw std::invalid_argument("loop_levels_for: faces and target must be > 0");
  int best = 0;
  double best_gap = std::abs(std::log(static_cast<double>(target) / static_cast<double>(faces)));
  for (int k = 1; k < 16; ++k) {
    const double gap = std::abs(std::log(static_cast<double>(target) / (static_cast<double>(faces) * std::pow(4.0, k))));
    if (gap < best_gap) best = k, best_gap = gap;
  }
  return best;
}

TriangleMesh3 refined_mesh(const TriangleMesh3& mesh, std::size_t target_faces) {
  return loop_subdivided(mesh, loop_levels_for(mesh.triangles.size(), target_faces), 2);
}

std::size_t coplanar_neighbour_pairs(const TriangleMesh3& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> third;  // edge -> opposite vertices
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) third[std::minmax(t[i], t[(i + 1) % 3])].push_back(t[(i + 2) % 3]);
  std::size_t count = 0;
  for (const auto& [e, opposite] : third)
    for (std::size_t i = 0; i < opposite.size(); ++i)
      for (std::size_t j = i + 1; j < opposite.size(); ++j)
        count += orientation(exact(mesh.vertices[e.first]), exact(mesh.vertices[e.second]),
                             exact(mesh.vertices[opposite[i]]), exact(mesh.vertices[opposite[j]])) == 0;
  return count;
}

}  // namespace grassfire
