// mesh_repair_cgal.cpp -- the CGAL steps of mesh_repair.h: hole filling (PMP), the alpha
// wrap (Alpha_wrap_3) and the bounded-error Hausdorff distance (PMP). The only file that
// includes these CGAL packages (they are heavy to compile).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <iterator>
#include <vector>

#include "medial3/mesh/mesh_embedding.h"
#include "medial3/mesh/mesh_repair.h"

namespace grassfire {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

std::vector<Point> points_of(const TriangleMesh3& mesh) {
  std::vector<Point> p;
  p.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) p.emplace_back(v[0], v[1], v[2]);
  return p;
}

// The triangles of a Surface_mesh without removed elements, with its vertex numbering.
TriangleMesh3 triangle_mesh_of(const Mesh& sm, const std::string& source) {
  TriangleMesh3 out;
  out.source = source;
  std::vector<std::uint32_t> index(sm.number_of_vertices());
  for (Mesh::Vertex_index v : sm.vertices()) {
    index[v.idx()] = static_cast<std::uint32_t>(out.vertices.size());
    const Point& p = sm.point(v);
    out.vertices.push_back({p.x(), p.y(), p.z()});
  }
  for (Mesh::Face_index f : sm.faces()) {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm)) t[k++] = index[v.idx()];
    out.triangles.push_back(t);
  }
  return out;
}

// Every triangle with its own three vertices: a valid Surface_mesh for any triangle soup
// (non-manifold, self-intersecting), which is all the distance needs.
Mesh soup_mesh(const TriangleMesh3& mesh) {
  Mesh sm;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (has_zero_area(mesh, t)) continue;
    std::array<Mesh::Vertex_index, 3> v;
    for (int k = 0; k < 3; ++k) {
      const auto& p = mesh.vertices[mesh.triangles[t][k]];
      v[k] = sm.add_vertex(Point(p[0], p[1], p[2]));
    }
    sm.add_face(v[0], v[1], v[2]);
  }
  return sm;
}

}  // namespace

bool fill_holes(const TriangleMesh3& mesh, TriangleMesh3& filled, std::size_t& holes) {
  std::vector<Point> points = points_of(mesh);
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  // false: orienting needed duplicated vertices (the soup is not an orientable manifold).
  if (!PMP::orient_polygon_soup(points, polygons) || points.size() != mesh.vertices.size()) return false;
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return false;
  Mesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(sm, std::back_inserter(cycles));
  holes = cycles.size();
  for (Mesh::Halfedge_index h : cycles) {
    std::vector<Mesh::Face_index> added;
    PMP::triangulate_hole(sm, h, std::back_inserter(added));
  }
  if (!CGAL::is_closed(sm)) return false;
  if (!PMP::is_outward_oriented(sm)) PMP::reverse_face_orientations(sm);
  filled = triangle_mesh_of(sm, mesh.source + " (holes filled)");
  return true;
}

TriangleMesh3 alpha_wrap(const TriangleMesh3& mesh, double alpha, double offset) {
  const std::vector<Point> points = points_of(mesh);
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) faces.push_back({t[0], t[1], t[2]});
  Mesh wrap;
  CGAL::alpha_wrap_3(points, faces, alpha, offset, wrap);
  return triangle_mesh_of(wrap, mesh.source + " (alpha wrap)");
}

double hausdorff_distance(const TriangleMesh3& a, const TriangleMesh3& b, double error_bound) {
  const Mesh sa = soup_mesh(a), sb = soup_mesh(b);
  if (sa.number_of_faces() == 0 || sb.number_of_faces() == 0) return 0;
  return PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(sa, sb, error_bound);
}

}  // namespace grassfire
