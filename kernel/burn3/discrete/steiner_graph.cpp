// steiner_graph.cpp -- layout of the Steiner points (see header).
#include "burn3/discrete/steiner_graph.h"

#include <stdexcept>
#include <string>

namespace grassfire {

SteinerGraph::SteinerGraph(const MedialComplex& mc, double h, std::uint64_t max_points)
    : mc_(mc), spacing_(h), nv_(static_cast<std::uint32_t>(mc.vertex_count())) {
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("Steiner graph: spacing must be > 0");
  first_steiner_.assign(mc.edge_count() + 1, 0);
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    const double n = std::max(0.0, std::ceil(mc.edge(e).length / h) - 1);
    if (n + static_cast<double>(first_steiner_[e] + nv_) > static_cast<double>(max_points))
      throw std::invalid_argument("Steiner graph of " + mc.source() + ": more than " + std::to_string(max_points) +
                                  " graph points at spacing " + std::to_string(h));
    first_steiner_[e + 1] = first_steiner_[e] + static_cast<std::uint64_t>(n);
  }
  steiner_edge_.resize(first_steiner_.back());
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    for (std::uint64_t i = first_steiner_[e]; i < first_steiner_[e + 1]; ++i) steiner_edge_[i] = e;
  vertex_slot_.assign(nv_ + 1, 0);
  for (std::uint32_t v = 0; v < nv_; ++v) vertex_slot_[v + 1] = vertex_slot_[v] + mc.link_elements(v).size();
  edge_slot_.assign(mc.edge_count() + 1, vertex_slot_[nv_]);
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e)
    edge_slot_[e + 1] = edge_slot_[e] + steiner_count(e) * (2 + mc.edge_triangles(e).size());
  tri_edge_pos_.assign(3 * mc.triangle_count(), 0);
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    const auto& tris = mc.edge_triangles(e);
    for (std::uint32_t idx = 0; idx < tris.size(); ++idx)
      for (int c = 0; c < 3; ++c)
        if (mc.triangle(tris[idx]).e[c] == e) tri_edge_pos_[3 * tris[idx] + c] = idx;
  }
}

Vec3d SteinerGraph::position(std::uint32_t node) const {
  if (is_vertex(node)) return mc_.vertex(node).approx;
  const std::uint32_t e = edge_of(node);
  const double s = parameter(e, index_on_edge(node));
  const Vec3d& a = mc_.vertex(mc_.edge(e).v[0]).approx;
  const Vec3d& b = mc_.vertex(mc_.edge(e).v[1]).approx;
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}

}  // namespace grassfire
