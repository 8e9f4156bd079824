// closed_subcomplex.cpp -- peeling free faces (see header).
#include "complex3/closed_subcomplex.h"

namespace grassfire {

ClosedSubcomplex maximal_closed_subcomplex(const MedialComplex& mc) {
  ClosedSubcomplex k;
  k.triangle.assign(mc.triangle_count(), true);
  std::vector<bool> segment(mc.edge_count(), false);
  std::vector<std::size_t> edge_cells(mc.edge_count(), 0);    // kept triangles (+1 for a kept segment)
  std::vector<std::size_t> vertex_cells(mc.vertex_count(), 0);  // kept triangles and segments at the vertex
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    segment[e] = mc.edge(e).stratum == EdgeStratum::Dangling;
    edge_cells[e] = segment[e] ? 1 : mc.edge_triangles(e).size();
    if (segment[e])
      for (std::uint32_t v : mc.edge(e).v) ++vertex_cells[v];
  }
  for (const ComplexTriangle& t : mc.triangles())
    for (std::uint32_t v : t.v) ++vertex_cells[v];
  std::vector<std::uint32_t> work_edges, work_vertices;
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    if (!segment[e] && edge_cells[e] == 1) work_edges.push_back(e);
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (vertex_cells[v] == 1) work_vertices.push_back(v);
  auto drop_segment = [&](std::uint32_t e) {
    segment[e] = false;
    edge_cells[e] = 0;
    for (std::uint32_t v : mc.edge(e).v)
      if (--vertex_cells[v] == 1) work_vertices.push_back(v);
  };
  while (!work_edges.empty() || !work_vertices.empty()) {
    if (!work_edges.empty()) {
      const std::uint32_t e = work_edges.back();
      work_edges.pop_back();
      if (segment[e] || edge_cells[e] != 1) continue;
      for (std::uint32_t t : mc.edge_triangles(e)) {
        if (!k.triangle[t]) continue;
        k.triangle[t] = false;  // the free triangle on e
        for (std::uint32_t f : mc.triangle(t).e)
          if (--edge_cells[f] == 1) work_edges.push_back(f);
        for (std::uint32_t v : mc.triangle(t).v)
          if (--vertex_cells[v] == 1) work_vertices.push_back(v);
      }
      continue;
    }
    const std::uint32_t v = work_vertices.back();
    work_vertices.pop_back();
    if (vertex_cells[v] != 1) continue;
    for (std::uint32_t e : mc.vertex_edges(v))
      if (segment[e]) drop_segment(e);  // the only cell at v is this segment: a free end
  }
  k.edge.assign(mc.edge_count(), false);
  k.vertex.assign(mc.vertex_count(), false);
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) k.edge[e] = edge_cells[e] > 0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) k.vertex[v] = vertex_cells[v] > 0;
  for (bool b : k.triangle) k.triangles += b;
  for (bool b : k.edge) k.edges += b;
  for (bool b : k.vertex) k.vertices += b;
  return k;
}

}  // namespace grassfire
