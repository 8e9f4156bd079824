// medial_complex_validate.cpp -- MedialComplex::validate(): the contract and every derived
// structure, re-checked by local conditions independent of how construction found them.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "complex3/complex_checks.h"
#include "complex3/medial_complex.h"
#include "complex3/medial_complex_detail.h"

namespace grassfire {
namespace {

[[noreturn]] void violation(const std::string& source, const std::string& what) {
  throw std::logic_error("MedialComplex " + source + " invalid: " + what);
}

bool shares_manifold_edge_at(const MedialComplex& mc, std::uint32_t t0, std::uint32_t t1, std::uint32_t apex) {
  for (std::uint32_t e0 : edges_at(mc.triangle(t0), apex))
    for (std::uint32_t e1 : edges_at(mc.triangle(t1), apex))
      if (e0 == e1 && mc.edge(e0).stratum == EdgeStratum::Manifold) return true;
  return false;
}

void check_edges(const MedialComplex& mc, const FilteredPoints& points) {
  const std::string& src = mc.source();
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    const ComplexEdge& ed = mc.edge(e);
    if (ed.v[0] >= ed.v[1] || ed.v[1] >= mc.vertex_count()) violation(src, "edge " + std::to_string(e) + " ends");
    const auto& tris = mc.edge_triangles(e);
    const std::size_t k = tris.size();
    const EdgeStratum expect = k == 0   ? EdgeStratum::Dangling
                               : k == 1 ? EdgeStratum::Border
                               : k == 2 ? EdgeStratum::Manifold
                                        : EdgeStratum::Singular;
    if (ed.stratum != expect) violation(src, "edge " + std::to_string(e) + " stratum does not match its triangles");
    if (ed.stratum != EdgeStratum::Border && ed.rule != IgnitionRule::Linear)
      violation(src, "edge " + std::to_string(e) + " has an ignition rule but is not a border edge");
    if (mc.find_edge(ed.v[0], ed.v[1]) != e) violation(src, "edge " + std::to_string(e) + " is not unique");
    for (std::uint32_t t : tris) {
      const ComplexTriangle& tr = mc.triangle(t);
      const int c = corner_of(tr, third_vertex(tr, ed.v));
      if (corner_of(tr, ed.v[0]) < 0 || corner_of(tr, ed.v[1]) < 0 || tr.e[c] != e)
        violation(src, "triangle " + std::to_string(t) + " listed on edge " + std::to_string(e) + " wrongly");
    }
    if (k < 2) continue;
    const FilteredEdgeOrder order(points, ed.v[0], ed.v[1]);
    auto third = [&](std::uint32_t t) { return third_vertex(mc.triangle(t), ed.v); };
    const std::uint32_t ref = third(tris[0]);
    for (std::size_t i = 0; i + 1 < k; ++i)
      if (order.compare(ref, third(tris[i]), third(tris[i + 1])) >= 0)
        violation(src, "triangles around edge " + std::to_string(e) + " are not in strict angular order");
  }
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      const ComplexTriangle& tr = mc.triangle(t);
      const ComplexEdge& ed = mc.edge(tr.e[i]);
      const std::array<std::uint32_t, 2> ends = {std::min(tr.v[(i + 1) % 3], tr.v[(i + 2) % 3]),
                                                 std::max(tr.v[(i + 1) % 3], tr.v[(i + 2) % 3])};
      if (ed.v != ends) violation(src, "triangle " + std::to_string(t) + " edge " + std::to_string(i) + " is wrong");
    }
}

void check_sheets(const MedialComplex& mc, const FilteredPoints& points) {
  const std::string& src = mc.source();
  SheetPlanarity planarity(points, mc.triangles());
  std::vector<int> seen(mc.triangle_count(), 0);
  for (std::uint32_t s = 0; s < mc.sheets().size(); ++s) {
    const Sheet& sh = mc.sheets()[s];
    if (sh.triangles.empty()) violation(src, "sheet " + std::to_string(s) + " is empty");
    for (std::uint32_t t : sh.triangles) {
      ++seen[t];
      if (mc.triangle(t).sheet != s) violation(src, "triangle " + std::to_string(t) + " has the wrong sheet id");
    }
    // Planarity against the plane of the sheet's first triangle, recomputed.
    const bool planar = planarity.planar(sh);
    if (planar != sh.planar) violation(src, "sheet " + std::to_string(s) + " planarity flag is wrong");
  }
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
    if (seen[t] != 1) violation(src, "triangle " + std::to_string(t) + " is in " + std::to_string(seen[t]) + " sheets");
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    if (mc.edge(e).stratum == EdgeStratum::Manifold &&
        mc.triangle(mc.edge_triangles(e)[0]).sheet != mc.triangle(mc.edge_triangles(e)[1]).sheet)
      violation(src, "manifold edge " + std::to_string(e) + " separates two sheets");
}

bool is_pole_edge(const MedialComplex& mc, std::uint32_t e) {
  return mc.edge(e).stratum == EdgeStratum::Singular || mc.edge(e).stratum == EdgeStratum::Dangling;
}

