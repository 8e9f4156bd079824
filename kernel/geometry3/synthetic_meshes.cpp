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

TriangleMesh3 pinched_torus_mesh(double major, double minor, int n, int m) {
  TriangleMesh3 mesh;
  mesh.source = "pinched torus(" + std::to_string(major) + ", " + std::to_string(minor) + ")";
  mesh.vertices.push_back({major, 0, 0});  // the ring at u = 0, pinched to one vertex
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m, r = minor * std::sin(u / 2);
      mesh.vertices.push_back({(major + r * std::cos(v)) * std::cos(u), (major + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  auto id = [&](int i, int j) { return i % n == 0 ? 0u : static_cast<std::uint32_t>(1 + (i - 1) * m + j % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
      for (const std::array<std::uint32_t, 3>& t : {std::array<std::uint32_t, 3>{id(i, j), id(i + 1, j), id(i + 1, j + 1)},
                                                    std::array<std::uint32_t, 3>{id(i, j), id(i + 1, j + 1), id(i, j + 1)}})
        if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) mesh.triangles.push_back(t);
  return mesh;
}

TriangleMesh3 sphere_mesh(const std::array<double, 3>& centre, double radius, int levels) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                          {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> t = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto [it, fresh] = middle.emplace(std::make_pair(std::min(a, b), std::max(a, b)), static_cast<std::uint32_t>(p.size()));
      if (fresh) p.push_back({(p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2, (p[a][2] + p[b][2]) / 2});
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    for (const auto& [a, b, c] : t) {
      const std::uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    t = std::move(finer);
  }
  TriangleMesh3 mesh;
  mesh.source = "sphere";
  for (const auto& q : p) {
    const double s = radius / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    mesh.vertices.push_back({centre[0] + s * q[0], centre[1] + s * q[1], centre[2] + s * q[2]});
  }
  mesh.triangles = std::move(t);
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

TriangleMesh3 lens_mesh(double rim_angle, int rings, int sectors) {
  TriangleMesh3 mesh;
  mesh.source = "lens " + std::to_string(rim_angle);
  const double a = rim_angle * M_PI / 180, z = std::cos(a), r = std::sin(a);
  auto ring_point = [&](double radius, double height, int j) {
    const double phi = 2 * M_PI * j / sectors;
    return std::array<double, 3>{radius * std::cos(phi), radius * std::sin(phi), height};
  };
  mesh.vertices.push_back({0, 0, 1});  // the cap's pole
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j < sectors; ++j) mesh.vertices.push_back(ring_point(std::sin(a * i / rings), std::cos(a * i / rings), j));
  std::vector<std::uint32_t> outer(sectors), inner(sectors);
  auto cap = [&](int i, int j) { return static_cast<std::uint32_t>(1 + (i - 1) * sectors + j % sectors); };
  for (int j = 0; j < sectors; ++j) mesh.triangles.push_back({0, cap(1, j), cap(1, j + 1)});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      mesh.triangles.push_back({cap(i, j), cap(i + 1, j), cap(i + 1, j + 1)});
      mesh.triangles.push_back({cap(i, j), cap(i + 1, j + 1), cap(i, j + 1)});
    }
  for (int j = 0; j < sectors; ++j) outer[j] = cap(rings, j);
  for (int i = rings - 1; i >= 1; --i) {  // the disc, ring by ring inwards, facing -z
    for (int j = 0; j < sectors; ++j) {
      inner[j] = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back(ring_point(r * i / rings, z, j));
    }
    for (int j = 0; j < sectors; ++j) {
      const int k = (j + 1) % sectors;
      mesh.triangles.push_back({outer[j], inner[j], inner[k]});
      mesh.triangles.push_back({outer[j], inner[k], outer[k]});
    }
    outer = inner;
  }
  const auto centre = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back({0, 0, z});
  for (int j = 0; j < sectors; ++j) mesh.triangles.push_back({outer[j], centre, outer[(j + 1) % sectors]});
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
