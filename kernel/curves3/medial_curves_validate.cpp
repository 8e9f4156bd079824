// medial_curves_validate.cpp -- MedialCurves::validate (guarantees listed in the header).
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "curves3/medial_curves.h"
#include "geometry3/vec3.h"
#include "support/union_find.h"

namespace grassfire {
namespace {

[[noreturn]] void fail(const MedialComplex& mc, const std::string& what) {
  throw std::logic_error("medial curves of " + mc.source() + ": " + what);
}

// The node as the convex combination of its cell's vertices (its weights).
Vec3d from_weights(const MedialComplex& mc, const CurveNode& n) {
  switch (n.on) {
    case RefinedVertex::On::Vertex: return mc.vertex(n.cell).approx;
    case RefinedVertex::On::Edge:
      return v3::add(v3::scale(mc.vertex(mc.edge(n.cell).v[0]).approx, n.weight[0]),
                     v3::scale(mc.vertex(mc.edge(n.cell).v[1]).approx, n.weight[1]));
    case RefinedVertex::On::Triangle: {
      const auto& v = mc.triangle(n.cell).v;
      return v3::add(v3::scale(mc.vertex(v[0]).approx, n.weight[0]),
                     v3::add(v3::scale(mc.vertex(v[1]).approx, n.weight[1]), v3::scale(mc.vertex(v[2]).approx, n.weight[2])));
    }
  }
  return n.position;
}

bool cell_in_range(const MedialComplex& mc, const CurveNode& n) {
  switch (n.on) {
    case RefinedVertex::On::Vertex: return n.cell < mc.vertex_count();
    case RefinedVertex::On::Edge: return n.cell < mc.edge_count();
    case RefinedVertex::On::Triangle: return n.cell < mc.triangle_count();
  }
  return false;
}

// Does node n lie in the closure of the edge e of M, or of the triangle t of M?
bool in_edge(const MedialComplex& mc, const CurveNode& n, std::uint32_t e) {
  if (n.on == RefinedVertex::On::Vertex) return mc.edge(e).v[0] == n.cell || mc.edge(e).v[1] == n.cell;
  return n.on == RefinedVertex::On::Edge && n.cell == e;
}
bool in_triangle(const MedialComplex& mc, const CurveNode& n, std::uint32_t t) {
  const ComplexTriangle& tr = mc.triangle(t);
  switch (n.on) {
    case RefinedVertex::On::Vertex: return corner_of(tr, n.cell) >= 0;
    case RefinedVertex::On::Edge: return tr.e[0] == n.cell || tr.e[1] == n.cell || tr.e[2] == n.cell;
    case RefinedVertex::On::Triangle: return n.cell == t;
  }
  return false;
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
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const CurveNode& n = nodes[i];
    const std::string name = "node " + std::to_string(i);
    if (!cell_in_range(mc, n)) fail(mc, name + ": its cell is out of range");
    const double sum = n.weight[0] + n.weight[1] + n.weight[2];
    for (double w : n.weight)
      if (!(w >= -1e-12 && w <= 1 + 1e-12)) fail(mc, name + " is not a convex combination of its cell");
    if (std::abs(sum - 1) > 1e-12) fail(mc, name + " is not a convex combination of its cell");
    const double off = v3::dist(n.position, from_weights(mc, n));
    if (off > tolerance) fail(mc, name + " leaves its cell of the axis by " + std::to_string(off));
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const CurveEdge& e = edges[i];
    const std::string name = "edge " + std::to_string(i);
    if (e.u >= nodes.size() || e.v >= nodes.size() || e.u == e.v) fail(mc, name + " has bad end nodes");
    if (!seen.insert({std::min(e.u, e.v), std::max(e.u, e.v)}).second) fail(mc, name + " repeats an edge");
    const Vec3d a = nodes[e.u].position, b = nodes[e.v].position;
    if (std::abs(v3::dist(a, b) - e.length) > 1e-12 * std::max(1.0, e.length)) fail(mc, name + " has a wrong length");
    if ((e.on_edge == kNoIndex) == (e.in_triangle == kNoIndex)) fail(mc, name + " has no single parent cell");
    const bool inside = e.on_edge != kNoIndex
                            ? e.on_edge < mc.edge_count() && in_edge(mc, nodes[e.u], e.on_edge) && in_edge(mc, nodes[e.v], e.on_edge)
                            : e.in_triangle < mc.triangle_count() && in_triangle(mc, nodes[e.u], e.in_triangle) &&
                                  in_triangle(mc, nodes[e.v], e.in_triangle);
    if (!inside) fail(mc, name + " is not a segment of one cell of the axis");
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
