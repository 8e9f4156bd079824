// axis_resolution.cpp -- see axis_resolution.h.
#include "medial3/mesh/axis_resolution.h"

#include <algorithm>
#include <cmath>

#include "support/union_find.h"

namespace grassfire {

std::vector<double> sample_spacing(const SurfaceSamples& samples, const std::vector<double>& triangle_spacing) {
  std::vector<double> out(samples.lattice.size(), INFINITY);
  for (std::size_t t = 0; t + 1 < samples.offset.size(); ++t)
    for (std::uint32_t i = samples.offset[t]; i < samples.offset[t + 1]; ++i) {
      double& h = out[samples.on_triangle[i]];
      h = std::min(h, triangle_spacing[t] / samples.grid);
    }
  return out;
}

// R(x) < T, T = (lambda / 2) h(x) in lattice units: |N|^2 < T^2 D^2, exactly.
bool ResolutionTest::unresolved(std::uint32_t vertex) const {
  if (!(half_lambda_ > 0)) return false;
  const LatticeCentre& c = vor_.vertices[vertex].centre;
  double h = INFINITY;
  for (std::uint32_t s : c.tetrahedron) h = std::min(h, spacing_[s]);
  const double threshold = half_lambda_ * h;
  if (!std::isfinite(threshold)) return true;
  Interval n2(0.0);
  for (int k = 0; k < 3; ++k) n2 += square(enclose_integer(c.num[k]));
  const int sign = certified_sign(n2 - square(Interval(threshold)) * square(enclose_integer(c.den)));
  if (sign != kUndecided) return sign < 0;
  mpq_class nn = 0;
  for (int k = 0; k < 3; ++k) nn += to_mpq(c.num[k]) * to_mpq(c.num[k]);
  const mpq_class t(threshold), den = to_mpq(c.den);
  return nn < t * t * den * den;
}

UnresolvedComponents unresolved_components(std::size_t vertex_count, const PolygonRings& polygons,
                                           const std::vector<std::array<std::uint32_t, 2>>& segments,
                                           const std::function<bool(std::uint32_t vertex)>& unresolved) {
  UnionFind components(vertex_count);
  for (std::size_t i = 0; i < polygons.size(); ++i)
    for (std::uint32_t k = 0; k < polygons.ring_size(i); ++k) {
      const auto [a, b] = polygons.side(i, k);
      components.unite(a, b);
    }
  for (const auto& s : segments) components.unite(s[0], s[1]);
  std::vector<bool> resolved_root(vertex_count, false);
  for (std::uint32_t v = 0; v < vertex_count; ++v)
    if (!unresolved(v)) resolved_root[components.find(v)] = true;
  UnresolvedComponents out;
  out.vertex_dropped.assign(vertex_count, false);
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    const std::uint32_t root = components.find(v);
    if (resolved_root[root]) continue;
    out.vertex_dropped[v] = true;
    if (root == v) ++out.components;  // the root is the component's smallest id
  }
  return out;
}

}  // namespace grassfire
