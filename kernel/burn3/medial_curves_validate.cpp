// medial_curves_validate.cpp -- MedialCurves::validate (guarantees listed in the header).
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "burn3/medial_curves.h"
#include "complex3/vec3.h"
#include "medial2/union_find.h"

namespace grassfire {
namespace {

[[noreturn]] void fail(const MedialComplex& mc, const std::string& what) {
  throw std::logic_error("medial curves of " + mc.source() + ": " + what);
}

double segment_distance(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = v3::sub(b, a);
  const double len2 = v3::dot(ab, ab);
  const double s = len2 > 0 ? std::clamp(v3::dot(v3::sub(p, a), ab) / len2, 0.0, 1.0) : 0.0;
  return v3::dist(p, v3::lerp(a, b, s));
}

// Distance from p to the closed triangle abc: to its plane when the projection falls
// inside (barycentric signs), else to the nearest side.
double triangle_distance(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d n = v3::cross(v3::sub(b, a), v3::sub(c, a));
  const double n2 = v3::dot(n, n);
  if (n2 > 0) {
    const Vec3d ap = v3::sub(p, a);
    const double along = v3::dot(ap, n) / n2;
    const Vec3d q = v3::sub(p, v3::scale(n, along));
    const double wa = v3::dot(v3::cross(v3::sub(b, q), v3::sub(c, q)), n);
    const double wb = v3::dot(v3::cross(v3::sub(c, q), v3::sub(a, q)), n);
    const double wc = v3::dot(v3::cross(v3::sub(a, q), v3::sub(b, q)), n);
    if (wa >= 0 && wb >= 0 && wc >= 0) return std::abs(along) * std::sqrt(n2);
  }
  return std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
}

double bounding_diagonal(const MedialComplex& mc) {
  Vec3d lo = mc.vertex(0).approx, hi = lo;
  for (const ComplexVertex& v : mc.vertices())
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v.approx[i]), hi[i] = std::max(hi[i], v.approx[i]);
  return v3::dist(lo, hi);
}

}  // namespace

void MedialCurves::validate(const MedialComplex& mc) const {
  if (stats.residual_triangles != 0)
    fail(mc, std::to_string(stats.residual_triangles) + " triangles could not be collapsed: not 1-dimensional");
  const double tolerance = 1e-9 * std::max(1.0, bounding_diagonal(mc));
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const CurveEdge& e = edges[i];
    const std::string name = "edge " + std::to_string(i);
    if (e.u >= nodes.size() || e.v >= nodes.size() || e.u == e.v) fail(mc, name + " has bad end nodes");
    if (!seen.insert({std::min(e.u, e.v), std::max(e.u, e.v)}).second) fail(mc, name + " repeats an edge");
    const Vec3d a = nodes[e.u].position, b = nodes[e.v].position;
    if (std::abs(v3::dist(a, b) - e.length) > 1e-12 * std::max(1.0, e.length)) fail(mc, name + " has a wrong length");
    double off = 0;
    if ((e.on_edge == kNoIndex) == (e.in_triangle == kNoIndex)) fail(mc, name + " has no single parent cell");
    if (e.on_edge != kNoIndex) {
      if (e.on_edge >= mc.edge_count()) fail(mc, name + ": parent edge out of range");
      const Vec3d p = mc.vertex(mc.edge(e.on_edge).v[0]).approx, q = mc.vertex(mc.edge(e.on_edge).v[1]).approx;
      off = std::max(segment_distance(a, p, q), segment_distance(b, p, q));
    } else {
      if (e.in_triangle >= mc.triangle_count()) fail(mc, name + ": parent triangle out of range");
      const auto& t = mc.triangle(e.in_triangle).v;
      const Vec3d p = mc.vertex(t[0]).approx, q = mc.vertex(t[1]).approx, r = mc.vertex(t[2]).approx;
      off = std::max(triangle_distance(a, p, q, r), triangle_distance(b, p, q, r));
    }
    if (off > tolerance) fail(mc, name + " leaves its cell of the axis by " + std::to_string(off));
  }
  UnionFind uf(nodes.size());
  for (const CurveEdge& e : edges) uf.unite(e.u, e.v);
  long b0 = 0;
  for (std::uint32_t v = 0; v < nodes.size(); ++v) b0 += uf.find(v) == v ? 1 : 0;
  const long b1 = static_cast<long>(edges.size()) - static_cast<long>(nodes.size()) + b0;
  if (b0 != curve_betti.b0 || b1 != curve_betti.b1) fail(mc, "stored Betti numbers of the graph are wrong");
  const BettiNumbers axis = complex_betti(mc);
  if (!(axis == axis_betti)) fail(mc, "stored Betti numbers of the axis are wrong");
  if (b0 != axis.b0 || b1 != axis.b1)
    fail(mc, "graph has b0 = " + std::to_string(b0) + ", b1 = " + std::to_string(b1) + "; the axis has b0 = " +
                 std::to_string(axis.b0) + ", b1 = " + std::to_string(axis.b1));
}

}  // namespace grassfire
