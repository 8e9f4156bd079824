// boost_voronoi_events.h -- the interior segment Voronoi topology (segment_voronoi.h) read
// from the events of Boost.Polygon's voronoi builder directly, without building its
// voronoi_diagram (2.1.1; docs/exactness.md). Included by segment_voronoi_boost*.cpp only.
//
// Computes: the same VoronoiTopology as BoostExtractor (boost_voronoi_extract.h) on the
// diagram the builder would have written with NoMergeTraits, identical vertex, edge and
// site order. The builder is the diagram's only writer and calls three hooks; this class
// keeps of them only what the interior search reads: per half-edge its cell's site and its
// start vertex, per edge pair whether it is primary (Boost's rule), per vertex its three
// outgoing half-edges. Why the order is the same: with no vertex merged, the diagram keeps
// every half-edge and vertex in creation order (the indices here); a circle event on the
// arcs A, B, C (bisectors e12 of A|B, e23 of B|C, the new pair n1, n2 of A|C) sets the
// only links the search follows at its vertex V: rot_next turns n2 -> e23 -> e12 -> n2,
// and V's incident edge is n2 (the last half-edge starting at V). The apex of a convex
// vertex p, which BoostExtractor finds in p's cell as the end of a secondary half-edge
// whose next is secondary, is the vertex whose two bisectors with p are both secondary;
// a cell with two such vertices (never seen on a valid polygon) is not decided here: run()
// returns nothing and the caller reads the full diagram instead.
// Contract: the builder ran on the polygon's segments in site order (segment i from vertex
// i to next[i]). Complexity: O(n) time and memory for n polygon vertices (16 bytes per
// half-edge, against the diagram's 48 and its vertices and cells).
#pragma once

#include <boost/polygon/detail/voronoi_structures.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "medial2/polygon/boost_voronoi_extract.h"
#include "medial2/polygon/segment_voronoi.h"

namespace grassfire {

class BoostVoronoiEvents {
 public:
  explicit BoostVoronoiEvents(const PolygonSites& sites) : sites_(sites), apex_(sites.vertex_count(), kNone) {}

  // The builder's output interface (voronoi_builder::construct).
  void _reserve(std::size_t site_events) {
    cell_site_.reserve(site_events);
    half_.reserve(6 * site_events);
    vertex_.reserve(2 * site_events);
  }
  template <class Site>
  void _process_single_site(const Site& s) {
    cell_site_.push_back(site_id(s));
  }
  template <class Site>
  std::pair<void*, void*> _insert_new_edge(const Site& s1, const Site& s2) {
    if (cell_site_.empty()) cell_site_.push_back(site_id(s1));
    cell_site_.push_back(site_id(s2));
    return add_pair(s1.sorted_index(), s2.sorted_index(), is_primary(s1, s2));
  }
  template <class Site, class Circle>
  std::pair<void*, void*> _insert_new_edge(const Site& s1, const Site& s3, const Circle&, void* d12, void* d23) {
    const std::uint32_t e12 = half_of(d12), e23 = half_of(d23), v = static_cast<std::uint32_t>(vertex_.size());
    half_[e12].vertex0 = v;
    half_[e23].vertex0 = v;
    const bool p13 = is_primary(s1, s3);
    const std::pair<void*, void*> out = add_pair(s1.sorted_index(), s3.sorted_index(), p13);
    const std::uint32_t n2 = half_of(out.second);
    half_[n2].vertex0 = v;
    vertex_.push_back({n2, e23, e12});
    const bool p12 = primary_[e12 / 2], p23 = primary_[e23 / 2];
    // A's bisectors at V are A|C and A|B, B's are A|B and B|C, C's are B|C and A|C.
    if (!p13 && !p12) note_apex(half_[e12].site, v);
    if (!p12 && !p23) note_apex(half_[e23].site, v);
    if (!p23 && !p13) note_apex(half_[n2].site, v);
    return out;
  }
  void _build() {}

