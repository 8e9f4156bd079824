// mesh_weld.cpp -- see mesh_weld.h.
#include "geometry3/mesh_weld.h"

#include <algorithm>
#include <numeric>
#include <set>

namespace grassfire {

namespace {

// For each vertex, the first vertex (in file order) at exactly the same point.
std::vector<std::uint32_t> first_copies(const std::vector<std::array<double, 3>>& p) {
  std::vector<std::uint32_t> order(p.size());
  std::iota(order.begin(), order.end(), 0u);
  // Ties keep file order, so the first index of each run of equal points is the first copy.
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return p[a] < p[b]; });
  std::vector<std::uint32_t> first(p.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    first[order[i]] = (i > 0 && p[order[i]] == p[order[i - 1]]) ? first[order[i - 1]] : order[i];
  return first;
}

std::string count_of(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

void weld_and_drop(TriangleMesh3& mesh) {
  MeshCleanup& c = mesh.cleanup;
  const std::vector<std::uint32_t> first = first_copies(mesh.vertices);
  for (std::uint32_t v = 0; v < first.size(); ++v) c.welded_vertices += first[v] != v;
  std::vector<std::array<std::uint32_t, 3>> kept;
  std::vector<std::uint32_t> kept_origin;
  std::set<std::array<std::uint32_t, 3>> seen;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<std::uint32_t, 3> tri;
    for (int k = 0; k < 3; ++k) tri[k] = first[mesh.triangles[t][k]];
    std::array<std::uint32_t, 3> key = tri;
    std::sort(key.begin(), key.end());
    if (key[0] == key[1] || key[1] == key[2]) {
      ++c.degenerate_faces;
    } else if (!seen.insert(key).second) {
      ++c.repeated_faces;
    } else {
      kept.push_back(tri);
      kept_origin.push_back(mesh.triangle_origin[t]);
    }
  }
  // Renumber the used first copies in file order.
  const std::uint32_t none = static_cast<std::uint32_t>(-1);
  std::vector<std::uint32_t> renumber(mesh.vertices.size(), none);
  for (const auto& tri : kept)
    for (std::uint32_t v : tri) renumber[v] = 0;
  const bool exact = mesh.exact_vertices.size() == mesh.vertices.size();
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<mpq_class, 3>> exact_vertices;
  std::vector<std::uint32_t> origin;
  for (std::uint32_t v = 0; v < renumber.size(); ++v) {
    if (first[v] != v) continue;
    if (renumber[v] == none) {
      ++c.unused_vertices;
      continue;
    }
    renumber[v] = static_cast<std::uint32_t>(vertices.size());
    vertices.push_back(mesh.vertices[v]);
    if (exact) exact_vertices.push_back(std::move(mesh.exact_vertices[v]));
    origin.push_back(v < mesh.vertex_origin.size() ? mesh.vertex_origin[v] : v);
  }
  for (auto& tri : kept)
    for (std::uint32_t& v : tri) v = renumber[v];
  mesh.vertices = std::move(vertices);
  mesh.exact_vertices = std::move(exact_vertices);
  mesh.vertex_origin = std::move(origin);
  mesh.triangles = std::move(kept);
  mesh.triangle_origin = std::move(kept_origin);
}

std::string describe_cleanup(const MeshCleanup& c) {
  std::vector<std::string> parts;
  if (c.welded_vertices) parts.push_back("welded " + count_of(c.welded_vertices, "repeated vertex", "repeated vertices"));
  std::vector<std::string> dropped;
  if (c.degenerate_faces) dropped.push_back(count_of(c.degenerate_faces, "degenerate face", "degenerate faces"));
  if (c.repeated_faces) dropped.push_back(count_of(c.repeated_faces, "repeated face", "repeated faces"));
  if (c.unused_vertices) dropped.push_back(count_of(c.unused_vertices, "unused vertex", "unused vertices"));
  for (std::size_t i = 0; i < dropped.size(); ++i)
    parts.push_back((i == 0 ? "dropped " : "") + dropped[i]);
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i == 0 ? "" : ", ") + parts[i];
  return s;
}

}  // namespace grassfire
