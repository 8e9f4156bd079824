// disk_union_triangulations.cpp -- see disk_union_triangulations.h. The only translation
// unit of the union-of-disks axis with CGAL headers.
#include "medial2/disks/disk_union_triangulations.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace grassfire {

namespace {

// ---- regular triangulation of the disks ------------------------------------------------

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using RVb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K, CGAL::Regular_triangulation_vertex_base_2<K>>;
using RFb = CGAL::Triangulation_face_base_with_info_2<std::uint32_t, K, CGAL::Regular_triangulation_face_base_2<K>>;
using RTds = CGAL::Triangulation_data_structure_2<RVb, RFb>;
using Regular = CGAL::Regular_triangulation_2<K, RTds>;

// The exact number type behind K::FT is mpq_class or boost mpq_rational, depending on
// how CGAL was configured; both are built from an mpq_t.
K::FT exact_ft(const mpq_class& q) { return K::FT(K::FT::ET(q.get_mpq_t())); }

// ---- Delaunay triangulation of the corners, through CornerPredicates -------------------

struct CornerRef {
  std::uint32_t id = 0;
};

// The traits concept of CGAL's Delaunay_triangulation_2 (DelaunayTriangulationTraits_2),
// restricted to what insertion and traversal use: the predicates. Constructions are never
// called (no drawing, no dual); their types exist only to satisfy the class templates.
struct CornerTraits {
  const CornerPredicates* p = nullptr;

  using Point_2 = CornerRef;
  struct Segment_2 {};
  struct Triangle_2 {};
  struct Line_2 {};
  struct Ray_2 {};
  struct Compare_x_2 {
    const CornerPredicates* p;
    CGAL::Comparison_result operator()(const CornerRef& a, const CornerRef& b) const {
      return CGAL::Comparison_result(p->compare_x(a.id, b.id));
    }
  };
  struct Compare_y_2 {
    const CornerPredicates* p;
    CGAL::Comparison_result operator()(const CornerRef& a, const CornerRef& b) const {
      return CGAL::Comparison_result(p->compare_y(a.id, b.id));
    }
  };
  struct Orientation_2 {
    const CornerPredicates* p;
    CGAL::Orientation operator()(const CornerRef& a, const CornerRef& b, const CornerRef& c) const {
      return CGAL::Orientation(p->orientation(a.id, b.id, c.id));
    }
  };
  struct Side_of_oriented_circle_2 {
    const CornerPredicates* p;
    CGAL::Oriented_side operator()(const CornerRef& a, const CornerRef& b, const CornerRef& c,
                                   const CornerRef& d) const {
      return CGAL::Oriented_side(p->in_circle(a.id, b.id, c.id, d.id));
    }
  };
  struct Construct_point_2 {
    const CornerRef& operator()(const CornerRef& x) const { return x; }
  };
  struct Construct_segment_2 {
    Segment_2 operator()(const CornerRef&, const CornerRef&) const { return {}; }
  };
  struct Construct_triangle_2 {
    Triangle_2 operator()(const CornerRef&, const CornerRef&, const CornerRef&) const { return {}; }
  };
  struct Compare_distance_2 {};
  struct Construct_circumcenter_2 {};
  struct Construct_bisector_2 {};
  struct Construct_ray_2 {};

