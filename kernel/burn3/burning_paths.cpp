// burning_paths.cpp -- burning paths of vertices, curve nodes and points (see header).
#include "burn3/burning_paths.h"

#include <algorithm>
#include <cmath>

#include "complex3/vec3.h"

namespace grassfire {
namespace {

BurningPath make(std::vector<Vec3d> points, double bt) {
  BurningPath p;
  p.length = polyline_length(points);
  p.points = std::move(points);
  p.bt = bt;
  return p;
}

// The closest point of segment ab to q, as a parameter in [0, 1].
double segment_parameter(const Vec3d& q, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = v3::sub(b, a);
  const double len2 = v3::dot(ab, ab);
  return len2 > 0 ? std::clamp(v3::dot(v3::sub(q, a), ab) / len2, 0.0, 1.0) : 0.0;
}

// The closest point of triangle abc to q (Ericson, Real-Time Collision Detection 5.1.5).
Vec3d closest_on_triangle(const Vec3d& q, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = v3::sub(b, a), ac = v3::sub(c, a), ap = v3::sub(q, a);
  const double d1 = v3::dot(ab, ap), d2 = v3::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3d bp = v3::sub(q, b);
  const double d3 = v3::dot(ab, bp), d4 = v3::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return v3::add(a, v3::scale(ab, d1 / (d1 - d3)));
  const Vec3d cp = v3::sub(q, c);
  const double d5 = v3::dot(ab, cp), d6 = v3::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return v3::add(a, v3::scale(ac, d2 / (d2 - d6)));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return v3::add(b, v3::scale(v3::sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
  const double denom = 1 / (va + vb + vc);
  return v3::add(a, v3::add(v3::scale(ab, vb * denom), v3::scale(ac, vc * denom)));
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
    if (c.on_segment)
      out.push_back(make(field.path_on_segment(c.cell, c.s), field.sample_on_segment(c.cell, c.s).bt));
    else
      out.push_back(make(field.path_in_triangle(c.cell, c.p), field.sample_in_triangle(c.cell, c.p).bt));
  }
  return out;
}

CellPoint nearest_cell_point(const MedialComplex& mc, const Vec3d& q, double* distance) {
  CellPoint best;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    const auto& v = mc.triangle(t).v;
    const Vec3d p = closest_on_triangle(q, mc.vertex(v[0]).approx, mc.vertex(v[1]).approx, mc.vertex(v[2]).approx);
    const double d = v3::dist(p, q);
    if (d < best_d) best_d = d, best = {false, t, p, 0};
  }
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    if (mc.edge(e).stratum != EdgeStratum::Dangling) continue;
    const Vec3d a = mc.vertex(mc.edge(e).v[0]).approx, b = mc.vertex(mc.edge(e).v[1]).approx;
    const double s = segment_parameter(q, a, b);
    const double d = v3::dist(v3::lerp(a, b, s), q);
    if (d < best_d) best_d = d, best = {true, e, v3::lerp(a, b, s), s};
  }
  if (distance) *distance = best_d;
  return best;
}

}  // namespace grassfire