  // BoostExtractor::run on the diagram these events describe; nothing when a convex
  // vertex's apex is ambiguous (the caller reads the full diagram).
  std::optional<VoronoiTopology> run() {
    for (std::uint32_t p : cell_site_)
      if (sites_.is_point(p) && apex_[p] == kAmbiguous && is_convex_vertex(sites_, p)) return std::nullopt;
    id_.assign(vertex_.size(), kNone);
    out_.vertices.reserve(vertex_.size());
    out_.edges.reserve(half_.size() / 4);
    std::vector<std::uint32_t> stack;
    for (std::uint32_t p : cell_site_) {
      if (!sites_.is_point(p) || !is_convex_vertex(sites_, p)) continue;
      if (apex_[p] == kNone)
        throw std::logic_error("boost_segment_voronoi: no apex at convex vertex " + std::to_string(p));
      const std::uint32_t a = add_vertex(apex_[p]);
      out_.vertices[a].apex = true;
      out_.vertices[a].sites = {p, sites_.vertex_count() + sites_.prev[p], sites_.vertex_count() + p};
      for (std::uint32_t h : vertex_[apex_[p]])
        if (primary_[h / 2]) stack.push_back(h);
    }
    std::vector<bool> done(half_.size(), false);
    while (!stack.empty()) {
      const std::uint32_t h = stack.back();
      stack.pop_back();
      if (done[h]) continue;
      done[h] = done[h ^ 1] = true;
      const std::uint32_t w = half_[h ^ 1].vertex0;  // the end vertex
      if (half_[h].vertex0 == kNone || w == kNone)
        throw std::logic_error("boost_segment_voronoi: an interior search reached an infinite edge");
      const std::uint32_t u = id_[half_[h].vertex0];
      const bool fresh = id_[w] == kNone;
      const std::uint32_t v = add_vertex(w);
      out_.edges.push_back({u, v, half_[h].site, half_[h ^ 1].site});
      if (!fresh || out_.vertices[v].apex) continue;
      out_.vertices[v].sites = ccw_sites(w);
      for (std::uint32_t f : vertex_[w])
        if (primary_[f / 2] && !done[f]) stack.push_back(f);
    }
    return std::move(out_);
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu, kAmbiguous = 0xfffffffeu;
  struct Half {
    std::uint32_t site = 0;       // the site of the half-edge's cell
    std::uint32_t vertex0 = kNone;  // its start vertex (kNone: at infinity)
  };

  template <class Site>
  std::uint32_t site_id(const Site& s) const {
    const auto i = static_cast<std::uint32_t>(s.initial_index());
    switch (s.source_category()) {
      case boost::polygon::SOURCE_CATEGORY_SEGMENT_START_POINT: return i;
      case boost::polygon::SOURCE_CATEGORY_SEGMENT_END_POINT: return sites_.next[i];
      default: return sites_.vertex_count() + i;
    }
  }

  // voronoi_diagram::is_primary_edge: false only between a segment and its own endpoint.
  template <class Site>
  static bool is_primary(const Site& a, const Site& b) {
    if (a.is_segment() && !b.is_segment()) return a.point0() != b.point0() && a.point1() != b.point0();
    if (!a.is_segment() && b.is_segment()) return b.point0() != a.point0() && b.point1() != a.point0();
    return true;
  }

  // Half-edges travel through the builder as opaque handles (index + 1: never null).
  static void* handle(std::uint32_t h) { return reinterpret_cast<void*>(static_cast<std::uintptr_t>(h) + 1); }
  static std::uint32_t half_of(void* p) { return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(p) - 1); }

  std::pair<void*, void*> add_pair(std::size_t cell1, std::size_t cell2, bool primary) {
    const auto h = static_cast<std::uint32_t>(half_.size());
    half_.push_back({cell_site_[cell1], kNone});
    half_.push_back({cell_site_[cell2], kNone});
    primary_.push_back(primary);
    return {handle(h), handle(h + 1)};
  }

  void note_apex(std::uint32_t site, std::uint32_t v) {
    if (!sites_.is_point(site)) return;
    apex_[site] = apex_[site] == kNone ? v : kAmbiguous;
  }

  std::uint32_t add_vertex(std::uint32_t w) {
    std::uint32_t& id = id_[w];
    if (id == kNone) {
      id = static_cast<std::uint32_t>(out_.vertices.size());
      out_.vertices.emplace_back();
    }
    return id;
  }

  // Sites around vertex w counter-clockwise from its incident edge, the first three
  // distinct (BoostExtractor::ccw_sites).
  std::array<std::uint32_t, 3> ccw_sites(std::uint32_t w) const {
    std::array<std::uint32_t, 3> around{};
    std::size_t count = 0;
    for (std::uint32_t h : vertex_[w]) {
      const std::uint32_t s = half_[h].site;
      bool seen = false;
      for (std::size_t i = 0; i < count; ++i) seen = seen || around[i] == s;
      if (!seen) around[count++] = s;
    }
    if (count < 3) throw std::logic_error("boost_segment_voronoi: a Voronoi vertex with fewer than three sites");
    return around;
  }

  const PolygonSites& sites_;
  std::vector<std::uint32_t> cell_site_;  // by the builder's sorted site index
  std::vector<Half> half_;                // pairs 2k, 2k + 1 are twins
  std::vector<bool> primary_;             // by pair
  std::vector<std::array<std::uint32_t, 3>> vertex_;  // outgoing half-edges, rot_next order
  std::vector<std::uint32_t> apex_;       // by polygon vertex: kNone, a vertex, or kAmbiguous
  std::vector<std::uint32_t> id_;
  VoronoiTopology out_;
};

// The topology from the builder's events, or from the full diagram when the events leave
// an apex ambiguous (BoostVoronoiEvents::run). `build(output)` constructs into `output`
// (a fresh builder each call); `full_diagram` forces the diagram path (the reference the
// tests compare the events path with).
template <class Diagram, class Build>
VoronoiTopology boost_interior_topology(const PolygonSites& sites, Build&& build, bool full_diagram) {
  if (!full_diagram) {
    BoostVoronoiEvents events(sites);
    build(&events);
    if (std::optional<VoronoiTopology> topo = events.run()) return std::move(*topo);
  }
  Diagram vd;
  build(&vd);
  return BoostExtractor<Diagram>(vd, sites).run();
}

}  // namespace grassfire