  Compare_x_2 compare_x_2_object() const { return {p}; }
  Compare_y_2 compare_y_2_object() const { return {p}; }
  Orientation_2 orientation_2_object() const { return {p}; }
  Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const { return {p}; }
  Construct_point_2 construct_point_2_object() const { return {}; }
  Construct_segment_2 construct_segment_2_object() const { return {}; }
  Construct_triangle_2 construct_triangle_2_object() const { return {}; }
};

using DVb = CGAL::Triangulation_vertex_base_2<CornerTraits>;
using DFb = CGAL::Triangulation_face_base_with_info_2<std::uint32_t, CornerTraits>;
using DTds = CGAL::Triangulation_data_structure_2<DVb, DFb>;
using Delaunay = CGAL::Delaunay_triangulation_2<CornerTraits, DTds>;

// Morton code of a point scaled into [0, 2^21)^2 (insertion order only).
std::uint64_t morton(double x, double y, double x0, double y0, double scale) {
  auto spread = [](std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  const auto cell = [&](double t, double t0) {
    return static_cast<std::uint64_t>(std::clamp((t - t0) * scale, 0.0, 2097151.0));
  };
  return spread(cell(x, x0)) | spread(cell(y, y0)) << 1;
}

std::vector<std::uint32_t> insertion_order(const std::vector<UnionCorner>& corners) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const UnionCorner& c : corners) {
    x0 = std::fmin(x0, c.approx.x.mid());
    y0 = std::fmin(y0, c.approx.y.mid());
    x1 = std::fmax(x1, c.approx.x.mid());
    y1 = std::fmax(y1, c.approx.y.mid());
  }
  const double extent = std::fmax(x1 - x0, y1 - y0);
  const double scale = extent > 0 ? 2097151.0 / extent : 0.0;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  for (std::uint32_t i = 0; i < corners.size(); ++i)
    keyed.emplace_back(morton(corners[i].approx.x.mid(), corners[i].approx.y.mid(), x0, y0, scale), i);
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order;
  for (const auto& k : keyed) order.push_back(k.second);
  return order;
}

}  // namespace

RegularTriangulationData regular_triangulation(const std::vector<Disk>& disks) {
  std::vector<std::pair<K::Weighted_point_2, std::uint32_t>> input;
  input.reserve(disks.size());
  for (std::uint32_t i = 0; i < disks.size(); ++i)
    input.emplace_back(K::Weighted_point_2(K::Point_2(exact_ft(disks[i].x), exact_ft(disks[i].y)),
                                           exact_ft(disks[i].r * disks[i].r)),
                       i);
  Regular rt(input.begin(), input.end());
  RegularTriangulationData out;
  out.dimension = rt.dimension();
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v) out.vertices.push_back(v->info());
  std::sort(out.vertices.begin(), out.vertices.end());
  for (auto f = rt.all_faces_begin(); f != rt.all_faces_end(); ++f) f->info() = kNoId;
  if (rt.dimension() == 2) {
    for (auto f = rt.finite_faces_begin(); f != rt.finite_faces_end(); ++f) {
      f->info() = static_cast<std::uint32_t>(out.faces.size());
      out.faces.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    }
  }
  for (auto e = rt.finite_edges_begin(); e != rt.finite_edges_end(); ++e) {
    const auto f = e->first;
    const int k = e->second;
    RegularTriangulationData::Edge edge;
    edge.i = f->vertex(f->ccw(k))->info();
    edge.j = f->vertex(f->cw(k))->info();
    if (rt.dimension() == 2) {
      const auto g = f->neighbor(k);
      const auto apex_g = g->vertex(g->index(f));
      if (!rt.is_infinite(f)) edge.face[0] = f->info(), edge.apex[0] = f->vertex(k)->info();
      if (!rt.is_infinite(g)) edge.face[1] = g->info(), edge.apex[1] = apex_g->info();
    }
    out.edges.push_back(edge);
  }
  return out;
}

CornerTriangulationData corner_delaunay(const std::vector<UnionCorner>& corners, const CornerPredicates& predicates) {
  CornerTraits traits;
  traits.p = &predicates;
  Delaunay dt(traits);
  Delaunay::Face_handle hint;
  for (std::uint32_t id : insertion_order(corners)) {
    const Delaunay::Vertex_handle v = dt.insert(CornerRef{id}, hint);
    hint = v->face();
  }
  CornerTriangulationData out;
  out.dimension = dt.dimension();
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info() = kNoId;
  if (dt.dimension() == 2) {
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      f->info() = static_cast<std::uint32_t>(out.faces.size());
      out.faces.push_back({f->vertex(0)->point().id, f->vertex(1)->point().id, f->vertex(2)->point().id});
    }
  }
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto f = e->first;
    const int k = e->second;
    CornerTriangulationData::Edge edge;
    edge.a = f->vertex(f->ccw(k))->point().id;
    edge.b = f->vertex(f->cw(k))->point().id;
    if (dt.dimension() == 2) {
      edge.left = f->info();
      edge.right = f->neighbor(k)->info();
    }
    out.edges.push_back(edge);
  }
  return out;
}

}  // namespace grassfire
