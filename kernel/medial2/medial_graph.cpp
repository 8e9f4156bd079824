// medial_graph.cpp -- see medial_graph.h.
#include "medial2/medial_graph.h"

#include <boost/graph/connected_components.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace grassfire {

const char* to_string(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::Segment: return "segment";
    case EdgeKind::ParabolicArc: return "parabolic-arc";
  }
  return "unknown";
}

namespace {
template <class Enclose>
LongInterval long_from_mpfr(Enclose enclose) {
  mpfr_t lo, hi;
  mpfr_init2(lo, 80);
  mpfr_init2(hi, 80);
  enclose(lo, hi);
  const LongInterval r{mpfr_get_ld(lo, MPFR_RNDD), mpfr_get_ld(hi, MPFR_RNDU)};
  mpfr_clear(lo);
  mpfr_clear(hi);
  return r;
}
}  // namespace

LongInterval MedialGeometry::enclose_radius_long(std::uint32_t node) const {
  return long_from_mpfr([&](mpfr_ptr lo, mpfr_ptr hi) { enclose_radius(node, lo, hi); });
}

LongInterval MedialGeometry::enclose_length_long(std::uint32_t edge) const {
  return long_from_mpfr([&](mpfr_ptr lo, mpfr_ptr hi) { enclose_length(edge, lo, hi); });
}

Point2 MedialGeometry::point_along(const MedialGraph& g, std::uint32_t edge, std::uint32_t from,
                                   double s) const {
  const MedialEdge& e = g.edge(edge);
  const Point2 a = g.node(from).position;
  const Point2 b = g.node(g.other_end(edge, from)).position;
  const double w = e.length.mid();
  const double t = w > 0 ? std::fmin(1.0, std::fmax(0.0, s / w)) : 0.0;
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

std::vector<Point2> MedialGeometry::polyline(const MedialGraph& g, std::uint32_t edge) const {
  const MedialEdge& e = g.edge(edge);
  return {g.node(e.u).position, g.node(e.v).position};
}

MedialGraph::MedialGraph(std::vector<MedialNode> nodes, std::vector<MedialEdge> edges,
                         std::shared_ptr<const MedialGeometry> geometry)
    : nodes_(std::move(nodes)), edges_(std::move(edges)), geometry_(std::move(geometry)) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> arcs;
  std::vector<std::uint32_t> arc_edge;
  arcs.reserve(2 * edges_.size());
  arc_edge.reserve(2 * edges_.size());
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    if (edges_[e].u >= nodes_.size() || edges_[e].v >= nodes_.size())
      throw std::logic_error("medial graph: edge " + std::to_string(e) + " has an end outside the node range");
    arcs.emplace_back(edges_[e].u, edges_[e].v);
    arc_edge.push_back(e);
    arcs.emplace_back(edges_[e].v, edges_[e].u);
    arc_edge.push_back(e);
  }
  adjacency_ = Adjacency(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(), arc_edge.begin(),
                         nodes_.size());
}

