// shape_analysis.cpp -- planar / tubular split, signature, surface values (see header).
#include "curves3/shape_analysis.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "geometry3/vec3.h"
#include "support/union_find.h"

namespace grassfire {
namespace {

double tubularity(double radius, double bt) {
  if (!std::isfinite(bt)) return 1;
  return bt > 0 ? 1 - radius / bt : 1;
}

// Areas of the connected parts of the planar triangles (joined across shared edges).
std::vector<double> part_areas(const AxisRefinement& k, const std::vector<bool>& planar) {
  UnionFind uf(k.triangles.size());
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    const auto& tris = k.edge_triangles[e];
    for (std::size_t i = 1; i < tris.size(); ++i)
      if (planar[tris[0]] && planar[tris[i]]) uf.unite(tris[0], tris[i]);
  }
  std::vector<double> area(k.triangles.size(), 0);
  for (std::uint32_t t = 0; t < k.triangles.size(); ++t)
    if (planar[t]) area[uf.find(t)] += k.area(t);
  std::vector<double> parts;
  for (double a : area)
    if (a > 0) parts.push_back(a);
  std::sort(parts.rbegin(), parts.rend());
  return parts;
}

// Lengths of the chains of tubular curve edges, cut at nodes whose tubular degree is not 2.
std::vector<double> branch_lengths(const MedialCurves& c, const std::vector<bool>& tubular) {
  std::vector<std::vector<std::uint32_t>> incident(c.nodes.size());
  for (std::uint32_t e = 0; e < c.edges.size(); ++e)
    if (tubular[e]) incident[c.edges[e].u].push_back(e), incident[c.edges[e].v].push_back(e);
  std::vector<bool> used(c.edges.size(), false);
  std::vector<double> out;
  auto walk = [&](std::uint32_t from, std::uint32_t e) {
    double length = 0;
    for (std::size_t guard = 0; guard <= c.edges.size() && !used[e]; ++guard) {
      used[e] = true;
      length += c.edges[e].length;
      const std::uint32_t to = c.edges[e].u == from ? c.edges[e].v : c.edges[e].u;
      if (incident[to].size() != 2) break;
      e = incident[to][0] == e ? incident[to][1] : incident[to][0];
      from = to;
    }
    out.push_back(length);
  };
  for (std::uint32_t n = 0; n < c.nodes.size(); ++n)
    if (incident[n].size() != 2)
      for (std::uint32_t e : incident[n])
        if (!used[e]) walk(n, e);
  for (std::uint32_t e = 0; e < c.edges.size(); ++e)  // closed loops
    if (tubular[e] && !used[e]) walk(c.edges[e].u, e);
  std::sort(out.rbegin(), out.rend());
  return out;
}

}  // namespace

ShapeAnalysis analyze_shape(const AxisRefinement& k, const MedialCurves& curves, const ShapeAnalysisOptions& options) {
  ShapeAnalysis a;
  a.planar.resize(k.triangles.size());
  a.tubularity.resize(k.triangles.size());
  for (std::uint32_t t = 0; t < k.triangles.size(); ++t) {
    double r = 0, bt = 0;
    for (int c = 0; c < 3; ++c) r += k.vertices[k.triangles[t].v[c]].radius / 3, bt += k.triangles[t].side_bt[c] / 3;
    a.tubularity[t] = tubularity(r, bt);
    a.planar[t] = a.tubularity[t] >= options.planar_tubularity;
    (a.planar[t] ? a.signature.planar_area : a.signature.tubular_area) += k.area(t);
  }
  a.tubular_edge.resize(curves.edges.size());
  for (std::uint32_t e = 0; e < curves.edges.size(); ++e) {
    const CurveNode &u = curves.nodes[curves.edges[e].u], &v = curves.nodes[curves.edges[e].v];
    // On a dangling segment of M (a 1-dimensional part of the axis: a tube's axis itself)
    // the edge is tubular by definition: ST would measure its length, not a sideways extent.
    a.tubular_edge[e] =
        curves.edges[e].segment || tubularity((u.radius + v.radius) / 2, (u.bt + v.bt) / 2) < options.planar_tubularity;
    (a.tubular_edge[e] ? a.signature.tubular_curve_length : a.signature.planar_curve_length) += curves.edges[e].length;
  }
  a.signature.sheet_areas = part_areas(k, a.planar);
  a.signature.curve_lengths = branch_lengths(curves, a.tubular_edge);
  return a;
}

SurfaceValues map_to_surface(const AxisRefinement& k, const std::vector<Vec3d>& points) {
  std::vector<std::uint32_t> samples;
  double max_radius = 0;
  for (std::uint32_t v = 0; v < k.vertices.size(); ++v)
    if (std::isfinite(k.vertices[v].bt)) samples.push_back(v), max_radius = std::max(max_radius, k.vertices[v].radius);
  SurfaceValues out;
  const double inf = std::numeric_limits<double>::infinity();
  for (const Vec3d& p : points) {
    double best = inf;
    std::uint32_t at = kNoIndex;
    for (std::uint32_t v : samples) {
      const RefinedVertex& x = k.vertices[v];
      const double d2 = v3::dot(v3::sub(p, x.position), v3::sub(p, x.position));
      if (std::isfinite(best) && d2 > (best + max_radius) * (best + max_radius)) continue;  // |p - x| - R >= best
      const double gap = std::sqrt(d2) - x.radius;
      if (gap < best) best = gap, at = v;
    }
    const double bt = at == kNoIndex ? inf : k.vertices[at].bt, r = at == kNoIndex ? 0 : k.vertices[at].radius;
    out.bt.push_back(bt);
    out.radius.push_back(r);
    out.et.push_back(bt - r);
    out.gap.push_back(best);
  }
  return out;
}

}  // namespace grassfire
