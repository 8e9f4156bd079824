// boost_voronoi_extract.h -- the interior segment Voronoi topology (segment_voronoi.h) read
// from a Boost.Polygon voronoi_diagram of any coordinate type (the int32 default, the wide
// and the mp traits). Included by segment_voronoi_boost*.cpp only.
// Computes: from the apex of every convex polygon vertex (where its cell's two secondary
// edges meet) a depth-first search along primary edges; every vertex with its three sites
// counter-clockwise. Contract: the diagram of the polygon's segments in site order (segment
// i from vertex i to next[i]), built without Boost's vertex merging (NoMergeTraits).
// Complexity: O(n) for n polygon vertices.
#pragma once

#include <boost/polygon/voronoi_diagram.hpp>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "medial2/polygon/segment_voronoi.h"

namespace grassfire {

// Keeps every vertex the builder creates: Boost's default post-pass merges vertices
// whose coordinates agree within 128 ulps, an approximate decision we make exactly later.
template <class T>
struct NoMergeTraits {
  using coordinate_type = T;
  using cell_type = boost::polygon::voronoi_cell<T>;
  using vertex_type = boost::polygon::voronoi_vertex<T>;
  using edge_type = boost::polygon::voronoi_edge<T>;
  struct vertex_equality_predicate_type {
    bool operator()(const vertex_type&, const vertex_type&) const { return false; }
  };
};

template <class BoostCell>
std::uint32_t site_of(const BoostCell& cell, const PolygonSites& sites) {
  const std::uint32_t i = static_cast<std::uint32_t>(cell.source_index());
  switch (cell.source_category()) {
    case boost::polygon::SOURCE_CATEGORY_SEGMENT_START_POINT: return i;
    case boost::polygon::SOURCE_CATEGORY_SEGMENT_END_POINT: return sites.next[i];
    default: return sites.vertex_count() + i;
  }
}

template <class Diagram>
class BoostExtractor {
  using BoostEdge = typename Diagram::edge_type;
  using BoostVertex = typename Diagram::vertex_type;
  using BoostCell = typename Diagram::cell_type;

 public:
  BoostExtractor(const Diagram& vd, const PolygonSites& sites) : vd_(vd), sites_(sites) {}

  VoronoiTopology run() {
    id_.assign(vd_.num_vertices(), kNone);
    out_.vertices.reserve(vd_.num_vertices());
    out_.edges.reserve(vd_.num_edges() / 2);
    std::vector<const BoostEdge*> stack;
    for (const BoostCell& cell : vd_.cells()) {
      const std::uint32_t p = site_of(cell, sites_);
      if (!sites_.is_point(p) || !is_convex_vertex(sites_, p)) continue;
      const BoostVertex* apex = find_apex(cell);
      const std::uint32_t a = add_vertex(apex);
      out_.vertices[a].apex = true;
      out_.vertices[a].sites = {p, sites_.vertex_count() + sites_.prev[p], sites_.vertex_count() + p};
      for_each_out_edge(apex, [&](const BoostEdge* e) {
        if (e->is_primary()) stack.push_back(e);
      });
    }
    // Depth-first search along primary edges; an edge is emitted from its first visit.
    std::vector<bool> done(vd_.num_edges(), false);
    while (!stack.empty()) {
      const BoostEdge* e = stack.back();
      stack.pop_back();
      if (done[edge_index(e)]) continue;
      done[edge_index(e)] = true;
      done[edge_index(e->twin())] = true;
      if (!e->vertex0() || !e->vertex1())
        throw std::logic_error("boost_segment_voronoi: an interior search reached an infinite edge");
      const std::uint32_t u = id_[index(e->vertex0())];
      const bool fresh = id_[index(e->vertex1())] == kNone;
      const std::uint32_t v = add_vertex(e->vertex1());
      out_.edges.push_back({u, v, site_of(*e->cell(), sites_), site_of(*e->twin()->cell(), sites_)});
      if (!fresh || out_.vertices[v].apex) continue;
      out_.vertices[v].sites = ccw_sites(e->vertex1());
      for_each_out_edge(e->vertex1(), [&](const BoostEdge* f) {
        if (f->is_primary() && !done[edge_index(f)]) stack.push_back(f);
      });
    }
    return std::move(out_);
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  std::size_t index(const BoostVertex* v) const { return static_cast<std::size_t>(v - &vd_.vertices()[0]); }

  std::size_t edge_index(const BoostEdge* e) const { return static_cast<std::size_t>(e - &vd_.edges()[0]); }

  std::uint32_t add_vertex(const BoostVertex* v) {
    std::uint32_t& id = id_[index(v)];
    if (id == kNone) {
      id = static_cast<std::uint32_t>(out_.vertices.size());
      out_.vertices.emplace_back();
    }
    return id;
  }

  template <class F>
  static void for_each_out_edge(const BoostVertex* v, F&& f) {
    const BoostEdge* e = v->incident_edge();
    do {
      f(e);
      e = e->rot_next();
    } while (e != v->incident_edge());
  }

  // The apex of a convex vertex's (exterior) cell: where its two secondary edges meet.
  const BoostVertex* find_apex(const BoostCell& cell) const {
    const BoostEdge* e = cell.incident_edge();
    do {
      if (e->is_secondary() && e->next()->is_secondary() && e->vertex1()) return e->vertex1();
      e = e->next();
    } while (e != cell.incident_edge());
    throw std::logic_error("boost_segment_voronoi: no apex at convex vertex " +
                           std::to_string(site_of(cell, sites_)));
  }

  // Sites around v in counter-clockwise order (rot_next turns counter-clockwise and the
  // cell of an outgoing edge lies on its left).
  // Only the first three distinct sites are kept (no allocation: this runs once per vertex).
  std::array<std::uint32_t, 3> ccw_sites(const BoostVertex* v) const {
    std::array<std::uint32_t, 3> around{};
    std::size_t count = 0;
    for_each_out_edge(v, [&](const BoostEdge* e) {
      if (count == 3) return;
      const std::uint32_t s = site_of(*e->cell(), sites_);
      bool seen = false;
      for (std::size_t i = 0; i < count; ++i) seen = seen || around[i] == s;
      if (!seen) around[count++] = s;
    });
    if (count < 3)
      throw std::logic_error("boost_segment_voronoi: a Voronoi vertex with fewer than three sites");
    return around;
  }

  const Diagram& vd_;
  const PolygonSites& sites_;
  std::vector<std::uint32_t> id_;
  VoronoiTopology out_;
};

}  // namespace grassfire
