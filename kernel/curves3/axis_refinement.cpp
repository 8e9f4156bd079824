// axis_refinement.cpp -- the triangulation K of a medial complex at a field's resolution.
#include "curves3/axis_refinement.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "geometry3/vec3.h"

namespace grassfire {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;

constexpr std::int64_t kMaxDenominator = std::int64_t{1} << 52;

// A point of one triangle of M: its id in K, integer affine coordinates (weights of
// corners 1 and 2 times the denominator), and its barycentric weights in doubles.
struct LocalPoint {
  std::uint32_t id;
  std::int64_t u, w;
  std::array<double, 3> weight;
};

class Builder {
 public:
  explicit Builder(const BurningField& field) : f_(field), mc_(field.complex()) {}

  AxisRefinement run() {
    add_vertices_and_edge_points();
    for (std::uint32_t t = 0; t < mc_.triangle_count(); ++t) refine_triangle(t);
    add_segments();
    k_.edge_triangles.assign(k_.edges.size(), {});
    for (std::uint32_t s = 0; s < k_.triangles.size(); ++s)
      for (std::uint32_t e : k_.triangles[s].e) k_.edge_triangles[e].push_back(s);
    return std::move(k_);
  }

 private:
  void add_vertices_and_edge_points() {
    for (std::uint32_t v = 0; v < mc_.vertex_count(); ++v) {
      RefinedVertex rv;
      rv.position = mc_.vertex(v).approx;
      rv.on = RefinedVertex::On::Vertex;
      rv.cell = v;
      rv.radius = mc_.vertex(v).radius;
      rv.bt = f_.vertex_burn_time(v);
      k_.vertices.push_back(rv);
    }
    edge_base_.resize(mc_.edge_count());
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
      edge_base_[e] = static_cast<std::uint32_t>(k_.vertices.size());
      const std::uint32_t n = f_.edge_points(e);
      const double r0 = mc_.vertex(mc_.edge(e).v[0]).radius, r1 = mc_.vertex(mc_.edge(e).v[1]).radius;
      for (std::uint32_t i = 1; i <= n; ++i) {
        const double s = static_cast<double>(i) / (n + 1);
        RefinedVertex rv;
        rv.position = edge_point(mc_, e, s);
        rv.on = RefinedVertex::On::Edge;
        rv.cell = e;
        rv.index = i;
        rv.weight = {1 - s, s, 0};
        rv.radius = r0 + s * (r1 - r0);
        rv.bt = f_.edge_point_burn_time(e, i);
        k_.vertices.push_back(rv);
      }
    }
  }

  // The K id of point i (0 .. n + 1) of edge e.
  std::uint32_t edge_vertex(std::uint32_t e, std::uint32_t i) const {
    if (i == 0) return mc_.edge(e).v[0];
    if (i == f_.edge_points(e) + 1) return mc_.edge(e).v[1];
    return edge_base_[e] + i - 1;
  }

  static std::int64_t lcm(std::int64_t a, std::int64_t b) { return a / std::gcd(a, b) * b; }

