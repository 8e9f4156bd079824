// mesh_checks.cpp -- see mesh_checks.h.
#include "medial3/mesh/mesh_checks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

#include "medial3/mesh/mesh_embedding.h"
#include "geometry3/exact_predicates3.h"
#include "support/number_text.h"

namespace grassfire {

namespace {

[[noreturn]] void reject(const TriangleMesh3& mesh, const std::string& problem) {
  throw std::invalid_argument(mesh.source + ": " + problem);
}

// Vertices and faces are named by their index in the file (TriangleMesh3::vertex_origin),
// with the point, which identifies a vertex in formats without vertex indices (STL).
std::string point_text(const std::array<double, 3>& p) {
  return "(" + shortest_double(p[0]) + ", " + shortest_double(p[1]) + ", " + shortest_double(p[2]) + ")";
}

std::string vertex_text(const TriangleMesh3& mesh, std::uint32_t v) {
  return "vertex " + std::to_string(file_vertex_index(mesh, v)) + " at " + point_text(mesh.vertices[v]);
}

std::string edge_text(const TriangleMesh3& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t t) {
  return "edge (" + std::to_string(file_vertex_index(mesh, a)) + ", " + std::to_string(file_vertex_index(mesh, b)) +
         ") from " + point_text(mesh.vertices[a]) + " to " + point_text(mesh.vertices[b]) + " of face " +
         std::to_string(file_face_index(mesh, t));
}

void require_distinct_used_vertices(const TriangleMesh3& mesh) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) used[v] = true;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v]) reject(mesh, vertex_text(mesh, v) + " is not used by any triangle");
  std::vector<std::uint32_t> order(mesh.vertices.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return mesh.vertices[a] < mesh.vertices[b]; });
  for (std::size_t i = 1; i < order.size(); ++i)
    if (mesh.vertices[order[i]] == mesh.vertices[order[i - 1]])
      reject(mesh, "duplicate vertices " + std::to_string(file_vertex_index(mesh, std::min(order[i], order[i - 1]))) +
                       " and " + std::to_string(file_vertex_index(mesh, std::max(order[i], order[i - 1]))) +
                       " (same position " + point_text(mesh.vertices[order[i]]) + ")");
}

// Each undirected edge once in each direction; returns the directed edge -> triangle map.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> require_paired_edges(const TriangleMesh3& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> directed;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      if (!directed.emplace(std::make_pair(a, b), t).second)
        reject(mesh, edge_text(mesh, a, b, t) + " is used twice in the same direction (inconsistent orientation or "
                                                "more than two triangles on the edge)");
    }
  for (const auto& [e, t] : directed)
    if (!directed.count({e.second, e.first}))
      reject(mesh, edge_text(mesh, e.first, e.second, t) + " has one triangle (the mesh is not closed)");
  return directed;
}

// The triangles around each vertex form one fan (no pinch): following b -> c over the
// link edges of the triangles (v, b, c) must close into a single cycle.
void require_single_fans(const TriangleMesh3& mesh) {
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> link(mesh.vertices.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) link[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
  for (std::uint32_t v = 0; v < link.size(); ++v) {
    std::map<std::uint32_t, std::uint32_t> next(link[v].begin(), link[v].end());
    std::uint32_t u = link[v].front().first;
    std::size_t steps = 0;
    do {
      u = next[u];
      ++steps;
    } while (u != link[v].front().first && steps <= link[v].size());
    if (steps != link[v].size())
      reject(mesh, vertex_text(mesh, v) + " is non-manifold (its triangles form more than one fan)");
  }
}

}  // namespace

ExactPoint3 exact_point(const std::array<double, 3>& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }

int orient3d(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
             const std::array<double, 3>& d) {
  // Shewchuk's orient3d with the static error bound o3derrboundA = (7 + 56 eps) eps,
  // eps = 2^-53, relative to the permanent of the difference matrix.
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
  const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
  const double det = adz * bc + bdz * ca + cdz * ab;
  const double permanent = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * std::fabs(adz) +
                           (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * std::fabs(bdz) +
                           (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * std::fabs(cdz);
  const double eps = 1.1102230246251565e-16;
  const double bound = (7.0 + 56.0 * eps) * eps * permanent;
  // det above is orient(d; a, b, c) = det[a-d, b-d, c-d] = -det[b-a, c-a, d-a].
  if (det > bound) return -1;
  if (-det > bound) return 1;
  return orientation(exact_point(a), exact_point(b), exact_point(c), exact_point(d));
}

void require_closed_manifold(const TriangleMesh3& mesh) {
  if (mesh.triangles.size() < 4) reject(mesh, "fewer than 4 triangles cannot bound a solid");
  require_distinct_used_vertices(mesh);
  require_paired_edges(mesh);
  require_single_fans(mesh);
  require_embedded(mesh);
}

int mesh_orientation(const TriangleMesh3& mesh) {
  // Six times the signed volume: sum of det[a, b, c] over the triangles (origin apex).
  mpq_class six_volume = 0;
  for (const auto& t : mesh.triangles) {
    const ExactPoint3 a = exact_point(mesh.vertices[t[0]]), b = exact_point(mesh.vertices[t[1]]),
                      c = exact_point(mesh.vertices[t[2]]);
    six_volume += dot(a, cross(b, c));
  }
  return sgn(six_volume);
}

}  // namespace grassfire
