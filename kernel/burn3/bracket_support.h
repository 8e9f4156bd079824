// bracket_support.h -- small pieces shared by the independent references of BT
// (bt_bracket.h, bt_bracket_upper.h, junction_books.h): the singular set Sigma, and the
// minimum of a convex function of one variable.
//  - Sigma: the singular edges and dangling segments, and the vertices on them, on
//    triangles of two or more sheets, or on no triangle (4.2.2; docs/design.md 5).
//  - golden_section_minimum(f, lo, hi): min over [lo, hi] of a convex f, by golden-section
//    search until the bracket is below 1e-15 (at most 200 steps), the ends included; the
//    value is f at a point of [lo, hi] (so an upper bound of the minimum, within the
//    function's rounding of it).
// Complexity: O(degree) per vertex test; 200 evaluations of f at most.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "complex3/medial_complex.h"

namespace grassfire {

inline bool on_sigma_edge(const MedialComplex& mc, std::uint32_t e) {
  return mc.edge(e).stratum == EdgeStratum::Singular || mc.edge(e).stratum == EdgeStratum::Dangling;
}

inline bool on_sigma_vertex(const MedialComplex& mc, std::uint32_t v) {
  const auto& tris = mc.vertex_triangles(v);
  if (tris.empty()) return true;
  for (std::uint32_t e : mc.vertex_edges(v))
    if (on_sigma_edge(mc, e)) return true;
  for (std::uint32_t t : tris)
    if (mc.triangle(t).sheet != mc.triangle(tris.front()).sheet) return true;
  return false;
}

template <class F>
double golden_section_minimum(const F& f, double lo, double hi) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0, a = lo, b = hi;
  double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo), f1 = f(m1), f2 = f(m2);
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    if (f1 <= f2) {
      hi = m2, m2 = m1, f2 = f1, m1 = hi - g * (hi - lo), f1 = f(m1);
    } else {
      lo = m1, m1 = m2, f1 = f2, m2 = lo + g * (hi - lo), f2 = f(m2);
    }
  }
  return std::min({f(a), f(b), f1, f2});
}

}  // namespace grassfire
