// burning_paths.cpp -- burning paths of vertices, curve nodes and points (see header).
#include "curves3/burning_paths.h"

#include <algorithm>
#include <cmath>

#include "geometry3/vec3.h"

namespace grassfire {
namespace {

BurningPath make(std::vector<Vec3d> points, double bt) {
  BurningPath p;
  p.length = polyline_length(points);
  p.points = std::move(points);
  p.bt = bt;
  return p;
}

}  // namespace

std::vector<BurningPath> paths_from_vertices(const BurningField& field) {
  std::vector<BurningPath> out;
  for (std::uint32_t v = 0; v < field.complex().vertex_count(); ++v)
    out.push_back(make(field.path_from_vertex(v), field.vertex_burn_time(v)));
  return out;
}

std::vector<BurningPath> paths_from_curve_nodes(const BurningField& field, const MedialCurves& curves) {
  std::vector<BurningPath> out;
  for (const CurveNode& n : curves.nodes) {
    if (n.on == RefinedVertex::On::Vertex)
      out.push_back(make(field.path_from_vertex(n.cell), n.bt));
    else if (n.on == RefinedVertex::On::Edge)
      out.push_back(make(field.path_from_edge_point(n.cell, n.index), n.bt));
    else
      out.push_back(make(field.path_in_triangle(n.cell, n.position), n.bt));
  }
  return out;
}

std::vector<BurningPath> paths_ending_on_curves(const BurningField& field, const MedialCurves& curves,
                                                double arrive_cosine) {
  const MedialComplex& mc = field.complex();
  std::vector<BurningPath> out;
  for (const CurveNode& n : curves.nodes) {
    if (n.on == RefinedVertex::On::Triangle) {
      out.push_back(make(field.path_in_triangle(n.cell, n.position), n.bt));
      continue;
    }
    if (n.on != RefinedVertex::On::Edge) continue;
    const Vec3d a = mc.vertex(mc.edge(n.cell).v[0]).approx, b = mc.vertex(mc.edge(n.cell).v[1]).approx;
    const Vec3d along = v3::unit(v3::sub(b, a));
    for (std::uint32_t t : mc.edge_triangles(n.cell)) {
      const Vec3d apex = mc.vertex(third_vertex(mc.triangle(t), mc.edge(n.cell).v)).approx;
      Vec3d out_dir = v3::sub(n.position, apex);
      out_dir = v3::unit(v3::sub(out_dir, v3::scale(along, v3::dot(out_dir, along))));
      const FieldSample s = field.sample_in_triangle(t, n.position);
      if (std::isfinite(s.bt) && v3::dot(s.direction, out_dir) > arrive_cosine)
        out.push_back(make(field.path_in_triangle(t, n.position), s.bt));
    }
  }
  return out;
}

std::vector<BurningPath> paths_from_points(const BurningField& field, const std::vector<CellPoint>& points) {
  std::vector<BurningPath> out;
  for (const CellPoint& c : points) {
    if (c.kind == CellPoint::Kind::Vertex)
      out.push_back(make(field.path_from_vertex(c.cell), field.vertex_burn_time(c.cell)));
    else if (c.kind == CellPoint::Kind::Segment)
      out.push_back(make(field.path_on_segment(c.cell, c.s), field.sample_on_segment(c.cell, c.s).bt));
    else
      out.push_back(make(field.path_in_triangle(c.cell, c.p), field.sample_in_triangle(c.cell, c.p).bt));
  }
  return out;
}

CellPoint cell_point(const BurningField& field, const ComplexPoint& x) {
  const MedialComplex& mc = field.complex();
  if (x.kind == ComplexPoint::Kind::Vertex) return {CellPoint::Kind::Vertex, x.id, x.approx(), 0};
  if (x.kind == ComplexPoint::Kind::Triangle) return {CellPoint::Kind::Triangle, x.id, x.approx(), 0};
  const double s = x.parameter.get_d();
  const auto& tris = mc.edge_triangles(x.id);
  if (tris.empty()) return {CellPoint::Kind::Segment, x.id, x.approx(), s};
  std::vector<std::pair<double, std::uint32_t>> sides;
  for (std::uint32_t t : tris) sides.push_back({field.sample_in_triangle(t, x.approx()).bt, t});
  std::sort(sides.begin(), sides.end());
  const std::size_t rule = tris.size() >= 3 ? tris.size() - 2 : 0;
  return {CellPoint::Kind::Triangle, sides[rule].second, x.approx(), 0};
}

}  // namespace grassfire
