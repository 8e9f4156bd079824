// geodesic_smsp.cpp -- see geodesic_smsp.h. The only file with CGAL's shortest-path headers.
#include "burn3/geodesic_smsp.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <limits>
#include <map>
#include <variant>
#include <stdexcept>
#include <string>

namespace grassfire {
namespace {

using Kernel = CGAL::Epick;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh>;
using ShortestPath = CGAL::Surface_mesh_shortest_path<Traits>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using FaceIndex = Mesh::Face_index;
constexpr double kEdgeStep = 0x1p-40;

}  // namespace

// CGAL 5.5.1 (Debian bookworm) mishandles locations on edges, measured here: a source
// inside an edge is rooted at the mirror image of its position along the edge (a source at
// parameter 0.4 burns as if at 0.6; CGAL issue #6681, fixed in CGAL 5.6 by PR #6739), a
// query on a border edge gets a wrong distance, and a location at a vertex given with
// round-off is rooted at a wrong vertex (#9646). So: a point at a vertex (two weights <= 0)
// is passed as that vertex; a point inside an edge (one weight <= 0) is moved 2^-40 of the
// way towards the opposite corner, into the face; T is 1-Lipschitz in the source and in
// the query, so this changes T by at most 2^-40 times the corner's distance (1e-12
// relative), below the double precision this peer is compared at.
struct SmspGeodesics::Impl {
  Mesh mesh;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::map<double, std::vector<MeshPoint>> groups;  // sources by t0
  std::vector<std::pair<double, std::unique_ptr<ShortestPath>>> trees;
  std::unique_ptr<ShortestPath> locator;
  AabbTree aabb;
  double seconds = 0.0;

  // Which of our triangle's corners CGAL's barycentric coordinate i weighs: asked of
  // CGAL itself (ShortestPath::point at the unit weights), not assumed.
  std::array<int, 3> cgal_order(std::uint32_t f) const {
    std::array<int, 3> order{};
    for (int i = 0; i < 3; ++i) {
      ShortestPath::Barycentric_coordinates unit = {0, 0, 0};
      unit[i] = 1;
      const Kernel::Point_3 p = ShortestPath::point(FaceIndex(f), unit, mesh);
      for (int j = 0; j < 3; ++j)
        if (mesh.point(Mesh::Vertex_index(triangles[f][j])) == p) order[i] = j;
    }
    return order;
  }
  MeshPoint from_cgal(const ShortestPath::Face_location& l) const {
    MeshPoint p;
    p.face = static_cast<std::uint32_t>(l.first);
    const std::array<int, 3> order = cgal_order(p.face);
    for (int i = 0; i < 3; ++i) p.barycentric[order[i]] = l.second[i];
    return p;
  }
  // The vertex (two weights <= 0), else the face location, moved off an edge.
  std::variant<Mesh::Vertex_index, ShortestPath::Face_location> root(const MeshPoint& p) const {
    int zeros = 0, largest = 0;
    for (int j = 0; j < 3; ++j) {
      zeros += p.barycentric[j] <= 0;
      if (p.barycentric[j] > p.barycentric[largest]) largest = j;
    }
    if (zeros >= 2) return Mesh::Vertex_index(triangles[p.face][largest]);
    std::array<double, 3> w = p.barycentric;
    if (zeros == 1)
      for (double& x : w) x = x <= 0 ? kEdgeStep : (1 - kEdgeStep) * x;
    const std::array<int, 3> order = cgal_order(p.face);
    return ShortestPath::Face_location{FaceIndex(p.face), {w[order[0]], w[order[1]], w[order[2]]}};
  }
};

SmspGeodesics::SmspGeodesics(const TriangleMesh3& input) : impl_(std::make_unique<Impl>()) {
  Mesh& mesh = impl_->mesh;
  for (const auto& v : input.vertices) mesh.add_vertex(Kernel::Point_3(v[0], v[1], v[2]));
  for (std::size_t f = 0; f < input.triangles.size(); ++f) {
    const auto& t = input.triangles[f];
    if (mesh.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2])) ==
        Mesh::null_face())
      throw std::invalid_argument(input.source + ": face " + std::to_string(f) +
                                  " makes the mesh non-manifold or inconsistently oriented (CGAL shortest paths need "
                                  "a manifold triangle mesh)");
  }
  if (!CGAL::is_valid_polygon_mesh(mesh)) throw std::invalid_argument(input.source + ": not a valid polygon mesh");
  impl_->triangles = input.triangles;
  impl_->locator = std::make_unique<ShortestPath>(mesh);
  impl_->locator->build_aabb_tree(impl_->aabb);
}

SmspGeodesics::~SmspGeodesics() = default;

ExactPoint3 exact_mesh_point(const TriangleMesh3& mesh, const MeshPoint& p) {
  ExactPoint3 c{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const auto& v = mesh.vertices[mesh.triangles[p.face][i]];
    c = c + mpq_class(p.barycentric[i]) * ExactPoint3{mpq_class(v[0]), mpq_class(v[1]), mpq_class(v[2])};
  }
  return c;
}

MeshPoint SmspGeodesics::locate(const std::array<double, 3>& p) const {
  return impl_->from_cgal(impl_->locator->locate(Kernel::Point_3(p[0], p[1], p[2]), impl_->aabb));
}

void SmspGeodesics::add_source(const MeshPoint& p, double t0) {
  if (p.face >= impl_->triangles.size()) throw std::invalid_argument("SmspGeodesics: source face out of range");
  impl_->groups[t0].push_back(p);
}

void SmspGeodesics::build() {
  const auto start = std::chrono::steady_clock::now();
  impl_->trees.clear();
  for (const auto& [t0, points] : impl_->groups) {
    auto tree = std::make_unique<ShortestPath>(impl_->mesh);
    for (const MeshPoint& p : points) {
      const auto r = impl_->root(p);
      if (std::holds_alternative<Mesh::Vertex_index>(r)) tree->add_source_point(std::get<Mesh::Vertex_index>(r));
      else tree->add_source_point(std::get<ShortestPath::Face_location>(r));
    }
    tree->build_sequence_tree();
    impl_->trees.emplace_back(t0, std::move(tree));
  }
  impl_->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double SmspGeodesics::distance(const MeshPoint& q) const {
  const auto r = impl_->root(q);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [t0, tree] : impl_->trees) {
    const auto [d, source] =
        std::holds_alternative<Mesh::Vertex_index>(r)
            ? tree->shortest_distance_to_source_points(std::get<Mesh::Vertex_index>(r))
            : tree->shortest_distance_to_source_points(std::get<ShortestPath::Face_location>(r).first,
                                                       std::get<ShortestPath::Face_location>(r).second);
    if (source != tree->source_points_end() && d >= 0) best = std::min(best, t0 + d);
  }
  return best;
}

std::size_t SmspGeodesics::tree_count() const { return impl_->trees.size(); }

double SmspGeodesics::build_seconds() const { return impl_->seconds; }

}  // namespace grassfire