void check_sector(const MedialComplex& mc, std::uint32_t id) {
  const std::string& src = mc.source();
  const Sector& s = mc.sectors()[id];
  const std::string name = "sector " + std::to_string(id);
  if (s.triangles.empty()) violation(src, name + " is empty");
  for (std::size_t i = 0; i + 1 < s.triangles.size(); ++i)
    if (!shares_manifold_edge_at(mc, s.triangles[i], s.triangles[i + 1], s.apex))
      violation(src, name + " is not a fan joined across manifold edges");
  for (std::uint32_t t : s.triangles)
    if (mc.triangle(t).sheet != s.sheet) violation(src, name + " crosses sheets");
  if (s.closed) {
    if (s.ends[0] != kNoIndex || !shares_manifold_edge_at(mc, s.triangles.back(), s.triangles.front(), s.apex) ||
        (s.triangles.size() < 3))
      violation(src, name + " is marked closed but is not a circle");
    return;
  }
  for (std::uint32_t e : s.ends)
    if (e == kNoIndex || mc.edge(e).stratum == EdgeStratum::Manifold || mc.edge(e).stratum == EdgeStratum::Dangling)
      violation(src, name + " ends at an edge that is not a pole or a border edge");
  auto has = [&](std::uint32_t t, std::uint32_t e) {
    const auto es = edges_at(mc.triangle(t), s.apex);
    return es[0] == e || es[1] == e;
  };
  if (!has(s.triangles.front(), s.ends[0]) || !has(s.triangles.back(), s.ends[1]))
    violation(src, name + " ends do not bound its fan");
}

void check_links(const MedialComplex& mc) {
  const std::string& src = mc.source();
  std::vector<int> corner_seen(3 * mc.triangle_count(), 0);
  for (std::uint32_t id = 0; id < mc.sectors().size(); ++id) {
    check_sector(mc, id);
    const Sector& s = mc.sectors()[id];
    for (std::uint32_t t : s.triangles) {
      ++corner_seen[3 * t + corner_of(mc.triangle(t), s.apex)];
      const LinkElement& el = mc.link_elements(s.apex).at(mc.corner_element(t, corner_of(mc.triangle(t), s.apex)));
      if (el.is_pole || el.id != id) violation(src, "corner of triangle " + std::to_string(t) + " maps to another sector");
    }
  }
  for (std::size_t c = 0; c < corner_seen.size(); ++c)
    if (corner_seen[c] != 1) violation(src, "corner " + std::to_string(c) + " is not in exactly one sector");
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    std::size_t poles = 0;
    for (const LinkElement& el : mc.link_elements(v)) {
      if (!el.is_pole) continue;
      ++poles;
      if (!is_pole_edge(mc, el.id) || (mc.edge(el.id).v[0] != v && mc.edge(el.id).v[1] != v))
        violation(src, "vertex " + std::to_string(v) + " lists a pole that is not one of its pole edges");
    }
    const auto incident = static_cast<std::size_t>(std::count_if(mc.vertex_edges(v).begin(), mc.vertex_edges(v).end(),
                                                                 [&](std::uint32_t e) { return is_pole_edge(mc, e); }));
    if (poles != incident) violation(src, "vertex " + std::to_string(v) + " misses poles in its link");
    const VertexKind k = mc.vertex(v).kind;
    const bool one_closed = poles == 0 && mc.link_elements(v).size() == 1 && mc.sectors()[mc.link_elements(v)[0].id].closed;
    if ((k == VertexKind::Interior) != one_closed) violation(src, "vertex " + std::to_string(v) + " interior kind");
    if ((k == VertexKind::Isolated) != mc.link_elements(v).empty())
      violation(src, "vertex " + std::to_string(v) + " isolated kind");
    if (!mc.is_border_point(v) && std::isfinite(mc.ignition_at_vertex(v)))
      violation(src, "vertex " + std::to_string(v) + " ignites but is not a border point");
  }
}

}  // namespace

void MedialComplex::validate() const {
  const FilteredPoints points(vertices_.size(), [&](std::size_t v) -> const ExactPoint3& { return vertices_[v].exact; });
  for (const ComplexVertex& v : vertices_)
    if (v.approx != to_double(v.exact)) violation(source_, "a vertex approximation is stale");
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(triangles_.size());
  for (const ComplexTriangle& t : triangles_) triangles.push_back(t.v);
  std::vector<std::array<std::uint32_t, 2>> segments;
  for (std::uint32_t e = 0; e < edges_.size(); ++e)
    if (edges_[e].stratum == EdgeStratum::Dangling) segments.push_back(edges_[e].v);
  const auto radius = [&](std::size_t v) -> const mpq_class& { return vertices_[v].radius_squared; };
  if (auto problem = first_raw_violation(points, radius, vertices_.size(), triangles, segments))
    violation(source_, *problem);
  check_edges(*this, points);
  check_sheets(*this, points);
  check_links(*this);
  validate_frames();
}

}  // namespace grassfire