MedialGraph MedialGraph::from_exact(std::vector<Point2> positions, std::vector<ExactSum> radii,
                                    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends,
                                    std::vector<ExactSum> lengths) {
  if (positions.size() != radii.size() || ends.size() != lengths.size())
    throw std::invalid_argument("medial graph: sizes of positions/radii or ends/lengths differ");
  std::vector<MedialNode> nodes(positions.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = {positions[i], radii[i].approx()};
  std::vector<MedialEdge> edges(ends.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    edges[e] = {ends[e].first, ends[e].second, EdgeKind::Segment, lengths[e].approx()};
  auto geometry = std::make_shared<ExplicitGeometry>(std::move(radii), std::move(lengths));
  return MedialGraph(std::move(nodes), std::move(edges), std::move(geometry));
}

// Breadth-first search from each node not yet reached, in node order: the numbering of
// boost::connected_components (a component is numbered when its smallest node is met),
// without the depth-first search's stack of iterator tuples and colour map.
std::vector<std::uint32_t> MedialGraph::component_of_nodes() const {
  constexpr std::uint32_t kUnreached = 0xffffffffu;
  std::vector<std::uint32_t> component(nodes_.size(), kUnreached);
  std::vector<std::uint32_t> queue;
  queue.reserve(nodes_.size());
  std::uint32_t count = 0;
  for (std::uint32_t s = 0; s < nodes_.size(); ++s) {
    if (component[s] != kUnreached) continue;
    component[s] = count;
    queue.clear();
    queue.push_back(s);
    // Every node enters the queue once: the loop is bounded by the node count.
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto range = boost::out_edges(queue[head], adjacency_);
      for (auto it = range.first; it != range.second; ++it) {
        const std::uint32_t w = static_cast<std::uint32_t>(boost::target(*it, adjacency_));
        if (component[w] != kUnreached) continue;
        component[w] = count;
        queue.push_back(w);
      }
    }
    ++count;
  }
  return component;
}

std::uint32_t MedialGraph::component_count() const {
  if (nodes_.empty()) return 0;
  std::vector<std::uint32_t> component(nodes_.size(), 0);
  return static_cast<std::uint32_t>(boost::connected_components(adjacency_, component.data()));
}

void MedialGraph::validate() const {
  auto fail = [](const std::string& what) { throw std::logic_error("medial graph invalid: " + what); };
  if (!geometry_) fail("no geometry behind the graph");
  if (boost::num_vertices(adjacency_) != nodes_.size()) fail("adjacency has a different node count");
  if (boost::num_edges(adjacency_) != 2 * edges_.size()) fail("adjacency has a different arc count");
  for (std::uint32_t i = 0; i < nodes_.size(); ++i) {
    const MedialNode& n = nodes_[i];
    if (!(n.radius.lo >= 0.0) || !(n.radius.lo <= n.radius.hi) || !std::isfinite(n.radius.hi))
      fail("node " + std::to_string(i) + " has an invalid radius enclosure");
    if (!std::isfinite(n.position.x) || !std::isfinite(n.position.y))
      fail("node " + std::to_string(i) + " has a non-finite position");
  }
  std::vector<std::uint32_t> seen(edges_.size(), 0);
  for (std::uint32_t v = 0; v < nodes_.size(); ++v) {
    for_each_incident(v, [&](std::uint32_t e) {
      if (e >= edges_.size() || (edges_[e].u != v && edges_[e].v != v))
        fail("adjacency of node " + std::to_string(v) + " lists edge " + std::to_string(e) + " not incident to it");
      ++seen[e];
    });
  }
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    const MedialEdge& ed = edges_[e];
    if (ed.u == ed.v) fail("edge " + std::to_string(e) + " is a loop");
    if (!(ed.length.lo >= 0.0) || !(ed.length.lo <= ed.length.hi) || !std::isfinite(ed.length.hi))
      fail("edge " + std::to_string(e) + " has an invalid length enclosure");
    if (seen[e] != 2) fail("edge " + std::to_string(e) + " is not listed at both ends");
  }
}

TwoCore two_core(const MedialGraph& g) {
  TwoCore core;
  const std::uint32_t n = g.node_count();
  core.node_in_core.assign(n, true);
  core.edge_in_core.assign(g.edge_count(), true);
  std::vector<std::uint32_t> degree(n);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t v = 0; v < n; ++v) {
    degree[v] = g.degree(v);
    if (degree[v] <= 1) stack.push_back(v);
  }
  while (!stack.empty()) {
    const std::uint32_t v = stack.back();
    stack.pop_back();
    if (!core.node_in_core[v]) continue;
    core.node_in_core[v] = false;
    g.for_each_incident(v, [&](std::uint32_t e) {
      if (!core.edge_in_core[e]) return;
      core.edge_in_core[e] = false;
      const std::uint32_t w = g.other_end(e, v);
      if (--degree[w] <= 1 && core.node_in_core[w]) stack.push_back(w);
    });
  }
  for (std::uint32_t v = 0; v < n; ++v) core.core_nodes += core.node_in_core[v] ? 1 : 0;
  return core;
}

}  // namespace grassfire
