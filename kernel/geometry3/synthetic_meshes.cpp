// synthetic_meshes.cpp -- see synthetic_meshes.h.
#include "geometry3/synthetic_meshes.h"

#include <cmath>
#include <map>
#include <set>

namespace grassfire {

TriangleMesh3 torus_mesh(double major, double minor, int n, int m) {
  TriangleMesh3 mesh;
  mesh.source = "torus(" + std::to_string(major) + ", " + std::to_string(minor) + ", " + std::to_string(n) + "x" +
                std::to_string(m) + ")";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      mesh.vertices.push_back({(major + minor * std::cos(v)) * std::cos(u), (major + minor * std::cos(v)) * std::sin(u),
                               minor * std::sin(v)});
    }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      // d/du x d/dv points outward for this parametrisation.
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

TriangleMesh3 voxel_mesh(const std::vector<Voxel>& filled, double size, const std::string& name) {
  const std::set<Voxel> cells(filled.begin(), filled.end());
  TriangleMesh3 mesh;
  mesh.source = name;
  std::map<Voxel, std::uint32_t> ids;
  auto vertex = [&](const Voxel& p) {
    auto [it, fresh] = ids.emplace(p, static_cast<std::uint32_t>(mesh.vertices.size()));
    if (fresh) mesh.vertices.push_back({size * p[0], size * p[1], size * p[2]});
    return it->second;
  };
  for (const Voxel& c : cells)
    for (int k = 0; k < 3; ++k)
      for (int s : {1, -1}) {
        Voxel n = c;
        n[k] += s;
        if (cells.count(n)) continue;
        // The face at c[k] + (s > 0), corners (0,0), (1,0), (1,1), (0,1) in the axes
        // u = k + 1, v = k + 2: e_u x e_v = e_k, so this order faces +k; reversed for -k.
        const int u = (k + 1) % 3, v = (k + 2) % 3;
        std::array<std::uint32_t, 4> q;
        const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
        for (int i = 0; i < 4; ++i) {
          Voxel p = c;
          p[k] += s > 0 ? 1 : 0;
          p[u] += du[i];
          p[v] += dv[i];
          q[i] = vertex(p);
        }
        if (s < 0) std::swap(q[1], q[3]);
        mesh.triangles.push_back({q[0], q[1], q[2]});
        mesh.triangles.push_back({q[0], q[2], q[3]});
      }
  return mesh;
}

TriangleMesh3 prism_mesh(const std::vector<std::array<double, 2>>& polygon, double height, const std::string& name) {
  TriangleMesh3 mesh;
  mesh.source = name;
  const auto n = static_cast<std::uint32_t>(polygon.size());
  for (double z : {0.0, height})
    for (const auto& p : polygon) mesh.vertices.push_back({p[0], p[1], z});
  for (std::uint32_t i = 1; i + 1 < n; ++i) {
    mesh.triangles.push_back({0, i + 1, i});              // bottom, facing -z
    mesh.triangles.push_back({n, n + i, n + i + 1});      // top, facing +z
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.triangles.push_back({i, j, n + j});
    mesh.triangles.push_back({i, n + j, n + i});
  }
  return mesh;
}

std::vector<Voxel> hollow_block_voxels(int n) {
  std::vector<Voxel> v;
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y)
      for (int z = 0; z < n; ++z)
        if (x == 0 || y == 0 || z == 0 || x == n - 1 || y == n - 1 || z == n - 1) v.push_back({x, y, z});
  return v;
}

TriangleMesh3 plate_with_holes(int nx, int ny, const std::vector<std::array<int, 2>>& holes) {
  const std::set<std::array<int, 2>> removed(holes.begin(), holes.end());
  std::vector<Voxel> cells;
  for (int x = 0; x < nx; ++x)
    for (int y = 0; y < ny; ++y)
      if (!removed.count({x, y})) cells.push_back({x, y, 0});
  return voxel_mesh(cells, 1, "plate " + std::to_string(nx) + "x" + std::to_string(ny) + " with " +
                                  std::to_string(holes.size()) + " holes");
}

}  // namespace grassfire
