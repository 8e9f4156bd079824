// segment_voronoi_boost.cpp -- the interior segment Voronoi topology by Boost.Polygon
// (see segment_voronoi.h). Boost.Polygon is used in this file only (its wide coordinate
// traits in boost_wide_traits.h).
#include <boost/polygon/point_data.hpp>
#include <boost/polygon/segment_data.hpp>
#include <boost/polygon/voronoi.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "medial2/boost_wide_traits.h"
#include "medial2/segment_voronoi.h"
#include "number/interval.h"

namespace grassfire {

namespace bp = boost::polygon;

namespace {

// Keeps every vertex the builder creates: Boost's default post-pass merges vertices
// whose coordinates agree within 128 ulps, an approximate decision we make exactly later.
struct NoMergeTraits : bp::voronoi_diagram_traits<double> {
  struct vertex_equality_predicate_type {
    bool operator()(const vertex_type&, const vertex_type&) const { return false; }
  };
};
using Diagram = bp::voronoi_diagram<double, NoMergeTraits>;
using BoostEdge = Diagram::edge_type;
using BoostVertex = Diagram::vertex_type;
using BoostCell = Diagram::cell_type;

std::int32_t to_int32(double x) {
  if (!(std::fabs(x) <= 2147483647.0) || x != std::floor(x))
    throw std::invalid_argument("boost_segment_voronoi: frame coordinate " + std::to_string(x) +
                                " is not an int32 integer");
  return static_cast<std::int32_t>(x);
}

// The frame's integers translated by the midpoint of their bounding box (exact in 128-bit
// integers; translation does not change the diagram), or nothing when one exceeds 62 bits.
std::optional<std::vector<std::int64_t>> wide_integers(const PolygonSites& sites) {
  constexpr double kLimit = 0x1p126;
  __int128 lo[2], hi[2];
  std::vector<__int128> v;
  v.reserve(2 * sites.vertex.size());
  for (const Point2& p : sites.vertex)
    for (double x : {p.x, p.y}) {
      if (!(std::fabs(x) < kLimit) || x != std::floor(x)) return std::nullopt;
      v.push_back(static_cast<__int128>(x));
    }
  for (int axis = 0; axis < 2; ++axis) lo[axis] = hi[axis] = v.empty() ? 0 : v[axis];
  for (std::size_t i = 0; i < v.size(); ++i) {
    lo[i % 2] = std::min(lo[i % 2], v[i]);
    hi[i % 2] = std::max(hi[i % 2], v[i]);
  }
  std::vector<std::int64_t> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const __int128 t = v[i] - (lo[i % 2] + hi[i % 2]) / 2;
    if (t > boost_wide::kMaxMagnitude || t < -boost_wide::kMaxMagnitude) return std::nullopt;
    out[i] = static_cast<std::int64_t>(t);
  }
  return out;
}

std::uint32_t site_of(const BoostCell& cell, const PolygonSites& sites) {
  const std::uint32_t i = static_cast<std::uint32_t>(cell.source_index());
  switch (cell.source_category()) {
    case bp::SOURCE_CATEGORY_SEGMENT_START_POINT: return i;
    case bp::SOURCE_CATEGORY_SEGMENT_END_POINT: return sites.next[i];
    default: return sites.vertex_count() + i;
  }
}

class Extractor {
 public:
  Extractor(const Diagram& vd, const PolygonSites& sites) : vd_(vd), sites_(sites) {}

  VoronoiTopology run() {
    id_.assign(vd_.num_vertices(), kNone);
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
  std::array<std::uint32_t, 3> ccw_sites(const BoostVertex* v) const {
    std::vector<std::uint32_t> around;
    for_each_out_edge(v, [&](const BoostEdge* e) {
      const std::uint32_t s = site_of(*e->cell(), sites_);
      bool seen = false;
      for (std::uint32_t t : around) seen = seen || t == s;
      if (!seen) around.push_back(s);
    });
    if (around.size() < 3)
      throw std::logic_error("boost_segment_voronoi: a Voronoi vertex with fewer than three sites");
    return {around[0], around[1], around[2]};
  }

  const Diagram& vd_;
  const PolygonSites& sites_;
  std::vector<std::uint32_t> id_;
  VoronoiTopology out_;
};

}  // namespace

VoronoiTopology boost_segment_voronoi(const PolygonSites& sites) {
  std::vector<bp::segment_data<std::int32_t>> segments;
  segments.reserve(sites.vertex_count());
  for (std::uint32_t i = 0; i < sites.vertex_count(); ++i) {
    const Point2 a = sites.vertex[i], b = sites.vertex[sites.next[i]];
    segments.emplace_back(bp::point_data<std::int32_t>(to_int32(a.x), to_int32(a.y)),
                          bp::point_data<std::int32_t>(to_int32(b.x), to_int32(b.y)));
  }
  Diagram vd;
  bp::construct_voronoi(segments.begin(), segments.end(), &vd);
  return Extractor(vd, sites).run();
}

bool fits_wide_boost(const PolygonSites& sites) { return wide_integers(sites).has_value(); }

VoronoiTopology boost_segment_voronoi_wide(const PolygonSites& sites) {
  const std::optional<std::vector<std::int64_t>> v = wide_integers(sites);
  if (!v) throw std::invalid_argument("boost_segment_voronoi_wide: a frame coordinate is not an integer within 2^62 of the frame's centre");
  bp::voronoi_builder<std::int64_t, boost_wide::CtypeTraits> builder;
  for (std::uint32_t i = 0; i < sites.vertex_count(); ++i) {
    const std::uint32_t j = sites.next[i];
    builder.insert_segment((*v)[2 * i], (*v)[2 * i + 1], (*v)[2 * j], (*v)[2 * j + 1]);
  }
  Diagram vd;
  builder.construct(&vd);
  return Extractor(vd, sites).run();
}

}  // namespace grassfire