  std::vector<LocalPoint> triangle_points(std::uint32_t t, std::int64_t* lattice) {
    const ComplexTriangle& tr = mc_.triangle(t);
    std::int64_t L = 1, D = 1;
    for (std::uint32_t e : tr.e) L = std::max<std::int64_t>(L, f_.edge_points(e) + 1);
    for (std::uint32_t e : tr.e) D = lcm(D, f_.edge_points(e) + 1);
    D = lcm(D, L);
    if (D > kMaxDenominator)
      throw std::invalid_argument(mc_.source() + ": refinement of triangle " + std::to_string(t) +
                                  " needs a denominator above 2^52 (resolution too fine)");
    *lattice = L;
    std::vector<LocalPoint> pts;
    auto add = [&](std::uint32_t id, std::int64_t a1, std::int64_t a2) {
      const double w1 = static_cast<double>(a1) / D, w2 = static_cast<double>(a2) / D;
      pts.push_back({id, a1, a2, {1 - w1 - w2, w1, w2}});
    };
    add(tr.v[0], 0, 0);
    add(tr.v[1], D, 0);
    add(tr.v[2], 0, D);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t e = tr.e[k];
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      const std::int64_t n1 = f_.edge_points(e) + 1, step = D / n1;
      const bool forward = mc_.edge(e).v[0] == tr.v[a];
      for (std::int64_t i = 1; i < n1; ++i) {
        std::int64_t weight[3] = {0, 0, 0};  // of the corners, times D
        weight[a] = (forward ? n1 - i : i) * step;
        weight[b] = D - weight[a];
        add(edge_vertex(e, static_cast<std::uint32_t>(i)), weight[1], weight[2]);
      }
    }
    const std::int64_t step = D / L;
    for (std::int64_t j = 1; j < L; ++j)
      for (std::int64_t m = 1; j + m < L; ++m) add(kNoIndex, j * step, m * step);
    return pts;
  }

  void refine_triangle(std::uint32_t t) {
    const ComplexTriangle& tr = mc_.triangle(t);
    std::int64_t L;
    std::vector<LocalPoint> pts = triangle_points(t, &L);
    const Vec3d c0 = mc_.vertex(tr.v[0]).approx, c1 = mc_.vertex(tr.v[1]).approx, c2 = mc_.vertex(tr.v[2]).approx;
    const double r[3] = {mc_.vertex(tr.v[0]).radius, mc_.vertex(tr.v[1]).radius, mc_.vertex(tr.v[2]).radius};
    for (LocalPoint& p : pts) {
      if (p.id != kNoIndex) continue;
      RefinedVertex rv;
      rv.position = v3::add(c0, v3::add(v3::scale(v3::sub(c1, c0), p.weight[1]), v3::scale(v3::sub(c2, c0), p.weight[2])));
      rv.on = RefinedVertex::On::Triangle;
      rv.cell = t;
      rv.weight = p.weight;
      rv.radius = p.weight[0] * r[0] + p.weight[1] * r[1] + p.weight[2] * r[2];
      rv.bt = f_.sample_in_triangle(t, rv.position).bt;
      p.id = static_cast<std::uint32_t>(k_.vertices.size());
      k_.vertices.push_back(rv);
    }
    std::vector<std::pair<Kernel::Point_2, std::uint32_t>> input;
    for (std::uint32_t i = 0; i < pts.size(); ++i)
      input.push_back({Kernel::Point_2(static_cast<double>(pts[i].u), static_cast<double>(pts[i].w)), i});
    const Delaunay dt(input.begin(), input.end());
    std::vector<double> side(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) side[i] = f_.sample_in_triangle(t, k_.vertices[pts[i].id].position).bt;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      RefinedTriangle rt;
      rt.parent = t;
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t local = f->vertex(c)->info();
        rt.v[c] = pts[local].id;
        rt.side_bt[c] = side[local];
      }
      for (int c = 0; c < 3; ++c) rt.e[c] = edge_of(rt.v[(c + 1) % 3], rt.v[(c + 2) % 3], t);
      const std::uint32_t id = static_cast<std::uint32_t>(k_.triangles.size());
      k_.triangles.push_back(rt);
      k_.triangles[id].fire = f_.sample_in_triangle(t, k_.centroid(id)).direction;
    }
  }

  // The M edge holding both K vertices (a and b on one edge of M, or ends of it), if any.
  std::uint32_t common_edge(std::uint32_t a, std::uint32_t b, std::uint32_t t) const {
    for (std::uint32_t e : mc_.triangle(t).e) {
      auto on = [&](std::uint32_t x) {
        const RefinedVertex& v = k_.vertices[x];
        if (v.on == RefinedVertex::On::Edge) return v.cell == e;
        return v.on == RefinedVertex::On::Vertex && (mc_.edge(e).v[0] == v.cell || mc_.edge(e).v[1] == v.cell);
      };
      if (on(a) && on(b)) return e;
    }
    return kNoIndex;
  }

  std::uint32_t edge_of(std::uint32_t a, std::uint32_t b, std::uint32_t t) {
    const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
    const auto it = edge_id_.find(key);
    if (it != edge_id_.end()) return it->second;
    RefinedEdge re;
    re.v = {std::min(a, b), std::max(a, b)};
    re.on_edge = common_edge(a, b, t);
    if (re.on_edge == kNoIndex) re.in_triangle = t;
    const std::uint32_t id = static_cast<std::uint32_t>(k_.edges.size());
    k_.edges.push_back(re);
    edge_id_.emplace(key, id);
    return id;
  }

  void add_segments() {
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
      if (mc_.edge(e).stratum != EdgeStratum::Dangling) continue;
      for (std::uint32_t i = 0; i <= f_.edge_points(e); ++i) {
        RefinedEdge re;
        const std::uint32_t a = edge_vertex(e, i), b = edge_vertex(e, i + 1);
        re.v = {std::min(a, b), std::max(a, b)};
        re.on_edge = e;
        re.segment = true;
        k_.edges.push_back(re);
      }
    }
  }

  const BurningField& f_;
  const MedialComplex& mc_;
  AxisRefinement k_;
  std::vector<std::uint32_t> edge_base_;
  std::unordered_map<std::uint64_t, std::uint32_t> edge_id_;
};

}  // namespace

AxisRefinement AxisRefinement::build(const BurningField& field) { return Builder(field).run(); }

double AxisRefinement::burn_key(std::uint32_t t) const {
  const auto& b = triangles[t].side_bt;
  return std::max({b[0], b[1], b[2]});
}

double AxisRefinement::length(std::uint32_t e) const {
  return v3::dist(vertices[edges[e].v[0]].position, vertices[edges[e].v[1]].position);
}

double AxisRefinement::area(std::uint32_t t) const {
  const auto& v = triangles[t].v;
  const Vec3d a = vertices[v[0]].position;
  return v3::norm(v3::cross(v3::sub(vertices[v[1]].position, a), v3::sub(vertices[v[2]].position, a))) / 2;
}

Vec3d AxisRefinement::centroid(std::uint32_t t) const {
  const auto& v = triangles[t].v;
  Vec3d c{0, 0, 0};
  for (std::uint32_t x : v) c = v3::add(c, v3::scale(vertices[x].position, 1.0 / 3));
  return c;
}

}  // namespace grassfire
