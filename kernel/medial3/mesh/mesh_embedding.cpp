// mesh_embedding.cpp -- see mesh_embedding.h.
#include "medial3/mesh/mesh_embedding.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>

#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "medial3/mesh/mesh_checks.h"
#include "geometry3/exact_predicates3.h"

namespace grassfire {

namespace {

[[noreturn]] void reject(const TriangleMesh3& mesh, const std::string& problem) {
  throw std::invalid_argument(mesh.source + ": " + problem);
}

std::string face_name(const TriangleMesh3& mesh, std::uint32_t t) { return "face " + std::to_string(file_face_index(mesh, t)); }

// Certainly not collinear: some coordinate projection of the triangle has an orient2d
// determinant whose sign the double computation certifies (Shewchuk's ccwerrboundA).
bool certainly_proper(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c) {
  const double eps = 1.1102230246251565e-16, bound = (3.0 + 16.0 * eps) * eps;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const double left = (b[i] - a[i]) * (c[j] - a[j]), right = (b[j] - a[j]) * (c[i] - a[i]);
    if (std::fabs(left - right) > bound * (std::fabs(left) + std::fabs(right))) return true;
  }
  return false;
}

}  // namespace

bool has_zero_area(const TriangleMesh3& mesh, std::uint32_t t) {
  const auto& [a, b, c] = mesh.triangles[t];
  const auto& p = mesh.vertices;
  return !certainly_proper(p[a], p[b], p[c]) && collinear(exact_point(p[a]), exact_point(p[b]), exact_point(p[c]));
}

namespace {

void require_positive_areas(const TriangleMesh3& mesh) {
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (has_zero_area(mesh, t))
      reject(mesh, face_name(mesh, t) + " has zero area: its three vertices are collinear (it is not dropped: that "
                                        "would open the mesh)");
  }
}

// Triangles (a, b, c) and (b, a, d) on the edge ab fold when d lies in their common plane
// on the same side of the line ab as c.
void require_no_folds(const TriangleMesh3& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> directed;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) directed[{mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]}] = t;
  for (const auto& [e, t] : directed) {
    if (e.first > e.second) continue;  // each edge once
    const auto other = directed.find({e.second, e.first});
    if (other == directed.end()) continue;  // the combinatorial checks report open edges
    const auto apex = [&](std::uint32_t tri) {
      for (std::uint32_t v : mesh.triangles[tri])
        if (v != e.first && v != e.second) return v;
      return e.first;
    };
    const auto& p = mesh.vertices;
    const std::uint32_t c = apex(t), d = apex(other->second);
    if (orient3d(p[e.first], p[e.second], p[c], p[d]) != 0) continue;
    const ExactPoint3 a = exact_point(p[e.first]), ab = exact_point(p[e.second]) - a;
    if (sgn(dot(cross(ab, exact_point(p[c]) - a), cross(ab, exact_point(p[d]) - a))) > 0)
      reject(mesh, face_name(mesh, t) + " and " + face_name(mesh, other->second) +
                       " fold onto each other along their common edge (the mesh is self-intersecting)");
  }
}

// Mesh coordinates are doubles, so CGAL's filtered predicates on them (Epick) are exact.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, std::uint32_t, CGAL::Box_intersection_d::ID_EXPLICIT>;

// Do triangles s and t of the mesh meet outside their common vertices and edges?
// No common vertex: any intersection is improper. One common vertex v, s = (v, a, b) and
// t = (v, c, d): every ray from v into s leaves s through the segment ab, so a point of
// s ∩ t other than v exists iff t meets the segment ab or s meets the segment cd (an
// exit point of s ∩ t on the farther of the two opposite edges); coplanar or not. A common
// edge is the fold test's (require_no_folds).
bool improper(const TriangleMesh3& mesh, std::uint32_t s, std::uint32_t t) {
  if (s == t) return false;
  const auto& ts = mesh.triangles[s];
  const auto& tt = mesh.triangles[t];
  const auto point = [&](std::uint32_t v) { return K::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]); };
  int common = 0, is = -1, it = -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ts[i] == tt[j]) ++common, is = i, it = j;
  if (common >= 2) return false;
  const K::Triangle_3 a(point(ts[0]), point(ts[1]), point(ts[2])), b(point(tt[0]), point(tt[1]), point(tt[2]));
  if (common == 0) return CGAL::do_intersect(a, b);
  const K::Segment_3 opposite_s(point(ts[(is + 1) % 3]), point(ts[(is + 2) % 3]));
  const K::Segment_3 opposite_t(point(tt[(it + 1) % 3]), point(tt[(it + 2) % 3]));
  return CGAL::do_intersect(b, opposite_s) || CGAL::do_intersect(a, opposite_t);
}

}  // namespace

namespace {

// Calls visit(s, t), s < t, for every pair of triangles of `mesh` (those with use[t], all
// when `use` is empty) whose closed bounding boxes overlap.
template <class Visit>
void visit_box_pairs(const TriangleMesh3& mesh, const std::vector<bool>& use, Visit visit) {
  std::vector<Box> boxes;
  boxes.reserve(mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!use.empty() && !use[t]) continue;
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
      lo[i] = hi[i] = mesh.vertices[mesh.triangles[t][0]][i];
      for (int k = 1; k < 3; ++k) {
        lo[i] = std::min(lo[i], mesh.vertices[mesh.triangles[t][k]][i]);
        hi[i] = std::max(hi[i], mesh.vertices[mesh.triangles[t][k]][i]);
      }
    }
    boxes.emplace_back(lo, hi, t);
  }
  auto callback = [&](const Box& x, const Box& y) {
    visit(std::min(x.handle(), y.handle()), std::max(x.handle(), y.handle()));
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), callback);  // closed boxes: touching ones are tested
}

}  // namespace

std::optional<std::array<std::uint32_t, 2>> first_crossing(const TriangleMesh3& mesh) {
  std::optional<std::array<std::uint32_t, 2>> found;
  visit_box_pairs(mesh, {}, [&](std::uint32_t s, std::uint32_t t) {
    const std::array<std::uint32_t, 2> pair{s, t};
    if ((!found || pair < *found) && improper(mesh, s, t)) found = pair;
  });
  return found;
}

std::size_t count_crossings(const TriangleMesh3& mesh, const std::vector<bool>& positive_area) {
  std::size_t n = 0;
  visit_box_pairs(mesh, positive_area, [&](std::uint32_t s, std::uint32_t t) { n += improper(mesh, s, t); });
  return n;
}

void require_embedded(const TriangleMesh3& mesh) {
  require_positive_areas(mesh);
  require_no_folds(mesh);
  if (const auto pair = first_crossing(mesh))
    reject(mesh, face_name(mesh, (*pair)[0]) + " and " + face_name(mesh, (*pair)[1]) +
                     " intersect (the mesh is self-intersecting)");
}

}  // namespace grassfire
