// medial_complex_reference.cpp -- see medial_complex_reference.h.
#include "complex3/medial_complex_reference.h"

#include <algorithm>

namespace grassfire {

ReferenceDecisions reference_decisions(const MedialComplex& mc) {
  ReferenceDecisions out;
  out.edge_triangles.resize(mc.edge_count());
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    const ComplexEdge& edge = mc.edge(e);
    std::vector<std::uint32_t> tris = mc.edge_triangles(e);
    std::sort(tris.begin(), tris.end());  // the construction's input order: by triangle id
    if (tris.size() >= 2) {
      const EdgeAngularOrder order(mc.vertex(edge.v[0]).exact, mc.vertex(edge.v[1]).exact);
      std::vector<std::pair<ExactPoint3, std::uint32_t>> keyed;
      for (std::uint32_t t : tris) keyed.emplace_back(order.direction(mc.vertex(third_vertex(mc.triangle(t), edge.v)).exact), t);
      const ExactPoint3 ref = keyed.front().first;
      std::stable_sort(keyed.begin(), keyed.end(),
                       [&](const auto& p, const auto& q) { return order.compare(ref, p.first, q.first) < 0; });
      for (std::size_t i = 0; i < tris.size(); ++i) tris[i] = keyed[i].second;
    }
    out.edge_triangles[e] = std::move(tris);
  }
  for (const Sheet& s : mc.sheets()) {
    const auto& t0 = mc.triangle(s.triangles.front()).v;
    const ExactPoint3 &a = mc.vertex(t0[0]).exact, &b = mc.vertex(t0[1]).exact, &c = mc.vertex(t0[2]).exact;
    bool planar = true;
    for (std::uint32_t t : s.triangles)
      for (std::uint32_t v : mc.triangle(t).v) planar = planar && orientation(a, b, c, mc.vertex(v).exact) == 0;
    out.sheet_planar.push_back(planar);
  }
  return out;
}

std::size_t reference_mismatches(const MedialComplex& mc, const ReferenceDecisions& ref) {
  std::size_t bad = 0;
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) bad += ref.edge_triangles[e] != mc.edge_triangles(e);
  for (std::size_t s = 0; s < mc.sheets().size(); ++s) bad += ref.sheet_planar[s] != mc.sheets()[s].planar;
  return bad;
}

}  // namespace grassfire
