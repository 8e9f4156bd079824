// regular_triangulation.cpp -- CGAL's Regular_triangulation_3 and Fixed_alpha_shape_3 on
// exact ball sets (see union_alpha_complex.h). The only translation unit of the union-of-
// balls builder that includes CGAL.
//
// Kernel choice: when every centre coordinate and weight is a double (random or binary
// input), Epick's filtered exact predicates decide the triangulation exactly; otherwise
// (decimals such as 0.1) the exact rationals go through Epeck. Either way the combinatorics
// are those of the exact input.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fixed_alpha_shape_3.h>
#include <CGAL/Fixed_alpha_shape_cell_base_3.h>
#include <CGAL/Fixed_alpha_shape_vertex_base_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "medial3/balls/union_alpha_complex.h"

namespace grassfire {

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

template <class K>
typename K::FT to_ft(const mpq_class& q) {
  if constexpr (std::is_same_v<K, Epick>) {
    return q.get_d();
  } else {
    using ET = typename K::FT::ET;
    return typename K::FT(ET(q.get_mpq_t()));
  }
}

template <class K>
std::vector<std::pair<typename K::Weighted_point_3, std::uint32_t>> weighted_points(const BallSet& b) {
  std::vector<std::pair<typename K::Weighted_point_3, std::uint32_t>> out;
  for (std::uint32_t i = 0; i < b.centers.size(); ++i) {
    const ExactPoint3& c = b.centers[i];
    out.push_back({typename K::Weighted_point_3(typename K::Point_3(to_ft<K>(c.x), to_ft<K>(c.y), to_ft<K>(c.z)),
                                                to_ft<K>(b.squared_radii[i])),
                   i});
  }
  return out;
}

template <std::size_t N>
std::array<std::uint32_t, N> sorted(std::array<std::uint32_t, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

template <class Rt>
void extract(const Rt& rt, RegularTriangulation* out) {
  out->dimension = rt.dimension();
  for (auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v) out->vertices.push_back(v->info());
  if (rt.dimension() >= 1)
    for (auto e = rt.finite_edges_begin(); e != rt.finite_edges_end(); ++e)
      out->edges.push_back(sorted<2>({e->first->vertex(e->second)->info(), e->first->vertex(e->third)->info()}));
  if (rt.dimension() >= 2)
    for (auto f = rt.finite_facets_begin(); f != rt.finite_facets_end(); ++f) {
      std::array<std::uint32_t, 3> t{};
      for (int k = 0, m = 0; k < 4; ++k)
        if (k != f->second && (rt.dimension() == 3 || k < 3)) t[m++] = f->first->vertex(k)->info();
      out->triangles.push_back(sorted(t));
    }
  if (rt.dimension() == 3)
    for (auto c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c)
      out->tetrahedra.push_back(
          sorted<4>({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()}));
  // CGAL enumerates each edge and facet from the cell of smaller address, so its order
  // changes from one call to the next in one process: sorted lists make the axis (its
  // numbering, and which cell first computes a vertex) a function of the input alone.
  std::sort(out->vertices.begin(), out->vertices.end());
  std::sort(out->edges.begin(), out->edges.end());
  std::sort(out->triangles.begin(), out->triangles.end());
  std::sort(out->tetrahedra.begin(), out->tetrahedra.end());
}

template <class K>
RegularTriangulation triangulate(const BallSet& b) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K, CGAL::Regular_triangulation_vertex_base_3<K>>;
  using Cb = CGAL::Regular_triangulation_cell_base_3<K>;
  using Rt = CGAL::Regular_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Cb>>;
  const auto points = weighted_points<K>(b);
  Rt rt(points.begin(), points.end());
  RegularTriangulation out;
  extract(rt, &out);
  out.exact_double_kernel = std::is_same_v<K, Epick>;
  return out;
}

template <class K>
std::size_t cells_only(const BallSet& b) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K, CGAL::Regular_triangulation_vertex_base_3<K>>;
  using Cb = CGAL::Regular_triangulation_cell_base_3<K>;
  using Rt = CGAL::Regular_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Cb>>;
  const auto points = weighted_points<K>(b);
  Rt rt(points.begin(), points.end());
  return rt.number_of_finite_cells();
}

bool all_doubles(const BallSet& b) {
  auto is_double = [](const mpq_class& q) { return mpq_class(q.get_d()) == q; };
  for (std::size_t i = 0; i < b.centers.size(); ++i)
    if (!is_double(b.centers[i].x) || !is_double(b.centers[i].y) || !is_double(b.centers[i].z) ||
        !is_double(b.squared_radii[i]))
      return false;
  return true;
}

}  // namespace

RegularTriangulation regular_triangulation(const BallSet& b) {
  return all_doubles(b) ? triangulate<Epick>(b) : triangulate<Epeck>(b);
}

std::size_t cgal_regular_triangulation_cells(const BallSet& b) {
  return all_doubles(b) ? cells_only<Epick>(b) : cells_only<Epeck>(b);
}

std::vector<std::array<std::uint32_t, 4>> cgal_alpha_complex(const BallSet& b) {
  using K = Epeck;
  using Vb = CGAL::Fixed_alpha_shape_vertex_base_3<
      K, CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K, CGAL::Regular_triangulation_vertex_base_3<K>>>;
  using Cb = CGAL::Fixed_alpha_shape_cell_base_3<K, CGAL::Regular_triangulation_cell_base_3<K>>;
  using Rt = CGAL::Regular_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Cb>>;
  using Shape = CGAL::Fixed_alpha_shape_3<Rt>;
  const auto points = weighted_points<K>(b);
  Rt rt(points.begin(), points.end());
  std::vector<std::array<std::uint32_t, 4>> out;
  if (rt.dimension() != 3) return out;
  Shape shape(rt, 0);
  constexpr std::uint32_t kPad = std::numeric_limits<std::uint32_t>::max();
  for (auto v = shape.finite_vertices_begin(); v != shape.finite_vertices_end(); ++v)
    if (shape.classify(v) != Shape::EXTERIOR) out.push_back({v->info(), kPad, kPad, kPad});
  for (auto e = shape.finite_edges_begin(); e != shape.finite_edges_end(); ++e)
    if (shape.classify(*e) != Shape::EXTERIOR) {
      const auto s = sorted<2>({e->first->vertex(e->second)->info(), e->first->vertex(e->third)->info()});
      out.push_back({s[0], s[1], kPad, kPad});
    }
  for (auto f = shape.finite_facets_begin(); f != shape.finite_facets_end(); ++f)
    if (shape.classify(*f) != Shape::EXTERIOR) {
      std::array<std::uint32_t, 3> t{};
      for (int k = 0, m = 0; k < 4; ++k)
        if (k != f->second) t[m++] = f->first->vertex(k)->info();
      t = sorted(t);
      out.push_back({t[0], t[1], t[2], kPad});
    }
  for (auto c = shape.finite_cells_begin(); c != shape.finite_cells_end(); ++c)
    if (shape.classify(c) != Shape::EXTERIOR)
      out.push_back(sorted<4>({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()}));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace grassfire
