// mesh_poles.cpp -- see mesh_poles.h. The CGAL translation unit of the mesh builder.
#include "complex3/builders/mesh_poles.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include "complex3/builders/mesh_checks.h"
#include "complex3/exact_predicates3.h"
#include "number/exact_sum.h"
#include "number/interval.h"

namespace grassfire {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Dt = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb>>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
using ET = K::FT::ET;

K::FT to_ft(const mpq_class& q) { return K::FT(ET(q.get_mpq_t())); }
K::Point_3 to_cgal(const ExactPoint3& p) { return {to_ft(p.x), to_ft(p.y), to_ft(p.z)}; }

// CGAL's exact rational type is mpq_class or CGAL::Gmpq, depending on its configuration.
template <class T>
mpq_class exact_to_mpq(const T& e) {
  if constexpr (std::is_same_v<T, mpq_class>) return e;
  else return mpq_class(e.mpq());
}

mpq_class to_mpq(const K::FT& x) { return exact_to_mpq(CGAL::exact(x)); }

struct LexLess {
  bool operator()(const ExactPoint3& a, const ExactPoint3& b) const { return compare_lex(a, b) < 0; }
};

struct Samples {
  std::vector<ExactPoint3> points, normals;  // normals: sums of outward triangle normals
};

// The points (i a + j b + k c) / S of every triangle, merged exactly across triangles.
Samples sample(const TriangleMesh3& mesh, int s, bool flip) {
  Samples out;
  std::map<ExactPoint3, std::uint32_t, LexLess> ids;
  for (auto t : mesh.triangles) {
    if (flip) std::swap(t[1], t[2]);
    const ExactPoint3 a = exact_point(mesh.vertices[t[0]]), b = exact_point(mesh.vertices[t[1]]),
                      c = exact_point(mesh.vertices[t[2]]);
    const ExactPoint3 n = cross(b - a, c - a);
    for (int i = 0; i <= s; ++i)
      for (int j = 0; i + j <= s; ++j) {
        const int k = s - i - j;
        const ExactPoint3 p = make_rational(1, s) * (mpq_class(i) * a + mpq_class(j) * b + mpq_class(k) * c);
        auto [it, fresh] = ids.emplace(p, static_cast<std::uint32_t>(out.points.size()));
        if (fresh) {
          out.points.push_back(p);
          out.normals.push_back({0, 0, 0});
        }
        out.normals[it->second] = out.normals[it->second] + n;
      }
  }
  return out;
}

Mesh surface_mesh(const TriangleMesh3& mesh, bool flip) {
  Mesh sm;
  std::vector<Mesh::Vertex_index> v;
  for (const auto& p : mesh.vertices) v.push_back(sm.add_vertex(to_cgal(exact_point(p))));
  for (auto t : mesh.triangles) {
    if (flip) std::swap(t[1], t[2]);
    sm.add_face(v[t[0]], v[t[1]], v[t[2]]);
  }
  return sm;
}

double sqrt_up(const mpq_class& q) { return round_up(std::sqrt(enclose(q).hi)); }
double sqrt_down(const mpq_class& q) { return std::max(0.0, round_down(std::sqrt(enclose(q).lo))); }

// How far the mesh (its triangle centroids) lies outside the union: an estimate.
double uncovered_estimate(const TriangleMesh3& mesh, const BallSet& balls) {
  double worst = 0;
  for (const auto& t : mesh.triangles) {
    double y[3];
    for (int k = 0; k < 3; ++k) y[k] = (mesh.vertices[t[0]][k] + mesh.vertices[t[1]][k] + mesh.vertices[t[2]][k]) / 3;
    double best = INFINITY;
    for (std::size_t i = 0; i < balls.centers.size(); ++i) {
      const auto& c = balls.approx_centers[i];
      const double d = std::sqrt((y[0] - c[0]) * (y[0] - c[0]) + (y[1] - c[1]) * (y[1] - c[1]) + (y[2] - c[2]) * (y[2] - c[2]));
      best = std::min(best, d - balls.approx_radii[i]);
    }
    worst = std::max(worst, best);
  }
  return worst;
}

}  // namespace

MeshPoles inner_polar_balls(const TriangleMesh3& mesh, const MeshPolesOptions& options) {
  if (options.subdivision < 1) throw std::invalid_argument("inner_polar_balls: subdivision must be at least 1");
  require_closed_manifold(mesh);
  const int orientation = mesh_orientation(mesh);
  if (orientation == 0) throw std::invalid_argument(mesh.source + ": the mesh encloses zero volume");
  const bool flip = orientation < 0;  // inside-out mesh: use outward triangles
  const Samples s = sample(mesh, options.subdivision, flip);
  MeshPoles out;
  out.samples = s.points.size();
  out.balls.source = mesh.source + " (inner polar balls)";

  std::vector<std::pair<K::Point_3, std::uint32_t>> pts;
  for (std::uint32_t i = 0; i < s.points.size(); ++i) pts.push_back({to_cgal(s.points[i]), i});
  const Dt dt(pts.begin(), pts.end());
  std::unordered_map<Dt::Cell_handle, ExactPoint3> centre;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    const K::Point_3 p =
        CGAL::circumcenter(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
    centre[c] = {to_mpq(p.x()), to_mpq(p.y()), to_mpq(p.z())};
  }

  const Mesh sm = surface_mesh(mesh, flip);
  Tree tree(faces(sm).first, faces(sm).second, sm);
  tree.accelerate_distance_queries();
  const CGAL::Side_of_triangle_mesh<Mesh, K> inside(tree);
  std::map<ExactPoint3, mpq_class, LexLess> poles;
  std::map<ExactPoint3, bool, LexLess> outside;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const ExactPoint3& p = s.points[v->info()];
    const ExactPoint3& n = s.normals[v->info()];
    std::vector<Dt::Cell_handle> cells;
    dt.finite_incident_cells(v, std::back_inserter(cells));
    const ExactPoint3* best = nullptr;
    mpq_class best_d2 = 0;
    for (const auto& c : cells) {
      const ExactPoint3& q = centre.at(c);
      const ExactPoint3 d = q - p;
      if (sgn(dot(d, n)) >= 0) continue;  // not on the inner side of the normal
      const mpq_class d2 = dot(d, d);
      if (!best || d2 > best_d2) {
        best = &q;
        best_d2 = d2;
      }
    }
    if (!best) {
      ++out.samples_without_pole;
      continue;
    }
    if (poles.count(*best) || outside.count(*best)) continue;
    if (inside(to_cgal(*best)) != CGAL::ON_BOUNDED_SIDE) {
      outside.emplace(*best, true);
      ++out.poles_outside;
      continue;
    }
    poles.emplace(*best, best_d2);
  }
  for (const auto& [c, w] : poles) {
    out.balls.centers.push_back(c);
    out.balls.squared_radii.push_back(w);
    out.balls.approx_centers.push_back({c.x.get_d(), c.y.get_d(), c.z.get_d()});
    out.balls.approx_radii.push_back(std::sqrt(w.get_d()));
    const mpq_class d2 = to_mpq(tree.squared_distance(to_cgal(c)));
    out.protrusion = std::max(out.protrusion, round_up(sqrt_up(w) - sqrt_down(d2)));
  }
  out.uncovered = uncovered_estimate(mesh, out.balls);
  return out;
}

}  // namespace grassfire
